// A scene's textures and the lookups a material makes in them: through the map's wrap and
// transform, filtered over the ray cone's footprint (texture/texture_sampler.h). Colour maps are
// decoded from sRGB before filtering, so minification averages light, not encoded values (a
// black-and-white checker far away is 0.5, not 0.21).
#pragma once

#include "texture/texture.h"

#include <deque>
#include <string>

namespace pt {

class TextureCache {
public:
    // Taps along a footprint's major axis, at most: a footprint stretched further takes its level
    // from the major axis divided by this (blurred along the minor one).
    static constexpr int kMaxTaps = 8;

    TextureCache() = default;
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    // Takes a texture read by readTexture (or made by Texture::fromFloats), builds its mip
    // pyramid and returns its index. Not thread-safe; scenes add their textures while loading,
    // before any lookup.
    int add(Texture&& texture);
    // Index of the texture read from `path` as colour or data, or -1.
    int find(const std::string& path, bool colour) const;
    const Texture& operator[](int index) const { return textures_[size_t(index)]; }
    size_t size() const { return textures_.size(); }
    double bytes() const;

    // The map's colour at uv (colour maps), filtered over the footprint.
    Spectrum color(const TextureMap& map, Vec2 uv, const Footprint& footprint) const;
    // The map's scalar value (the channel -imfchan picks).
    float scalar(const TextureMap& map, Vec2 uv, const Footprint& footprint) const;
    // Same, with the derivatives of the filtered value along u and v (bump maps).
    float scalar(const TextureMap& map, Vec2 uv, const Footprint& footprint, Vec2& dValueDuv) const;
    // The first three channels, as stored (normal maps).
    Vec3 vector(const TextureMap& map, Vec2 uv, const Footprint& footprint) const;

private:
    float pick(const TextureMap& map, const float* rgba, int count) const;

    std::deque<Texture> textures_; // a deque: a Texture& handed out stays valid as others are added
};

} // namespace pt
