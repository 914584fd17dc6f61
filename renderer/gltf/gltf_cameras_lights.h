// A glTF node's camera and KHR_lights_punctual light, placed by the node's world transform.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <string>

namespace pt::gltf {

// Add camera or light `index` at `world`; `where` names the node for messages. Throw LoadError.
void addCamera(const tinygltf::Model& model, const std::string& path, int index, const glm::dmat4& world,
               const std::string& where, Scene& scene);
void addLight(const tinygltf::Model& model, const std::string& path, int index, const glm::dmat4& world,
              const std::string& where, Scene& scene);

// A factor array's colour (its first three values), or `fallback` where it has none.
inline Spectrum colorOf(const std::vector<double>& v, Spectrum fallback) {
    return v.size() >= 3 ? Spectrum(float(v[0]), float(v[1]), float(v[2])) : fallback;
}

} // namespace pt::gltf
