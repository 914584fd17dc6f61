// Reading images as textures through OpenImageIO.
#pragma once

#include "texture/texture.h"

#include <string>

namespace pt {

// Reads an image as linear RGB. 8- and 16-bit files are taken as sRGB-encoded (as map_Kd
// textures are); float and half files (EXR, HDR) as linear. Grey images are replicated to RGB,
// alpha is dropped. Returns false and sets `error` if the file cannot be read.
// `budgetBytes` is what the texels may take: the size in the file's header is checked against it
// before any pixel is decoded (a 260 KB PNG can declare 16384 x 16384), and `tooLarge` is set
// when that is the reason for failing.
bool readTexture(const std::string& path, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge);

// Bytes that all textures of a scene may take: a quarter of this machine's memory.
double textureMemoryBudget();

} // namespace pt
