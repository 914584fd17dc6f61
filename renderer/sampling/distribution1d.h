// A discrete distribution over n items proportional to non-negative weights, sampled by
// inverting its CDF. Used to pick a light by power.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pt {

class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(const std::vector<double>& weights) {
        cdf_.resize(weights.size() + 1);
        cdf_[0] = 0.0;
        double sum = 0.0;
        for (size_t i = 0; i < weights.size(); ++i) {
            sum += std::max(0.0, weights[i]);
            cdf_[i + 1] = sum;
        }
        total_ = sum;
        // Items of zero weight everywhere fall back to uniform, so sampling never divides by zero.
        for (size_t i = 0; i <= weights.size(); ++i)
            cdf_[i] = sum > 0.0 ? cdf_[i] / sum : double(i) / double(weights.size());
        cdf_.back() = 1.0;
    }

    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    double total() const { return total_; }
    float pmf(size_t i) const { return float(cdf_[i + 1] - cdf_[i]); }

    // Returns the item index for u in [0, 1) and rescales u to [0, 1) for reuse.
    size_t sample(float u, float* pmfOut, float* uRemapped = nullptr) const {
        // The last i with cdf[i] <= u; it always has positive mass because cdf[i + 1] > u.
        auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u));
        size_t i = size_t(std::clamp<std::ptrdiff_t>(it - cdf_.begin() - 1, 0, std::ptrdiff_t(size()) - 1));
        double p = cdf_[i + 1] - cdf_[i];
        *pmfOut = float(p);
        if (uRemapped) *uRemapped = std::min(float((u - cdf_[i]) / p), 0x1.fffffep-1f);
        return i;
    }

private:
    std::vector<double> cdf_;
    double total_ = 0.0;
};

} // namespace pt
