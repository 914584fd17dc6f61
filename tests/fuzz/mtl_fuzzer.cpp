// libFuzzer target for the lab's extended MTL (materials, lights, cameras, texture maps). Any
// input must either parse or throw a LoadError; texture paths resolve against scenes/, where the
// textures of the repository's scenes lie, so map lines load real images.
#include "obj/mtl_loader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    pt::Warnings warnings;
    pt::Scene scene;
    std::unordered_map<std::string, uint32_t> materialIndex;
    try {
        pt::parseMtl(text, PT_SOURCE_DIR "/scenes/fuzz.mtl", scene, materialIndex, warnings);
    } catch (const pt::LoadError&) {
    }
    return 0;
}
