#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pt {

const ImageLayer* varianceLayer(const Image& image) {
    for (const ImageLayer& l : image.layers)
        if (l.name == "variance" && l.channels.size() == 3) return &l;
    return nullptr;
}

double samplesPerPixel(const Image& image) {
    for (const ImageAttribute& a : image.metadata)
        if (a.name == "pt:spp") {
            if (a.type == ImageAttribute::Type::Int) return double(a.integer);
            try { // files written before pt:spp became an int
                return std::stod(a.text);
            } catch (...) {
                return 0.0;
            }
        }
    return 0.0;
}

std::vector<float> pixelSampleCounts(const Image& image, std::string& error) {
    error.clear();
    const size_t n = size_t(image.width) * size_t(image.height);
    for (const ImageLayer& l : image.layers) {
        if (l.name != "spp" || l.channels.size() != 1 || l.pixels.size() != n) continue;
        for (size_t i = 0; i < n; ++i)
            if (!(l.pixels[i] >= 0.0f && l.pixels[i] <= 16777216.0f && l.pixels[i] == std::floor(l.pixels[i]))) {
                error = "its spp layer holds " + std::to_string(l.pixels[i]) + " at pixel (" + std::to_string(i % image.width) +
                        ", " + std::to_string(i / image.width) + "), which is not a count of samples";
                return {};
            }
        return l.pixels;
    }
    for (const ImageAttribute& a : image.metadata)
        if (a.name == "pt:sppMax") {
            error = "its pixels hold different sample counts (pt:spp " + std::to_string(long(samplesPerPixel(image))) +
                    ", pt:sppMax " + a.asText() + ") and it has no spp layer to say which; render it again with "
                    "--aov variance,spp so that each pixel is weighed by its own count";
            return {};
        }
    double spp = samplesPerPixel(image);
    return spp > 0 ? std::vector<float>(n, float(spp)) : std::vector<float>{};
}

double bonferroniZ(double alpha, double tests) {
    // Solve erfc(z / sqrt 2) = alpha / tests by bisection: P(|Z| > z) for a standard normal.
    double target = alpha / std::max(1.0, tests), lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        if (std::erfc(mid / std::sqrt(2.0)) > target) lo = mid;
        else hi = mid;
    }
    return hi;
}

static std::string findNonFinite(const Image& image, const char* which) {
    size_t n = size_t(image.width) * image.height;
    auto where = [&](size_t i, const std::string& what) {
        return std::string(which) + " image has " + what + " at pixel (" + std::to_string(i % image.width) + ", " +
               std::to_string(i / image.width) + ")";
    };
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(image.rgb[3 * i + c])) return where(i, std::isnan(image.rgb[3 * i + c]) ? "NaN" : "Inf");
    if (const ImageLayer* v = varianceLayer(image))
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) {
                float x = v->pixels[3 * i + c];
                if (x == std::numeric_limits<float>::infinity()) // pt writes it where a pixel holds one sample
                    return where(i, "no variance estimate (an infinite variance: a pixel of one sample; a variance "
                                    "needs two)");
                if (!std::isfinite(x) || x < 0) return where(i, "an invalid variance");
            }
    return "";
}

namespace {

// Summed-area table of one channel: any rectangle's sum in O(1).
class AreaSums {
public:
    AreaSums(int w, int h) : w_(w), sums_(size_t(w + 1) * (h + 1), 0.0) {}
    template <typename F>
    void fill(int h, F value) {
        for (int y = 0; y < h; ++y) {
            double row = 0;
            for (int x = 0; x < w_; ++x) {
                row += value(x, y);
                at(x + 1, y + 1) = at(x + 1, y) + row;
            }
        }
    }
    double sum(int x0, int y0, int x1, int y1) const { return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0); }

private:
    double& at(int x, int y) { return sums_[size_t(y) * (w_ + 1) + x]; }
    double at(int x, int y) const { return sums_[size_t(y) * (w_ + 1) + x]; }
    int w_;
    std::vector<double> sums_;
};

struct Block {
    int x0, y0, x1, y1;
};

// Every block of every scale and grid offset. A block cut by the image edge is kept where it
// holds at least half of what a whole one would inside the image (an image narrower than the
// block holds only a strip of it), so every pixel lies in some block. The smallest scale is at
// most the image's longer side: an image smaller than the block is tested as one block, never
// not at all.
std::vector<Block> allBlocks(int w, int h, const CompareOptions& o) {
    std::vector<Block> blocks;
    const int smallest = std::clamp(o.blockSize, 1, std::max(w, h));
    for (int s = smallest; s <= std::max(smallest, o.maxBlockSize); s *= 2) {
        if (s > std::max(w, h)) break;
        const int half = std::max(1, s / 2);
        const int whole = std::min(s, w) * std::min(s, h);
        for (int oy : {0, half})
            for (int ox : {0, half}) {
                if (s == 1 && (ox || oy)) continue;
                for (int y0 = oy - (oy ? s : 0); y0 < h; y0 += s)
                    for (int x0 = ox - (ox ? s : 0); x0 < w; x0 += s) {
                        Block b{std::max(0, x0), std::max(0, y0), std::min(w, x0 + s), std::min(h, y0 + s)};
                        if (2 * (b.x1 - b.x0) * (b.y1 - b.y0) >= whole) blocks.push_back(b);
                    }
            }
    }
    return blocks;
}

} // namespace

CompareReport compareImages(const Image& test, const Image& reference, const CompareOptions& options,
                            double relativeMseThreshold) {
    CompareReport r;
    if (test.width != reference.width || test.height != reference.height) {
        r.inputError = "size mismatch: test is " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                       ", reference is " + std::to_string(reference.width) + "x" + std::to_string(reference.height);
        return r;
    }
    if (test.width <= 0 || test.height <= 0) {
        r.inputError = "empty image";
        return r;
    }
    for (auto [img, name] : {std::pair{&test, "test"}, std::pair{&reference, "reference"}}) {
        r.inputError = findNonFinite(*img, name);
        if (!r.inputError.empty()) return r;
    }

    const int w = test.width, h = test.height;
    const size_t n = size_t(w) * h;
    double sq = 0, abs = 0;
    for (size_t i = 0; i < 3 * n; ++i) {
        double d = double(test.rgb[i]) - reference.rgb[i];
        sq += d * d / (double(reference.rgb[i]) * reference.rgb[i] + 0.01);
        abs += std::abs(d);
    }
    r.relativeMse = sq / double(3 * n);
    r.meanAbsError = abs / double(3 * n);

    const ImageLayer* vt = varianceLayer(test);
    const ImageLayer* vr = varianceLayer(reference);
    r.statistical = vt && vr;
    r.heat.assign(n, 0.0f);
    if (!r.statistical) {
        r.pass = r.relativeMse <= relativeMseThreshold;
        return r;
    }

    // Each test pixel's variance is at least the reference pixel's scaled to the test pixel's count.
    const bool counts = options.testCounts.size() == n && options.referenceCounts.size() == n;
    auto sppRatio = [&](size_t i) {
        return counts && options.testCounts[i] > 0.0f ? double(options.referenceCounts[i]) / options.testCounts[i] : 0.0;
    };
    const std::vector<Block> blocks = allBlocks(w, h, options);
    r.tests = 3 * blocks.size();
    r.smallestBlock = std::clamp(options.blockSize, 1, std::max(w, h));
    if (blocks.empty()) { // cannot happen (allBlocks covers every pixel), but a test of nothing must not pass
        r.inputError = "no block of the image could be tested";
        return r;
    }
    r.zThreshold = bonferroniZ(options.falsePositiveRate, double(r.tests));

    std::vector<BlockDifference> all;
    for (int c = 0; c < 3; ++c) {
        auto px = [&](int x, int y) { return 3 * (size_t(y) * w + x) + c; };
        AreaSums st(w, h), sr(w, h), vT(w, h), vR(w, h);
        st.fill(h, [&](int x, int y) { return double(test.rgb[px(x, y)]); });
        sr.fill(h, [&](int x, int y) { return double(reference.rgb[px(x, y)]); });
        vT.fill(h, [&](int x, int y) {
            return std::max(double(vt->pixels[px(x, y)]), sppRatio(size_t(y) * w + x) * vr->pixels[px(x, y)]);
        });
        vR.fill(h, [&](int x, int y) { return double(vr->pixels[px(x, y)]); });
        for (const Block& b : blocks) {
            double count = double(b.x1 - b.x0) * (b.y1 - b.y0);
            BlockDifference d{b.x0, b.y0, b.x1, b.y1, c};
            d.test = st.sum(b.x0, b.y0, b.x1, b.y1) / count;
            d.reference = sr.sum(b.x0, b.y0, b.x1, b.y1) / count;
            double var = (vT.sum(b.x0, b.y0, b.x1, b.y1) + vR.sum(b.x0, b.y0, b.x1, b.y1)) / (count * count);
            double floor = options.relativeFloor * std::abs(d.reference) + 1e-12;
            d.z = (d.test - d.reference) / std::sqrt(var + floor * floor);
            if (std::abs(d.z) > r.zThreshold) ++r.failedTests;
            float score = float(std::abs(d.z) / r.zThreshold);
            for (int y = b.y0; y < b.y1; ++y)
                for (int x = b.x0; x < b.x1; ++x) r.heat[size_t(y) * w + x] = std::max(r.heat[size_t(y) * w + x], score);
            all.push_back(d);
        }
    }
    std::sort(all.begin(), all.end(), [](const BlockDifference& a, const BlockDifference& b) { return std::abs(a.z) > std::abs(b.z); });
    // Report distinct places: skip blocks that overlap one already reported.
    for (const BlockDifference& d : all) {
        if (r.worst.size() >= options.worstCount) break;
        bool overlaps = false;
        for (const BlockDifference& k : r.worst)
            overlaps |= d.x0 < k.x1 && k.x0 < d.x1 && d.y0 < k.y1 && k.y0 < d.y1;
        if (!overlaps) r.worst.push_back(d);
    }
    r.pass = r.failedTests == 0;
    return r;
}

Image heatmapImage(const CompareReport& report, const Image& reference) {
    Image out;
    out.width = reference.width;
    out.height = reference.height;
    size_t n = size_t(out.width) * out.height;
    out.rgb.resize(3 * n);
    for (size_t i = 0; i < n; ++i) {
        const float* p = &reference.rgb[3 * i];
        float grey = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
        grey = 0.25f * std::clamp(grey / (1.0f + grey), 0.0f, 1.0f); // tone-mapped and dimmed, for context
        float s = i < report.heat.size() ? report.heat[i] : 0.0f;
        // Below half the threshold: the context alone; at the threshold red; at twice it yellow.
        float t = std::clamp((s - 0.5f) / 0.5f, 0.0f, 1.0f), u = std::clamp(s - 1.0f, 0.0f, 1.0f);
        out.rgb[3 * i + 0] = grey + (1.0f - grey) * t;
        out.rgb[3 * i + 1] = grey * (1.0f - t) + u;
        out.rgb[3 * i + 2] = grey * (1.0f - t);
    }
    return out;
}

} // namespace pt
