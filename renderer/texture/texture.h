// A texture: linear RGB texels and how to look them up. The texture module (texture/) owns
// reading images as textures and every lookup, so that materials only ask for a value at a uv.
#pragma once

#include "core/math.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pt {

// Linear RGB texels, row 0 at the top of the image (v = 1 in texture space).
struct Texture {
    std::string path;
    int width = 0, height = 0;
    std::vector<Spectrum> texels;
};

// How a material uses a texture: the MTL map options that change the lookup.
struct TextureMap {
    int texture = -1;               // index into Scene::textures; -1: no map
    Vec2 scale{1.0f}, offset{0.0f}; // -s and -o: the lookup is at uv * scale + offset
    bool clamp = false;             // -clamp on: uv outside [0, 1] takes the edge's texels

    bool used() const { return texture >= 0; }
};

// Bilinear lookup, repeating the image or (clampToEdge) extending its border texels. v = 0 is
// the bottom of the image, as in OBJ.
inline Spectrum lookupTexture(const Texture& tex, Vec2 uv, bool clampToEdge = false) {
    float x = uv.x * float(tex.width) - 0.5f;
    float y = (1.0f - uv.y) * float(tex.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return tex.texels[0];
    float fx = std::floor(x), fy = std::floor(y);
    float tx = x - fx, ty = y - fy;
    auto wrap = [clampToEdge](float i, int n) {
        if (clampToEdge) return int(std::clamp(i, 0.0f, float(n - 1)));
        long long k = (long long)std::fmod(i, float(n));
        return int(k < 0 ? k + n : k);
    };
    int x0 = wrap(fx, tex.width), x1 = wrap(fx + 1.0f, tex.width);
    int y0 = wrap(fy, tex.height), y1 = wrap(fy + 1.0f, tex.height);
    auto at = [&](int xi, int yi) { return tex.texels[size_t(yi) * tex.width + xi]; };
    return (1.0f - ty) * ((1.0f - tx) * at(x0, y0) + tx * at(x1, y0)) +
           ty * ((1.0f - tx) * at(x0, y1) + tx * at(x1, y1));
}

// A map's value at a hit's uv, after its -s, -o and -clamp options.
inline Spectrum lookupTexture(const std::vector<Texture>& textures, const TextureMap& map, Vec2 uv) {
    uv = uv * map.scale + map.offset;
    if (map.clamp) uv = glm::clamp(uv, Vec2(0.0f), Vec2(1.0f));
    return lookupTexture(textures[size_t(map.texture)], uv, map.clamp);
}

} // namespace pt
