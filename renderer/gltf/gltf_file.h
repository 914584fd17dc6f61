// A glTF file read into tinygltf's model under pt's file policy: the document checked first
// (gltf_document.h), buffers only from regular files beside the .gltf of the size they declare
// and within half the memory, images kept as bytes for the texture reader, nothing written, and
// extensions pt does not implement refused (required) or named (used).
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace pt::gltf {

struct GltfFile {
    tinygltf::Model model;
    std::vector<std::vector<unsigned char>> images; // the bytes of data-URI images, by image index
    std::vector<SourceFile> buffers;                 // the buffer files read, with their hashes
};

// Throws LoadError naming `path`.
GltfFile readGltfFile(const std::string& path, const std::vector<unsigned char>& bytes, bool binary, Warnings& warnings);

// A URI's path as tinygltf decodes it (%XX escapes, and '+' as a space), so that the loader finds
// an image where tinygltf finds a buffer of the same name.
std::string decodeUri(const std::string& uri);

} // namespace pt::gltf
