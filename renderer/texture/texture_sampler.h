// Filtered texture lookups over a Texture's mip pyramid: bilinear within a level, linear between
// the two levels whose texels are nearest the footprint's size, and, for a stretched footprint,
// several such taps along its major axis. Each lookup is a fixed sum over fixed texels: the same
// answer on any thread.
#pragma once

#include "texture/texture.h"

#include <algorithm>
#include <cmath>

namespace pt {

// A texture coordinate (in images, 0 to 1 across) taken to the period where `wrap` reads it:
// [0, 1] repeating, [0, 2] mirrored (the second image reversed), [-1, 2] clamped (beyond, every
// coordinate reads the edge). Small enough afterwards to scale to texels in int.
inline float reduceCoordinate(float s, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Repeat: return s - std::floor(s);
    case TextureWrap::Mirror: return s - 2.0f * std::floor(0.5f * s);
    default: return std::clamp(s, -1.0f, 2.0f);
    }
}

// The texel that index i reads along an axis of n texels, for i one texel either side of the
// period reduceCoordinate leaves.
inline int wrapIndex(int i, int n, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Repeat: return i < 0 ? i + n : i >= n ? i - n : i;
    case TextureWrap::Mirror:
        if (i < 0) i = -1 - i;
        if (i >= 2 * n) i -= 2 * n;
        return i < n ? i : 2 * n - 1 - i;
    default: return std::clamp(i, 0, n - 1);
    }
}

// Adds `weight` times the bilinear value of channels [first, first + Count) of `level` at image
// coordinates (s, t), t running down from the top row, into out; with ds and dt, also the
// derivatives of that value along s and t. The texel format is a template parameter: the
// format's branch is taken once per lookup, not per channel.
template <TexelFormat Format, int Count>
inline void addBilinear(const Texture& tex, int level, float s, float t, TextureWrap wrapS, TextureWrap wrapT, int first,
                        float weight, float* out, float* ds, float* dt) {
    const MipLevel& l = tex.levels[size_t(level)];
    const float x = s * float(l.width) - 0.5f, y = t * float(l.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y), ax = x - fx, ay = y - fy;
    const int x0 = wrapIndex(int(fx), l.width, wrapS), x1 = wrapIndex(int(fx) + 1, l.width, wrapS);
    const int y0 = wrapIndex(int(fy), l.height, wrapT), y1 = wrapIndex(int(fy) + 1, l.height, wrapT);
    const uint8_t *p00 = tex.texelAt(l, x0, y0), *p10 = tex.texelAt(l, x1, y0);
    const uint8_t *p01 = tex.texelAt(l, x0, y1), *p11 = tex.texelAt(l, x1, y1);
    constexpr int bpc = bytesPerChannel(Format);
    for (int c = 0; c < Count; ++c) {
        const int o = (first + c) * bpc;
        const float v00 = loadTexel(Format, p00 + o), v10 = loadTexel(Format, p10 + o);
        const float v01 = loadTexel(Format, p01 + o), v11 = loadTexel(Format, p11 + o);
        const float top = v00 + ax * (v10 - v00), bottom = v01 + ax * (v11 - v01);
        out[c] += weight * (top + ay * (bottom - top));
        if (ds) {
            ds[c] += weight * float(l.width) * ((v10 - v00) + ay * ((v11 - v01) - (v10 - v00)));
            dt[c] += weight * float(l.height) * (bottom - top);
        }
    }
}

// sampleTexture, for one texel format.
template <TexelFormat Format, int Count>
inline void sampleTextureAs(const Texture& tex, TextureWrap wrapS, TextureWrap wrapT, Vec2 st, Vec2 dx, Vec2 dy, int first,
                            int maxTaps, float* out, float* ds, float* dt) {
    for (int c = 0; c < Count; ++c) {
        out[c] = 0.0f;
        if (ds) ds[c] = dt[c] = 0.0f;
    }
    // The footprint's axes in texels of level 0.
    const Vec2 size(float(tex.width), float(tex.height));
    const float lx = glm::length(dx * size), ly = glm::length(dy * size);
    const Vec2 major = lx >= ly ? dx : dy;
    const float majorTexels = std::max(lx, ly), minorTexels = std::min(lx, ly);
    int taps = 1;
    if (maxTaps > 1 && majorTexels > 1.0f)
        taps = minorTexels * float(maxTaps) > majorTexels ? int(std::ceil(majorTexels / minorTexels)) : maxTaps;
    const float width = majorTexels / float(taps); // what each tap's texels must cover
    const int top = int(tex.levels.size()) - 1;
    const float lod = width > 1.0f ? std::min(std::log2(width), float(top)) : 0.0f;
    const int level = std::min(int(lod), top);
    const float between = lod - float(level);
    for (int k = 0; k < taps; ++k) {
        const Vec2 p = st + major * ((float(k) + 0.5f) / float(taps) - 0.5f);
        const float s = reduceCoordinate(p.x, wrapS), t = reduceCoordinate(1.0f - p.y, wrapT);
        addBilinear<Format, Count>(tex, level, s, t, wrapS, wrapT, first, (1.0f - between) / float(taps), out, ds, dt);
        if (between > 0.0f)
            addBilinear<Format, Count>(tex, level + 1, s, t, wrapS, wrapT, first, between / float(taps), out, ds, dt);
    }
    if (dt)
        for (int c = 0; c < Count; ++c) dt[c] = -dt[c]; // image t runs down, st's t up
}

// Channels [first, first + Count) of `tex` at st (pt's orientation: t = 0 at the bottom row),
// filtered over the footprint whose axes dx and dy are in st; ds and dt, where given, receive
// the derivatives of the filtered value along s and t. `maxTaps` bounds the taps along a
// stretched footprint (1: isotropic, the level chosen by the major axis).
// Count is 1 (a scalar map's channel) or 3 (colour, normal, luminance): fixed at compile time, as
// the format is, so that the bilinear loops unroll.
template <int Count>
inline void sampleTexture(const Texture& tex, TextureWrap wrapS, TextureWrap wrapT, Vec2 st, Vec2 dx, Vec2 dy, int first,
                          int maxTaps, float* out, float* ds = nullptr, float* dt = nullptr) {
    static_assert(Count == 1 || Count == 3);
    withTexelFormat(tex.format, [&](auto format) {
        sampleTextureAs<decltype(format)::value, Count>(tex, wrapS, wrapT, st, dx, dy, first, maxTaps, out, ds, dt);
    });
}

} // namespace pt
