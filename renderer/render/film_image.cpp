#include "render/film_image.h"

#include <cmath>
#include <limits>

namespace pt {

Image filmImage(const Film& film, const AovSelection& aovs, double exposure, size_t& overflowed) {
    Image image;
    image.width = film.width();
    image.height = film.height();
    image.rgb = film.mean();
    overflowed = 0;
    auto scale = [&](std::vector<float>& values, double gain) {
        for (float& v : values) {
            if (std::isinf(v)) continue; // a variance that is unknown (one sample) stays so
            double x = double(v) * gain;
            if (!(std::abs(x) <= double(std::numeric_limits<float>::max()))) {
                ++overflowed;
                x = std::copysign(double(std::numeric_limits<float>::max()), x);
            }
            v = float(x);
        }
    };
    scale(image.rgb, std::exp2(exposure)); // at 0 EV too: a merged part's mean may pass float
    if (aovs.variance) {
        image.layers.push_back({"variance", {"R", "G", "B"}, film.varianceOfMean()});
        scale(image.layers.back().pixels, std::exp2(2.0 * exposure)); // a mean's variance scales by the square
    }
    if (aovs.albedo) image.layers.push_back({"albedo", {"R", "G", "B"}, film.albedo()});
    if (aovs.normal) image.layers.push_back({"normal", {"X", "Y", "Z"}, film.normal()});
    if (aovs.depth) image.layers.push_back({"depth", {"Z"}, film.depth()});
    // A variance of the mean is only half of what pt diff needs where pixels hold different
    // counts (--noise, --time with --resume, merged parts): each pixel's count goes with it.
    auto countsDiffer = [&] {
        const Film::SampleCounts counts = film.sampleCounts();
        return counts.fewest != counts.most;
    };
    if (aovs.spp || (aovs.variance && countsDiffer())) image.layers.push_back({"spp", {"Z"}, film.samples()});
    return image;
}

} // namespace pt
