// Entry point for loading any supported scene file.
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <string>

namespace pt {

// Loads a scene by its extension: .obj (with its MTL files), .gltf or .glb. Afterwards the scene has at least one camera: if the
// file defines none, one framing the whole scene is added and a warning says so.
Scene loadScene(const std::string& path, Warnings& warnings);

} // namespace pt
