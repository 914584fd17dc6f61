// libFuzzer target for the lab's extended MTL (materials, lights, cameras). Any input must either
// parse or throw a LoadError; texture paths resolve against a folder that does not exist.
#include "scene/mtl_loader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    pt::Warnings warnings;
    pt::Scene scene;
    std::unordered_map<std::string, uint32_t> materialIndex;
    try {
        pt::parseMtl(text, "/nonexistent/fuzz.mtl", scene, materialIndex, warnings);
    } catch (const pt::LoadError&) {
    }
    return 0;
}
