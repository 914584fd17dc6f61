#include "texture/texture_cache.h"

#include "core/system.h"

#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace pt {
namespace {

// The TextureSystem reads files through an ImageInput; this one serves a Texture's texels from
// memory. Its creator takes no arguments, so texels are found by name in a process-wide table.
std::mutex registryMutex;
std::unordered_map<std::string, const Texture*>& registry() {
    static std::unordered_map<std::string, const Texture*> table;
    return table;
}

class MemoryTextureInput final : public OIIO::ImageInput {
public:
    const char* format_name() const override { return "pt-memory"; }
    bool open(const std::string& name, OIIO::ImageSpec& spec) override {
        {
            std::lock_guard<std::mutex> lock(registryMutex);
            auto it = registry().find(name);
            texture_ = it == registry().end() ? nullptr : it->second;
        }
        if (!texture_) return false;
        m_spec = OIIO::ImageSpec(texture_->width, texture_->height, texture_->channels, OIIO::TypeDesc::FLOAT);
        if (texture_->hasAlpha()) m_spec.alpha_channel = texture_->channels - 1;
        spec = m_spec;
        return true;
    }
    bool close() override {
        texture_ = nullptr;
        return true;
    }
    bool read_native_scanline(int subimage, int miplevel, int y, int /*z*/, void* data) override {
        if (!texture_ || subimage != 0 || miplevel != 0 || y < 0 || y >= texture_->height) return false;
        size_t row = size_t(texture_->width) * size_t(texture_->channels);
        std::memcpy(data, texture_->texels.data() + size_t(y) * row, row * sizeof(float));
        return true;
    }

private:
    const Texture* texture_ = nullptr;
};

OIIO::ImageInput* createMemoryTextureInput() { return new MemoryTextureInput; }

std::atomic<uint64_t> nextCacheId{0};

} // namespace

struct TextureCache::Impl {
    OIIO::TextureSystem* system = nullptr;
    std::string prefix; // "pt-texture:<cache id>:" keeps caches of different scenes apart
    std::vector<OIIO::TextureSystem::TextureHandle*> handles;
    std::vector<std::string> names;
};

TextureCache::TextureCache() : impl_(std::make_unique<Impl>()) {
    impl_->prefix = "pt-texture:" + std::to_string(nextCacheId++) + ":";
}

TextureCache::~TextureCache() {
    // Closed and forgotten before their texels go; the system itself lives on for other caches.
    if (impl_->system)
        for (const std::string& name : impl_->names) impl_->system->invalidate(OIIO::ustring(name), true);
    std::lock_guard<std::mutex> lock(registryMutex);
    for (const std::string& name : impl_->names) registry().erase(name);
}

int TextureCache::add(Texture&& texture) {
    if (!impl_->system) {
        // The process's one system: systems created and destroyed in turn (tests load many scenes)
        // can hand a new one the per-thread tile caches of an old one.
        impl_->system = OIIO::TextureSystem::create(true);
        OIIO::TextureSystem& ts = *impl_->system;
        ts.attribute("automip", 1);   // mip levels of our single-level images, built by OIIO
        ts.attribute("autotile", 64); // cached in 64x64 tiles
        ts.attribute("forcefloat", 1);
        ts.attribute("max_open_files", 1000000); // files here are memory: nothing to run out of
        double physical = physicalMemoryBytes();
        int cacheMB = int(std::clamp(physical > 0 ? physical / 8e6 : 1024.0, 256.0, 8192.0));
        ts.attribute("max_memory_MB", float(cacheMB));
    }
    texture.peak = 0.0f;
    for (float v : texture.texels) texture.peak = std::max(texture.peak, std::abs(v));
    textures_.push_back(std::move(texture));
    std::string name = impl_->prefix + std::to_string(textures_.size() - 1);
    {
        std::lock_guard<std::mutex> lock(registryMutex);
        registry()[name] = &textures_.back();
    }
    OIIO::ustring uname(name);
    impl_->system->imagecache()->add_file(uname, createMemoryTextureInput);
    impl_->handles.push_back(impl_->system->get_texture_handle(uname));
    impl_->names.push_back(name);
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

OIIO::TextureOpt::Wrap oiioWrap(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Clamp: return OIIO::TextureOpt::WrapClamp;
    case TextureWrap::Mirror: return OIIO::TextureOpt::WrapMirror;
    default: return OIIO::TextureOpt::WrapPeriodic;
    }
}

// OpenImageIO scales uv to texels in int: a coordinate of 1e10 overflows there. Far from the
// unit square a repeating coordinate is taken back into it by its period (1, or 2 mirrored),
// where float still has a fraction; a clamped one stays, as OpenImageIO clamps it first.
float nearUnitSquare(float x, TextureWrap wrap) {
    if (std::abs(x) <= 1e6f) return x;
    switch (wrap) {
    case TextureWrap::Repeat: return x - std::floor(x);
    case TextureWrap::Mirror: return x - 2.0f * std::floor(0.5f * x);
    default: return x;
    }
}

} // namespace

void TextureCache::lookup(const TextureMap& map, Vec2 uv, const Footprint& fp, int first, int count, float* out,
                          float* dds, float* ddt) const {
    OIIO::TextureOpt opt;
    opt.firstchannel = first;
    opt.swrap = oiioWrap(map.wrapU);
    opt.twrap = oiioWrap(map.wrapV);
    opt.interpmode = OIIO::TextureOpt::InterpBilinear; // as Mitsuba and Cycles: no bicubic magnification
    opt.anisotropic = 16;
    uv = map.linear * uv + map.offset;
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = Vec2(0.0f);
    uv = Vec2(nearUnitSquare(uv.x, map.wrapU), nearUnitSquare(uv.y, map.wrapV));
    Vec2 dx = map.linear * fp.dx, dy = map.linear * fp.dy;
    if (!(std::isfinite(dx.x) && std::isfinite(dx.y) && std::isfinite(dy.x) && std::isfinite(dy.y)))
        dx = dy = Vec2(0.0f); // a bilinear lookup instead
    // OIIO's t runs down from the top row; OBJ's v runs up from the bottom.
    OIIO::TextureSystem* ts = impl_->system;
    bool ok = ts->texture(impl_->handles[size_t(map.texture)], ts->get_perthread_info(), opt, uv.x, 1.0f - uv.y, dx.x,
                          -dx.y, dy.x, -dy.y, count, out, dds, ddt);
    if (!ok) std::fill(out, out + count, 0.0f);
    if (ddt)
        for (int c = 0; c < count; ++c) ddt[c] = -ddt[c];
}

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
    lookup(map, uv, fp, 0, 3, rgb);
    return Spectrum(rgb[0], rgb[1], rgb[2]);
}

float TextureCache::scalar(const TextureMap& map, Vec2 uv, const Footprint& fp) const {
    int first, count;
    channelRange(textures_[size_t(map.texture)], map.channel, first, count);
    float v[3];
    lookup(map, uv, fp, first, count, v);
    return pick(map, v, count);
}

float TextureCache::scalar(const TextureMap& map, Vec2 uv, const Footprint& fp, Vec2& dValueDuv) const {
    int first, count;
    channelRange(textures_[size_t(map.texture)], map.channel, first, count);
    float v[3], ds[3], dt[3];
    lookup(map, uv, fp, first, count, v, ds, dt);
    // d/duv = linear^T d/dst, with st = linear uv + offset.
    dValueDuv = glm::transpose(map.linear) * Vec2(pick(map, ds, count), pick(map, dt, count));
    return pick(map, v, count);
}

Vec3 TextureCache::vector(const TextureMap& map, Vec2 uv, const Footprint& fp) const {
    float v[3];
    lookup(map, uv, fp, 0, 3, v);
    return Vec3(v[0], v[1], v[2]);
}

} // namespace pt
