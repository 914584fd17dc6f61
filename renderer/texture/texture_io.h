// Reading images as textures through OpenImageIO.
#pragma once

#include "texture/texture.h"

#include <string>

namespace pt {

// Reads an image as a texture (see Texture). A colour texture's 8- and 16-bit files are taken as
// sRGB-encoded, float and half files (EXR, HDR, float TIFF) as linear; a data texture's values
// are linear whatever the file's type (an 8-bit roughness of 128 is 128 / 255). Returns false and
// sets `error` if the file cannot be read.
// `budgetBytes` is what the texels may take: the size in the file's header is checked against it
// before any pixel is decoded (a 260 KB PNG can declare 16384 x 16384), and `tooLarge` is set
// when that is the reason for failing.
bool readTexture(const std::string& path, bool colour, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge);

// Bytes that all textures of a scene may take: a quarter of this machine's memory.
double textureMemoryBudget();

} // namespace pt
