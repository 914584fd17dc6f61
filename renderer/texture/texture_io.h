// Reading images as textures through OpenImageIO.
#pragma once

#include "texture/texture.h"

#include <string>
#include <vector>

namespace pt {

// Reads an image as a texture (see Texture). A colour texture's 8- and 16-bit files are taken as
// sRGB-encoded, float and half files (EXR, HDR, float TIFF) as linear; a data texture's values
// are linear whatever the file's type (an 8-bit roughness of 128 is 128 / 255). Returns false and
// sets `error` if the file cannot be read.
// `budgetBytes` is what the texels may take: the size in the file's header is checked against it
// before any pixel is decoded (a 260 KB PNG can declare 16384 x 16384), and `tooLarge` is set
// when that is the reason for failing.
bool readTexture(const std::string& path, bool colour, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge);

// The same for an image held in memory (glTF's embedded images, and its files once read): `name`
// stands for the path in messages and in the texture, `format` is the file extension that picks
// the decoder (".png", ".jpg").
bool readTextureFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, const std::string& format,
                           bool colour, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge);

// Bytes that all textures of a scene may take: a quarter of this machine's memory.
double textureMemoryBudget();

} // namespace pt
