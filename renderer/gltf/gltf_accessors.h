// Reading glTF accessors with every offset, stride, count and index checked first: tinygltf
// parses the JSON and loads the buffers but trusts what they say, so a file whose accessor points
// past its buffer, or whose indices pass the vertex count, must be refused here by name rather
// than read out of bounds. Integer components are converted as the specification says
// (normalized ones to [0, 1] or [-1, 1], others as they are, for KHR_mesh_quantization), and
// sparse accessors are applied over their base.
#pragma once

#include "io/load_error.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pt::gltf {

// The accessor's elements as floats, `components` per element (1 for SCALAR, 2 for VEC2, ...).
// `types` lists the component types the attribute may have (TINYGLTF_COMPONENT_TYPE_*); `what`
// names the attribute for messages ("scene.gltf: mesh 2 primitive 0 POSITION"). Throws LoadError.
std::vector<float> readFloats(const tinygltf::Model& model, int accessor, int components,
                              std::initializer_list<int> types, const std::string& what);

// An index accessor (SCALAR of unsigned byte, short or int), every value below `vertexCount`.
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int accessor, size_t vertexCount,
                                  const std::string& what);

// The bytes of buffer view `view` (an image's), checked against its buffer.
std::vector<unsigned char> bufferViewBytes(const tinygltf::Model& model, int view, const std::string& what);

// "scene.gltf: mesh 2 primitive 0 POSITION, accessor 3", for messages.
std::string accessorName(int accessor, const std::string& what);

} // namespace pt::gltf
