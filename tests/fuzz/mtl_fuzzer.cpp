// libFuzzer target for the lab's extended MTL (materials, lights, cameras, texture maps). Any
// input must either parse or throw a LoadError; texture paths resolve against scenes/, where the
// textures of the repository's scenes lie, so map lines load real images.
//
// The inputs share one texture cache, as the materials of one scene do: a map line's path and
// options are this target's to fuzz, but decoding the same few PNGs and building their mip
// pyramids again for every input made it 16 to 27 times slower than the other targets (224
// inputs a second against 3,678 for the OBJ loader), and the decoders have fuzzers of their own
// (the part target's images, the glTF target's embedded ones). The cache is emptied when it
// holds many textures, so that a flood of spellings of one path ("./././checker.png") cannot
// grow it without bound.
#include "obj/mtl_loader.h"
#include "texture/texture_cache.h"

#include <cstdint>
#include <memory>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    static std::shared_ptr<pt::TextureCache> textures = std::make_shared<pt::TextureCache>();
    if (textures->size() > 64) textures = std::make_shared<pt::TextureCache>();
    pt::Warnings warnings;
    pt::Scene scene;
    scene.textures = textures;
    std::unordered_map<std::string, uint32_t> materialIndex;
    try {
        pt::parseMtl(text, PT_SOURCE_DIR "/scenes/fuzz.mtl", scene, materialIndex, warnings);
    } catch (const pt::LoadError&) {
    }
    return 0;
}
