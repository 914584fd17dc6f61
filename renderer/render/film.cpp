#include "render/film.h"

#include <algorithm>

namespace pt {

uint32_t Film::minSamples() const {
    return count_.empty() ? 0 : *std::min_element(count_.begin(), count_.end());
}

std::vector<float> Film::mean() const {
    std::vector<float> out(sum_.size() * 3, 0.0f);
    for (size_t i = 0; i < sum_.size(); ++i)
        if (count_[i] > 0)
            for (int c = 0; c < 3; ++c) out[3 * i + c] = float(sum_[i][c] / count_[i]);
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(sum_.size() * 3, 0.0f);
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

} // namespace pt
