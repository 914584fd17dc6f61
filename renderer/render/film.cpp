#include "render/film.h"

#include <algorithm>
#include <limits>

namespace pt {

Film::SampleCounts Film::sampleCounts() const {
    SampleCounts c;
    if (count_.empty()) return c;
    c.fewest = c.most = count_[0];
    double total = 0.0;
    for (uint32_t n : count_) {
        c.fewest = std::min(c.fewest, n);
        c.most = std::max(c.most, n);
        total += n;
    }
    c.mean = total / double(count_.size());
    return c;
}

size_t Film::convergedCount() const { return size_t(std::count(converged_.begin(), converged_.end(), uint8_t(1))); }

std::vector<float> Film::samples() const { return std::vector<float>(count_.begin(), count_.end()); }

std::vector<float> Film::perSample(const std::vector<glm::dvec3>& sums) const {
    std::vector<float> out(sums.size() * 3, 0.0f);
    for (size_t i = 0; i < sums.size(); ++i)
        if (count_[i] > 0)
            for (int c = 0; c < 3; ++c) out[3 * i + c] = float(sums[i][c] / count_[i]);
    return out;
}

std::vector<float> Film::mean() const { return perSample(sum_); }

std::vector<float> Film::varianceOfMean() const {
    // A pixel of fewer than two samples has no estimate of its variance: +inf says "unknown", where
    // 0 would say "certain" (pt diff refuses it, naming the pixel).
    std::vector<float> out(sum_.size() * 3, std::numeric_limits<float>::infinity());
    for (size_t i = 0; i < sum_.size(); ++i) {
        double n = count_[i];
        if (n < 2) continue;
        for (int c = 0; c < 3; ++c) {
            double m = sum_[i][c] / n;
            double var = std::max(0.0, (sumSq_[i][c] - n * m * m) / (n - 1.0));
            out[3 * i + c] = float(var / n);
        }
    }
    return out;
}

void Film::enableFirstHitLayers() {
    size_t n = sum_.size();
    albedo_.assign(n, glm::dvec3(0.0));
    normal_.assign(n, glm::dvec3(0.0));
    depth_.assign(n, 0.0);
    hits_.assign(n, 0);
}

std::vector<float> Film::albedo() const { return perSample(albedo_); }

std::vector<float> Film::normal() const {
    std::vector<float> out(normal_.size() * 3, 0.0f);
    for (size_t i = 0; i < normal_.size(); ++i) {
        double len = glm::length(normal_[i]);
        if (len > 0)
            for (int c = 0; c < 3; ++c) out[3 * i + c] = float(normal_[i][c] / len);
    }
    return out;
}

std::vector<float> Film::depth() const {
    std::vector<float> out(depth_.size(), std::numeric_limits<float>::infinity());
    for (size_t i = 0; i < depth_.size(); ++i)
        if (hits_[i] > 0) out[i] = float(depth_[i] / hits_[i]);
    return out;
}

} // namespace pt
