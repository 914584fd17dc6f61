#include "texture/mip_pyramid.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace pt {

namespace {

// Level sizes below `width` x `height`, level 0 included.
std::vector<MipLevel> mipLevelsOf(int width, int height, int bytesPerTexel) {
    std::vector<MipLevel> levels;
    size_t offset = 0;
    for (int w = width, h = height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
        levels.push_back({w, h, offset});
        offset += size_t(w) * size_t(h) * size_t(bytesPerTexel);
        if (w == 1 && h == 1) break;
    }
    return levels;
}

// The fine texels each coarse texel covers along one axis, with the share of each: coarse texel i
// spans [i, i + 1) * fine / coarse fine texels (two of weight 1/2 where fine is even).
using AxisTaps = std::vector<std::vector<std::pair<int, float>>>;
AxisTaps axisTaps(int fine, int coarse) {
    AxisTaps taps(static_cast<size_t>(coarse));
    double ratio = double(fine) / double(coarse);
    for (int i = 0; i < coarse; ++i) {
        double a = i * ratio, b = (i + 1) * ratio;
        for (int j = int(std::floor(a)); j < fine && j < b; ++j)
            taps[size_t(i)].emplace_back(j, float((std::min(b, j + 1.0) - std::max(a, double(j))) / ratio));
    }
    return taps;
}

// Filters level `from` (whose channel c of texel (x, y) is fine(x, y, c)) into `coarse`, in
// linear float, and stores it as level `to` of the texture.
template <typename Fine>
void filterLevel(Texture& t, const MipLevel& from, const MipLevel& to, Fine&& fine, std::vector<float>& coarse) {
    const int nc = t.channels, bpc = bytesPerChannel(t.format);
    coarse.assign(size_t(to.width) * size_t(to.height) * size_t(nc), 0.0f);
    const bool halves = from.width == 2 * to.width && from.height == 2 * to.height;
    const AxisTaps tx = halves ? AxisTaps() : axisTaps(from.width, to.width);
    const AxisTaps ty = halves ? AxisTaps() : axisTaps(from.height, to.height);
    tbb::parallel_for(0, to.height, [&](int y) {
        for (int x = 0; x < to.width; ++x) {
            float* out = &coarse[(size_t(y) * size_t(to.width) + size_t(x)) * size_t(nc)];
            if (halves) // the usual case: four texels of weight 1/4
                for (int c = 0; c < nc; ++c)
                    out[c] = 0.25f * ((fine(2 * x, 2 * y, c) + fine(2 * x + 1, 2 * y, c)) +
                                      (fine(2 * x, 2 * y + 1, c) + fine(2 * x + 1, 2 * y + 1, c)));
            else
                for (auto [fy, wy] : ty[size_t(y)])
                    for (auto [fx, wx] : tx[size_t(x)])
                        for (int c = 0; c < nc; ++c) out[c] += wy * wx * fine(fx, fy, c);
            uint8_t* stored = t.data.data() + to.offset + (size_t(y) * size_t(to.width) + size_t(x)) * size_t(nc * bpc);
            for (int c = 0; c < nc; ++c) storeTexel(t.format, out[c], stored + c * bpc);
        }
    });
}

// Level 0's largest |value|: the largest byte where bytes are monotonic in value, else every value.
float peakOf(const Texture& t) {
    const size_t count = size_t(t.width) * size_t(t.height) * size_t(t.channels);
    const uint8_t* data = t.data.data();
    return withTexelFormat(t.format, [&](auto format) {
        constexpr TexelFormat f = decltype(format)::value;
        constexpr size_t bpc = size_t(bytesPerChannel(f));
        return tbb::parallel_reduce(
            tbb::blocked_range<size_t>(0, count, 1 << 16), 0.0f,
            [&](const tbb::blocked_range<size_t>& r, float m) {
                if constexpr (bpc == 1) {
                    uint8_t top = 0;
                    for (size_t i = r.begin(); i != r.end(); ++i) top = std::max(top, data[i]);
                    return std::max(m, loadTexel(f, &top));
                } else {
                    for (size_t i = r.begin(); i != r.end(); ++i) m = std::max(m, std::abs(loadTexel(f, data + i * bpc)));
                    return m;
                }
            },
            [](float a, float b) { return std::max(a, b); }); // max is exact in any order
    });
}

// Mean of float texels, summed row by row in parallel and the rows in order: the same bits on any thread count.
double meanOf(const std::vector<float>& values, int rows) {
    std::vector<double> rowSums(static_cast<size_t>(rows));
    const size_t perRow = values.size() / size_t(rows);
    tbb::parallel_for(0, rows, [&](int y) {
        double sum = 0.0;
        for (size_t i = size_t(y) * perRow; i < size_t(y + 1) * perRow; ++i) sum += values[i];
        rowSums[size_t(y)] = sum;
    });
    double sum = 0.0;
    for (double r : rowSums) sum += r;
    return values.empty() ? 1.0 : sum / double(values.size());
}

} // namespace

void buildMipPyramid(Texture& t) {
    const int nc = t.channels;
    t.peak = peakOf(t);
    std::vector<MipLevel> levels = mipLevelsOf(t.width, t.height, t.bytesPerTexel());
    t.data.resize(levels.back().offset + size_t(t.bytesPerTexel()));
    t.levels = levels;
    // Level 1 from the stored level 0; each level after from the float copy of the one before,
    // so that rounding to 8 bits does not compound from level to level.
    std::vector<float> fine, coarse;
    const uint8_t* base = t.data.data();
    const size_t stride = size_t(t.width) * size_t(nc); // channels per row of level 0
    for (size_t l = 1; l < levels.size(); ++l) {
        const MipLevel& from = levels[l - 1];
        if (l == 1)
            withTexelFormat(t.format, [&](auto format) {
                constexpr TexelFormat f = decltype(format)::value;
                constexpr size_t bpc = size_t(bytesPerChannel(f));
                filterLevel(t, levels[0], levels[1], [&](int x, int y, int c) {
                    return loadTexel(f, base + (size_t(y) * stride + size_t(x) * size_t(nc) + size_t(c)) * bpc);
                }, coarse);
            });
        else
            filterLevel(t, from, levels[l], [&](int x, int y, int c) {
                return fine[(size_t(y) * size_t(from.width) + size_t(x)) * size_t(nc) + size_t(c)];
            }, coarse);
        fine.swap(coarse);
        // Every level keeps level 0's mean: level 1's, from its float texels, is the cheapest to sum.
        if (l == 1) t.mean = meanOf(fine, levels[1].height);
    }
    if (levels.size() == 1) {
        double sum = 0.0;
        for (int c = 0; c < nc; ++c) sum += t.texel(0, 0, c);
        t.mean = nc ? sum / nc : 1.0;
    }
}

} // namespace pt
