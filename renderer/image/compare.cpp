#include "image/compare.h"

#include <algorithm>
#include <cmath>

namespace pt {

const ImageLayer* varianceLayer(const Image& image) {
    for (const ImageLayer& l : image.layers)
        if (l.name == "variance" && l.channels.size() == 3) return &l;
    return nullptr;
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
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(v->pixels[3 * i + c]) || v->pixels[3 * i + c] < 0)
                    return where(i, "an invalid variance");
    return "";
}

CompareReport compareImages(const Image& test, const Image& reference, const CompareOptions& options) {
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
    const int bs = std::max(1, options.blockSize);
    r.blocksX = (w + bs - 1) / bs;
    r.blocksY = (h + bs - 1) / bs;
    r.blocks = r.blocksX * r.blocksY;
    r.blockZ.assign(size_t(r.blocks), 0.0f);
    r.zThreshold = bonferroniZ(options.falsePositiveRate, 3.0 * r.blocks);

    const double sppRatio = options.testSpp > 0 && options.referenceSpp > 0 ? options.referenceSpp / options.testSpp : 0.0;
    std::vector<BlockDifference> all;
    for (int by = 0; by < r.blocksY; ++by)
        for (int bx = 0; bx < r.blocksX; ++bx) {
            BlockDifference b;
            b.x0 = bx * bs;
            b.y0 = by * bs;
            b.x1 = std::min(w, b.x0 + bs);
            b.y1 = std::min(h, b.y0 + bs);
            double count = double(b.x1 - b.x0) * (b.y1 - b.y0);
            bool failed = false;
            for (int c = 0; c < 3; ++c) {
                double st = 0, sr = 0, varT = 0, varR = 0;
                for (int y = b.y0; y < b.y1; ++y)
                    for (int x = b.x0; x < b.x1; ++x) {
                        size_t i = 3 * (size_t(y) * w + x) + c;
                        st += test.rgb[i];
                        sr += reference.rgb[i];
                        if (r.statistical) {
                            varT += std::max(double(vt->pixels[i]), sppRatio * vr->pixels[i]);
                            varR += vr->pixels[i];
                        }
                    }
                BlockDifference d = b;
                d.channel = c;
                d.test = st / count;
                d.reference = sr / count;
                // Variance of a block mean: the pixels are independent estimates.
                double var = (varT + varR) / (count * count);
                double floor = options.relativeFloor * std::abs(d.reference) + 1e-12;
                d.z = (d.test - d.reference) / std::sqrt(var + floor * floor);
                float& bz = r.blockZ[size_t(by) * r.blocksX + bx];
                bz = std::max(bz, float(std::abs(d.z)));
                failed |= std::abs(d.z) > r.zThreshold;
                all.push_back(d);
            }
            r.failedBlocks += failed;
        }
    std::sort(all.begin(), all.end(), [](const BlockDifference& a, const BlockDifference& b) { return std::abs(a.z) > std::abs(b.z); });
    all.resize(std::min(all.size(), options.worstCount));
    r.worst = std::move(all);
    r.pass = r.statistical ? r.failedBlocks == 0 : false;
    return r;
}

} // namespace pt
