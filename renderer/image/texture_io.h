// Reading textures through OpenImageIO.
#pragma once

#include "scene/scene.h"

#include <string>

namespace pt {

// Reads an image as linear RGB. 8- and 16-bit files are taken as sRGB-encoded (as map_Kd
// textures are); float and half files (EXR, HDR) as linear. Grey images are replicated to RGB,
// alpha is dropped. Returns false and sets `error` if the file cannot be read.
bool readTexture(const std::string& path, Texture& texture, std::string& error);

float srgbToLinear(float c);
float linearToSrgb(float c);

} // namespace pt
