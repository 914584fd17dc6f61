// Wavefront OBJ geometry with the lab's extended MTL (materials, lights, cameras).
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <string>

namespace pt {

// Loads an OBJ file and the MTL files it names. Throws LoadError ("file:line: what") on
// malformed input; recoverable problems (unknown keywords, a missing mtllib or texture) become
// warnings.
Scene loadObj(const std::string& path, Warnings& warnings);

// Same, from text already in memory; mtllib and texture paths resolve relative to `path`.
Scene parseObj(std::string_view text, const std::string& path, Warnings& warnings);

} // namespace pt
