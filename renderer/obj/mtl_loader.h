// The lab's extended MTL: materials (both the lab's long keywords and the standard short ones),
// plus `newlight` and `newcamera` blocks. Keywords are case-insensitive.
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <string>
#include <unordered_map>

namespace pt {

// Parses `path` and appends its materials, lights and cameras to `scene`. Material names are
// added to `materialIndex`. Textures named by map_Kd are loaded relative to the MTL's folder;
// a texture that cannot be read is a warning and the material keeps its plain Kd.
void loadMtl(const std::string& path, Scene& scene,
             std::unordered_map<std::string, uint32_t>& materialIndex, Warnings& warnings);

// Same, from text already in memory (tests, fuzzing); `path` names it in messages and is the
// base for texture paths.
void parseMtl(std::string_view text, const std::string& path, Scene& scene,
              std::unordered_map<std::string, uint32_t>& materialIndex, Warnings& warnings);

} // namespace pt
