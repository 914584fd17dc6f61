#include "load/scene_loader.h"

#include "core/system.h"
#include "gltf/gltf_loader.h"
#include "obj/obj_loader.h"
#include "scene/complete_scene.h"

#include <filesystem>

namespace pt {

Scene loadScene(const std::string& path, Warnings& warnings) {
    std::string ext = toLower(std::filesystem::path(path).extension().string());
    Scene scene;
    if (ext == ".obj") {
        scene = loadObj(path, warnings);
    } else if (ext == ".gltf" || ext == ".glb") {
        scene = loadGltf(path, warnings);
    } else {
        throw LoadError(path + ": unsupported scene format \"" + ext + "\"; expected .obj, .gltf or .glb");
    }
    completeScene(scene, warnings);
    return scene;
}

} // namespace pt
