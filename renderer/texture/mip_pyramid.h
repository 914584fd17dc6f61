// A texture's mip levels, built at load: each level is the box-filtered average of the one before,
// half its size (rounded down, at least 1) along each axis. Odd sizes are filtered by the area each
// coarse texel covers, so every level keeps the image's mean. Averages are taken in linear float
// (an sRGB checker goes to the grey of its mean light) and stored in the texture's own format.
#pragma once

#include "texture/texture.h"

namespace pt {

// Appends levels 1 and up to a texture that holds level 0 only. Rows of a level are filtered in
// parallel on the TBB pool; each texel is a fixed sum, so the result is the same for any thread count.
// Sets the texture's peak (largest |value| of level 0) and mean (over all texels and channels) too.
void buildMipPyramid(Texture& texture);

} // namespace pt
