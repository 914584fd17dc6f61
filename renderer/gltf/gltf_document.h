// The glTF document as the file holds it, checked before tinygltf reads it. tinygltf trusts the
// file: a property of the wrong type (a string where an index belongs, a colour of two numbers)
// silently becomes its default, a JSON nested a million levels deep overflows its recursive
// converter, and an index is taken as it comes. So the loader first finds the JSON (in a .glb,
// after checking the container's lengths), bounds its nesting, and checks every property of the
// specification that pt reads, and every reference, against the schema of glTF 2.0 and of the
// extensions pt supports. Errors name the object: "material 2 \"Gold\": pbrMetallicRoughness.
// baseColorFactor must be an array of 4 numbers". Unknown properties and extras are left alone.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pt::gltf {

// Deepest nesting of arrays and objects accepted. The specification's own objects nest about ten
// deep; extras and unknown extensions may hold any JSON, but tinygltf converts them recursively.
inline constexpr int kMaxJsonDepth = 128;

// The JSON text of a .gltf file or of a .glb container's first chunk. Throws LoadError naming
// `path` when a .glb's header or chunk lengths do not fit the file.
std::string_view gltfJson(const std::vector<unsigned char>& bytes, bool binary, const std::string& path);

// Throws LoadError unless `json` nests at most kMaxJsonDepth deep; checked on the text, before any
// parser recurses.
void checkJsonDepth(std::string_view json, const std::string& path);

// What the loader needs of the document beyond what tinygltf keeps.
struct DocumentFacts {
    struct FileBuffer {
        size_t index;     // of the buffer
        std::string uri;  // as written (percent-encoded)
        uint64_t length;  // its byteLength
    };
    std::vector<FileBuffer> fileBuffers; // the buffers held in files of their own
};

// Parses `json` and checks it against the schema (types, array lengths, ranges the specification
// gives, required properties, references to other objects, buffer views inside their buffers).
// Throws LoadError.
// `binary`: the JSON of a .glb, whose first buffer may be its BIN chunk.
DocumentFacts checkGltfDocument(std::string_view json, bool binary, const std::string& path);

} // namespace pt::gltf
