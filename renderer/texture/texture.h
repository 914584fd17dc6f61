// Textures as the scene holds them, and how a material uses one. Lookups go through
// texture/texture_cache.h (OpenImageIO's TextureSystem: mip-mapped, filtered, tile-cached).
#pragma once

#include "core/math.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// Linear float texels as read from a file, row 0 at the top of the image (v = 1 in texture space).
// A colour texture is decoded from sRGB where the file is 8- or 16-bit and always has 3 channels
// (grey replicated, alpha dropped); a data texture keeps the file's values and its first 1 to 4
// channels (an alpha channel last).
struct Texture {
    std::string path;
    bool colour = true;
    int width = 0, height = 0, channels = 0;
    std::vector<float> texels;
    float peak = 0.0f; // largest |texel|, set by TextureCache::add: what a map can multiply its factor by
    uint64_t sourceHash = 0; // of the file's bytes it was decoded from (readTexture)

    bool hasAlpha() const { return channels == 2 || channels == 4; }
    double bytes() const { return double(texels.size()) * sizeof(float); }
};

// How a lookup outside [0, 1] finds its texels, along one axis: glTF's sampler wrapS and wrapT
// (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT); the MTL's -clamp on sets both axes to Clamp.
enum class TextureWrap : uint8_t { Repeat, Clamp, Mirror };

// Which value a scalar map takes from its texture (-imfchan).
enum class TextureChannel : uint8_t { Rgb, R, G, B, Alpha, Luminance };

// How a material uses a texture: the MTL map options that change the lookup.
struct TextureMap {
    int texture = -1;               // index into the scene's TextureCache; -1: no map
    Vec2 scale{1.0f}, offset{0.0f}; // -s and -o: the lookup is at uv * scale + offset
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
    TextureChannel channel = TextureChannel::Rgb; // colour maps: Rgb; scalar maps: -imfchan
    float bumpScale = 1.0f;         // -bm: height scale of bump maps, xy scale of normal maps

    bool used() const { return texture >= 0; }
};

// Where a lookup filters: two axes in uv (before -s and -o) of the ellipse that a ray cone
// covers at the hit. Zero axes give a bilinear lookup in the finest level.
struct Footprint {
    Vec2 dx{0.0f}, dy{0.0f};
};

} // namespace pt
