#include "texture/texture_cache.h"

#include "texture/mip_pyramid.h"
#include "texture/texture_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pt {

Texture Texture::fromFloats(int width, int height, int channels, const std::vector<float>& values, bool colour) {
    Texture t;
    t.colour = colour;
    t.width = width;
    t.height = height;
    t.channels = channels;
    t.format = TexelFormat::Float;
    t.data.resize(values.size() * sizeof(float));
    std::memcpy(t.data.data(), values.data(), t.data.size());
    t.levels = {MipLevel{width, height, 0}};
    return t;
}

int TextureCache::add(Texture&& texture) {
    buildMipPyramid(texture); // and its peak and mean
    textures_.push_back(std::move(texture));
    return int(textures_.size() - 1);
}

int TextureCache::find(const std::string& path, bool colour) const {
    for (size_t i = 0; i < textures_.size(); ++i)
        if (textures_[i].path == path && textures_[i].colour == colour) return int(i);
    return -1;
}

double TextureCache::bytes() const {
    double sum = 0.0;
    for (const Texture& t : textures_) sum += t.bytes();
    return sum;
}

namespace {

// Count channels from `first` of the map's texture at uv, through the map's transform and wraps.
template <int Count>
void lookup(const Texture& texture, const TextureMap& map, Vec2 uv, const Footprint& fp, int first, float* out,
            float* dds = nullptr, float* ddt = nullptr) {
    uv = map.linear * uv + map.offset;
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = Vec2(0.0f);
    Vec2 dx = map.linear * fp.dx, dy = map.linear * fp.dy;
    if (!(std::isfinite(dx.x) && std::isfinite(dx.y) && std::isfinite(dy.x) && std::isfinite(dy.y)))
        dx = dy = Vec2(0.0f); // a bilinear lookup instead
    sampleTexture<Count>(texture, map.wrapU, map.wrapV, uv, dx, dy, first, TextureCache::kMaxTaps, out, dds, ddt);
}

} // namespace

// -imfchan: which stored channel(s) a scalar map reads, and how they combine.
static void channelRange(const Texture& t, TextureChannel channel, int& first, int& count) {
    int colourChannels = t.hasAlpha() ? t.channels - 1 : t.channels; // 1 (grey) or 3
    first = 0;
    count = 1;
    switch (channel) {
    case TextureChannel::R: break;
    case TextureChannel::G: first = std::min(1, colourChannels - 1); break;
    case TextureChannel::B: first = std::min(2, colourChannels - 1); break;
    case TextureChannel::Alpha: first = t.channels - 1; break; // the loader checks there is one
    case TextureChannel::Rgb:
    case TextureChannel::Luminance: count = std::min(colourChannels, 3); break;
    }
}

float TextureCache::pick(const TextureMap& map, const float* v, int count) const {
    if (count == 3 && map.channel != TextureChannel::Rgb) return 0.2126f * v[0] + 0.7152f * v[1] + 0.0722f * v[2];
    return v[0];
}

Spectrum TextureCache::color(const TextureMap& map, Vec2 uv, const Footprint& fp) const {
    float rgb[3];
    lookup<3>(textures_[size_t(map.texture)], map, uv, fp, 0, rgb);
    return Spectrum(rgb[0], rgb[1], rgb[2]);
}

float TextureCache::scalar(const TextureMap& map, Vec2 uv, const Footprint& fp) const {
    int first, count;
    const Texture& t = textures_[size_t(map.texture)];
    channelRange(t, map.channel, first, count);
    float v[3];
    if (count == 1) lookup<1>(t, map, uv, fp, first, v);
    else lookup<3>(t, map, uv, fp, first, v);
    return pick(map, v, count);
}

float TextureCache::scalar(const TextureMap& map, Vec2 uv, const Footprint& fp, Vec2& dValueDuv) const {
    int first, count;
    const Texture& t = textures_[size_t(map.texture)];
    channelRange(t, map.channel, first, count);
    float v[3], ds[3], dt[3];
    if (count == 1) lookup<1>(t, map, uv, fp, first, v, ds, dt);
    else lookup<3>(t, map, uv, fp, first, v, ds, dt);
    // d/duv = linear^T d/dst, with st = linear uv + offset.
    dValueDuv = glm::transpose(map.linear) * Vec2(pick(map, ds, count), pick(map, dt, count));
    return pick(map, v, count);
}

Vec3 TextureCache::vector(const TextureMap& map, Vec2 uv, const Footprint& fp) const {
    float v[3];
    lookup<3>(textures_[size_t(map.texture)], map, uv, fp, 0, v);
    return Vec3(v[0], v[1], v[2]);
}

} // namespace pt
