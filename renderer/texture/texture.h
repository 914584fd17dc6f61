// Textures as the scene holds them, and how a material uses one. Lookups go through
// texture/texture_cache.h (filtered over a mip pyramid by texture/texture_sampler.h).
#pragma once

#include "core/math.h"
#include "texture/texel_format.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// One level of a texture's mip pyramid: its size, and where its texels start in Texture::data.
struct MipLevel {
    int width = 0, height = 0;
    size_t offset = 0;
};

// A texture as the scene holds it: texels at the file's own depth (texture/texel_format.h), row 0
// at the top of the image (v = 1 in texture space), then its mip levels, each half the size of the
// one before (TextureCache::add builds them). A colour texture has 3 channels (grey replicated,
// alpha dropped) and is sRGB-encoded where the file is 8-bit; a data texture keeps the file's
// values and its first 1 to 4 channels (an alpha channel last).
struct Texture {
    std::string path;
    bool colour = true;
    int width = 0, height = 0, channels = 0;
    TexelFormat format = TexelFormat::Float;
    std::vector<uint8_t> data;     // every level's texels, interleaved channels
    std::vector<MipLevel> levels;  // level 0 is the image as read
    float peak = 0.0f;  // largest |texel|, set by TextureCache::add: what a map can multiply its factor by
    double mean = 1.0;  // mean of all texels and channels (emission's light-tree power), set by add
    uint64_t sourceHash = 0; // of the file's bytes it was decoded from (readTexture)

    // Float texels given row by row (tests, constant maps).
    static Texture fromFloats(int width, int height, int channels, const std::vector<float>& values, bool colour = true);

    bool hasAlpha() const { return channels == 2 || channels == 4; }
    double bytes() const { return double(data.size()); }
    int bytesPerTexel() const { return channels * bytesPerChannel(format); }
    const uint8_t* texelAt(const MipLevel& level, int x, int y) const {
        return data.data() + level.offset + (size_t(y) * size_t(level.width) + size_t(x)) * size_t(bytesPerTexel());
    }
    // Channel c of texel (x, y) in `level`, as linear float.
    float texel(int x, int y, int c, int level = 0) const {
        return loadTexel(format, texelAt(levels[size_t(level)], x, y) + c * bytesPerChannel(format));
    }
};

// How a lookup outside [0, 1] finds its texels, along one axis: glTF's sampler wrapS and wrapT
// (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT); the MTL's -clamp on sets both axes to Clamp.
enum class TextureWrap : uint8_t { Repeat, Clamp, Mirror };

// Which value a scalar map takes from its texture (-imfchan).
enum class TextureChannel : uint8_t { Rgb, R, G, B, Alpha, Luminance };

// How a material uses a texture: the MTL map options that change the lookup.
struct TextureMap {
    int texture = -1;               // index into the scene's TextureCache; -1: no map
    // The lookup is at linear * uv + offset, in pt's uv (v up): the MTL's -s (a diagonal) and -o,
    // or glTF's KHR_texture_transform (setGltfTransform).
    glm::mat2 linear{1.0f};
    Vec2 offset{0.0f};
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
    TextureChannel channel = TextureChannel::Rgb; // colour maps: Rgb; scalar maps: -imfchan
    float bumpScale = 1.0f;         // -bm: height scale of bump maps, xy scale of normal maps

    bool used() const { return texture >= 0; }
};

// A diagonal `linear`: the MTL's -s.
inline glm::mat2 scaleMatrix(Vec2 s) { return glm::mat2(s.x, 0.0f, 0.0f, s.y); }

// KHR_texture_transform in pt's uv. The extension maps glTF's uv (v down the image) to
// offset + R (scale * uv), where R turns by `rotation` as its example has it: offset [0, 1],
// rotation pi/2 and scale 0.5 read the image's lower-left quadrant, turned clockwise, so
// R = [[c, s], [-s, c]]. pt's v is 1 - glTF's on both sides of the map, so pt's transform is
// that one conjugated by the flip (u, v) -> (u, 1 - v).
inline void setGltfTransform(TextureMap& map, Vec2 offset, float rotation, Vec2 scale) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    const float m00 = c * scale.x, m01 = s * scale.y, m10 = -s * scale.x, m11 = c * scale.y; // R * scale
    map.linear = glm::mat2(m00, -m10, -m01, m11); // columns: the flip's D M D
    map.offset = Vec2(offset.x + m01, 1.0f - offset.y - m11);
}

// A normal map's x and y lie along the texture's s and t, which `linear` turns (and may mirror)
// against the surface's u and v: the tangent-frame coefficients of (x, y) are the columns of
// linear's inverse, each made unit. The identity for a map without a transform or with -s > 0.
inline Vec2 normalMapToUv(const TextureMap& map, Vec2 xy) {
    const glm::mat2 inverse = glm::inverse(map.linear);
    const float l0 = glm::length(inverse[0]), l1 = glm::length(inverse[1]);
    if (!(l0 > 0.0f && l1 > 0.0f && std::isfinite(l0) && std::isfinite(l1))) return xy;
    return xy.x * (inverse[0] / l0) + xy.y * (inverse[1] / l1);
}

// Where a lookup filters: two axes in uv (before the map's transform) of the ellipse that a ray cone
// covers at the hit. Zero axes give a bilinear lookup in the finest level.
struct Footprint {
    Vec2 dx{0.0f}, dy{0.0f};
};

} // namespace pt
