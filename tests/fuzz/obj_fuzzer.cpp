// libFuzzer target for the OBJ loader and what the renderer builds from its scene. Any input
// must either load or throw a LoadError; a crash, a sanitizer report, an uncaught exception or a
// hang is a bug. mtllib and texture paths resolve against a folder that does not exist.
#include "light/light_set.h"
#include "render/shading_triangles.h"
#include "obj/obj_loader.h"
#include "load/scene_loader.h"
#include "scene/complete_scene.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    pt::Warnings warnings;
    try {
        pt::Scene scene = pt::parseObj(text, "/nonexistent/fuzz.obj", warnings);
        pt::completeScene(scene, warnings);
        std::vector<pt::ShadingTriangle> triangles = pt::buildShadingTriangles(scene);
        pt::LightSet lights(scene);
        (void)triangles;
        (void)lights;
    } catch (const pt::LoadError&) {
    }
    return 0;
}
