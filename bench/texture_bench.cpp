// pt-bench textures: the cost of one texture lookup through pt's own mip pyramid (what the
// renderer uses: an 8-bit sRGB texture, trilinear, up to TextureCache::kMaxTaps taps along a
// stretched footprint), against the same with one tap (isotropic), OpenImageIO's TextureSystem
// (what pt used before: automip, anisotropic, tile-cached, over the same texels as float), and a
// plain bilinear lookup in a float array (no mip levels: aliases when minified). Lookups at
// random uvs (incoherent, as after bounces) and along a scanline (coherent, as camera rays),
// with and without a footprint, on one thread and on all; rounds interleaved, as the machine is
// shared.
#include "bench/bench_common.h"
#include "texture/texture_cache.h"
#include "texture/texture_sampler.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include <unistd.h>

namespace pt::bench {
namespace {

// The lookup the TextureSystem replaced: bilinear, repeating, v = 0 at the bottom row.
Spectrum bilinear(const Texture& t, Vec2 uv) {
    float x = uv.x * float(t.width) - 0.5f, y = (1.0f - uv.y) * float(t.height) - 0.5f;
    float fx = std::floor(x), fy = std::floor(y), tx = x - fx, ty = y - fy;
    auto wrap = [](float i, int n) {
        int k = int(std::fmod(i, float(n)));
        return k < 0 ? k + n : k;
    };
    int x0 = wrap(fx, t.width), x1 = wrap(fx + 1.0f, t.width), y0 = wrap(fy, t.height), y1 = wrap(fy + 1.0f, t.height);
    auto at = [&](int xi, int yi) {
        const float* p = reinterpret_cast<const float*>(t.data.data()) + 3 * (size_t(yi) * t.width + xi);
        return Spectrum(p[0], p[1], p[2]);
    };
    return (1.0f - ty) * ((1.0f - tx) * at(x0, y0) + tx * at(x1, y0)) + ty * ((1.0f - tx) * at(x0, y1) + tx * at(x1, y1));
}

struct Pattern {
    const char* name;
    std::vector<Vec2> uv;
    Footprint footprint;
};

// Nanoseconds per lookup over all patterns' uvs, on `threads` threads.
template <typename Lookup>
double nsPerLookup(const std::vector<Vec2>& uvs, int threads, Lookup&& lookup) {
    std::atomic<uint64_t> sink{0};
    auto t0 = Clock::now();
    tbb::task_arena(threads).execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, uvs.size(), 16384), [&](const tbb::blocked_range<size_t>& r) {
            float sum = 0.0f;
            for (size_t i = r.begin(); i != r.end(); ++i) sum += lookup(uvs[i]).x;
            uint32_t bits;
            std::memcpy(&bits, &sum, sizeof bits);
            sink += bits;
        });
    });
    double ns = secondsSince(t0) * 1e9 / double(uvs.size());
    return sink == 1 ? ns + 1e-9 : ns; // keeps the sums alive
}

} // namespace

int runTextureBench(int argc, char** argv) {
    int rounds = 7, size = 1024;
    size_t count = 1 << 21;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--rounds" && i + 1 < argc) rounds = std::max(1, std::atoi(argv[++i]));
        else if (a == "--size" && i + 1 < argc) size = std::max(4, std::atoi(argv[++i]));
        else {
            std::fputs("usage: pt-bench textures [--rounds R] [--size N]  (an N x N RGB texture; default 1024)\n",
                       a == "--help" || a == "-h" ? stdout : stderr);
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    // Random 8-bit sRGB texels, held by pt as bytes and decoded as float for the others.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    Texture bytes;
    bytes.width = bytes.height = size;
    bytes.channels = 3;
    bytes.format = TexelFormat::Srgb8;
    bytes.data.resize(size_t(size) * size * 3);
    for (uint8_t& v : bytes.data) v = uint8_t(rng() & 0xff);
    bytes.levels = {MipLevel{size, size, 0}};
    std::vector<float> linear(bytes.data.size());
    for (size_t i = 0; i < linear.size(); ++i) linear[i] = srgbTable.linear[bytes.data[i]];
    const Texture t = Texture::fromFloats(size, size, 3, linear);
    TextureCache cache;
    TextureMap map;
    map.texture = cache.add(std::move(bytes));
    const Texture& ours = cache[map.texture];

    // The TextureSystem reads the same texels from a float EXR file (its tiles are cached after the first round).
    std::string exr = (std::filesystem::temp_directory_path() / ("pt-bench-texture-" + std::to_string(getpid()) + ".exr")).string();
    {
        auto out = OIIO::ImageOutput::create(exr);
        if (!out || !out->open(exr, OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::FLOAT)) ||
            !out->write_image(OIIO::TypeDesc::FLOAT, linear.data()) || !out->close()) {
            std::fprintf(stderr, "pt-bench textures: cannot write %s\n", exr.c_str());
            return 1;
        }
    }
    OIIO::TextureSystem* ts = OIIO::TextureSystem::create(false);
    ts->attribute("automip", 1);
    ts->attribute("autotile", 64);
    ts->attribute("forcefloat", 1);
    OIIO::TextureSystem::TextureHandle* handle = ts->get_texture_handle(OIIO::ustring(exr));
    auto textureSystem = [&](Vec2 uv, const Footprint& fp) {
        OIIO::TextureOpt opt;
        opt.interpmode = OIIO::TextureOpt::InterpBilinear;
        opt.anisotropic = 16;
        float rgb[3];
        ts->texture(handle, ts->get_perthread_info(), opt, uv.x, 1.0f - uv.y, fp.dx.x, -fp.dx.y, fp.dy.x, -fp.dy.y, 3, rgb);
        return Spectrum(rgb[0], rgb[1], rgb[2]);
    };
    auto isotropic = [&](Vec2 uv, const Footprint& fp) {
        float rgb[3];
        sampleTexture<3>(ours, TextureWrap::Repeat, TextureWrap::Repeat, uv, fp.dx, fp.dy, 0, 1, rgb);
        return Spectrum(rgb[0], rgb[1], rgb[2]);
    };

    std::vector<Pattern> patterns;
    Pattern random{"random uv, no footprint", {}, {}};
    for (size_t i = 0; i < count; ++i) random.uv.emplace_back(u01(rng), u01(rng));
    Pattern scan{"scanlines, no footprint", {}, {}};
    for (size_t i = 0; i < count; ++i) scan.uv.emplace_back(float(i % 2048) / 2048.0f, float(i / 2048) / 2048.0f);
    Pattern pixel = scan;
    pixel.name = "scanlines, 2-texel footprint";
    pixel.footprint = Footprint{Vec2(2.0f / size, 0.0f), Vec2(0.0f, 2.0f / size)};
    Pattern grazing = random;
    grazing.name = "random uv, 8:1 minified";
    grazing.footprint = Footprint{Vec2(32.0f / size, 0.0f), Vec2(0.0f, 4.0f / size)};
    patterns = {random, scan, pixel, grazing};

    const int hw = tbb::this_task_arena::max_concurrency();
    std::printf("pt-bench textures: %dx%d 8-bit sRGB texture, %zu lookups per pattern, median of %d interleaved rounds\n",
                size, size, count, rounds);
    std::printf("  %-30s %7s %10s %10s %10s %10s %9s %9s\n", "pattern", "threads", "pt", "pt 1 tap", "TexSystem",
                "bilinear", "pt/bilin", "pt/TS");
    for (const Pattern& p : patterns)
        for (int threads : {1, hw}) {
            std::vector<double> a, b, c, d;
            for (int r = 0; r < rounds; ++r) {
                a.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return cache.color(map, uv, p.footprint); }));
                b.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return isotropic(uv, p.footprint); }));
                c.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return textureSystem(uv, p.footprint); }));
                d.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return bilinear(t, uv); }));
            }
            double pa = medianOf(a), pb = medianOf(b), pc = medianOf(c), pd = medianOf(d);
            std::printf("  %-30s %7d %7.1f ns %7.1f ns %7.1f ns %7.1f ns %8.2fx %8.2fx\n", p.name, threads, pa, pb, pc, pd,
                        pa / pd, pa / pc);
            if (threads == hw) break;
        }
    std::printf("  (ns per lookup: wall time / lookups, so all threads together; bilinear filters nothing)\n");
    OIIO::TextureSystem::destroy(ts);
    std::filesystem::remove(exr);
    return 0;
}

} // namespace pt::bench
