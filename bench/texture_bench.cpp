// pt-bench textures: the cost of one texture lookup through OpenImageIO's TextureSystem (what the
// renderer uses: mip-mapped, filtered, tile-cached) against the alternative it replaced, a plain
// bilinear lookup in a float array (no mip levels: aliases when minified). Lookups at random uvs
// (incoherent, as after bounces) and along a scanline (coherent, as camera rays), with and
// without a footprint, on one thread and on all; pairs interleaved, as the machine is shared.
#include "bench/bench_common.h"
#include "texture/texture_cache.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <random>

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
        const float* p = &t.texels[3 * (size_t(yi) * t.width + xi)];
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
    Texture t;
    t.width = t.height = size;
    t.channels = 3;
    t.texels.resize(size_t(size) * size * 3);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (float& v : t.texels) v = u01(rng);
    TextureCache cache;
    TextureMap map;
    Texture copy = t;
    map.texture = cache.add(std::move(copy));

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
    std::printf("pt-bench textures: %dx%d RGB float texture, %zu lookups per pattern, median of %d interleaved rounds\n",
                size, size, count, rounds);
    std::printf("  %-32s %8s %14s %14s %8s\n", "pattern", "threads", "TextureSystem", "bilinear", "ratio");
    for (const Pattern& p : patterns)
        for (int threads : {1, hw}) {
            std::vector<double> ts, bl;
            for (int r = 0; r < rounds; ++r) {
                ts.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return cache.color(map, uv, p.footprint); }));
                bl.push_back(nsPerLookup(p.uv, threads, [&](Vec2 uv) { return bilinear(t, uv); }));
            }
            double a = medianOf(ts), b = medianOf(bl);
            std::printf("  %-32s %8d %11.1f ns %11.1f ns %7.1fx\n", p.name, threads, a, b, a / b);
            if (threads == hw) break;
        }
    std::printf("  (ns per lookup: wall time / lookups, so all threads together; bilinear filters nothing)\n");
    return 0;
}

} // namespace pt::bench
