// A texture: linear RGB texels and how to look them up. The texture module (texture/) owns
// reading images as textures and every lookup, so that materials only ask for a value at a uv.
#pragma once

#include "core/math.h"

#include <string>
#include <vector>

namespace pt {

// Linear RGB texels, row 0 at the top of the image (v = 1 in texture space).
struct Texture {
    std::string path;
    int width = 0, height = 0;
    std::vector<Spectrum> texels;
};

// Bilinear lookup with repeat wrapping. v = 0 is the bottom of the image, as in OBJ.

inline Spectrum lookupTexture(const Texture& tex, Vec2 uv) {
    float x = uv.x * float(tex.width) - 0.5f;
    float y = (1.0f - uv.y) * float(tex.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return tex.texels[0];
    float fx = std::floor(x), fy = std::floor(y);
    float tx = x - fx, ty = y - fy;
    auto wrap = [](float i, int n) {
        long long k = (long long)std::fmod(i, float(n));
        return int(k < 0 ? k + n : k);
    };
    int x0 = wrap(fx, tex.width), x1 = wrap(fx + 1.0f, tex.width);
    int y0 = wrap(fy, tex.height), y1 = wrap(fy + 1.0f, tex.height);
    auto at = [&](int xi, int yi) { return tex.texels[size_t(yi) * tex.width + xi]; };
    return (1.0f - ty) * ((1.0f - tx) * at(x0, y0) + tx * at(x1, y0)) +
           ty * ((1.0f - tx) * at(x0, y1) + tx * at(x1, y1));
}

} // namespace pt
