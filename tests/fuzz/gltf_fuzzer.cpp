// libFuzzer target for the glTF loader: tinygltf's parsing and every check pt adds on top of it
// (accessors, buffer views, indices, nodes, materials, cameras, lights). Any input must either
// load or throw a LoadError. Inputs starting with "glTF" are read as .glb, the rest as .gltf;
// relative URIs resolve against scenes/gltf/, so the seeds' external .bin and image load.
#include "gltf/gltf_loader.h"

#include <cstdint>
#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<unsigned char> bytes(data, data + size);
    bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    pt::Warnings warnings;
    try {
        pt::Scene scene = pt::loadGltfFromMemory(PT_SOURCE_DIR "/scenes/gltf/fuzz.gltf", bytes, binary, warnings);
    } catch (const pt::LoadError&) {
    }
    return 0;
}
