// Texture lookups through OpenImageIO's TextureSystem: mip levels built on first use, anisotropic
// filtering over a footprint, tiles cached. The texels come from memory (Texture), not from the
// files again: colour maps are decoded from sRGB before filtering, so minification averages
// light, not encoded values (a black-and-white checker far away is 0.5, not 0.21).
#pragma once

#include "texture/texture.h"

#include <deque>
#include <memory>
#include <string>

namespace pt {

class TextureCache {
public:
    TextureCache();
    ~TextureCache();
    TextureCache(const TextureCache&) = delete;
    TextureCache& operator=(const TextureCache&) = delete;

    // Takes a texture read by readTexture and returns its index. Not thread-safe; scenes add
    // their textures while loading, before any lookup.
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
    void lookup(const TextureMap& map, Vec2 uv, const Footprint& footprint, int first, int count, float* out,
                float* dds = nullptr, float* ddt = nullptr) const;
    float pick(const TextureMap& map, const float* rgba, int count) const;

    std::deque<Texture> textures_; // a deque: registered texels must not move
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace pt
