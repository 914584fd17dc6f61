// glTF 2.0 scenes (.gltf with its .bin and images, or data URIs; .glb) through tinygltf, into the
// same flat Scene the OBJ loader fills: the node hierarchy flattened into world-space triangles,
// materials as MaterialModel::MetalRough, cameras, KHR_lights_punctual lights, and images
// decoded by OpenImageIO. Every index and accessor is checked before use (gltf_accessors.h).
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace pt {

// Throws LoadError naming the file and the object (accessor, mesh, material, node) at fault.
Scene loadGltf(const std::string& path, Warnings& warnings);
// The same from the file's bytes (`binary`: a .glb container); external .bin and image files are
// looked up beside `path`. The fuzzer's entry point.
Scene loadGltfFromMemory(const std::string& path, const std::vector<unsigned char>& bytes, bool binary,
                         Warnings& warnings);

// Extensions the loader implements; a file that requires any other is refused.
bool gltfExtensionSupported(const std::string& name);

} // namespace pt
