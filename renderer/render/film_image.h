// A film as an image for viewing: the mean, scaled by the exposure, and the AOV layers asked for.
// (A film as a part of a split render, with the sums merging needs: render/film_part.h.)
#pragma once

#include "image/image_io.h"
#include "render/film.h"

#include <string>

namespace pt {

// Which extra layers an image carries (pt render --aov).
struct AovSelection {
    bool variance = false, albedo = false, normal = false, depth = false, spp = false;
    bool firstHit() const { return albedo || normal || depth; } // layers the film must gather
    bool any() const { return variance || spp || firstHit(); }
};

// The film's mean as RGB times 2^exposure (its variance by the square), with the AOVs asked for;
// first-hit layers need a film that has them. Scaled in double: a value the exposure takes past
// float's range is written as the largest float and counted in `overflowed`, for a warning.
Image filmImage(const Film& film, const AovSelection& aovs, double exposure, size_t& overflowed);

// The largest |exposure| pt accepts, in EV: 2^32 either way is beyond any photographic use, and
// its square (the variance layer's factor, 2^64) still leaves ordinary values inside float.
inline constexpr double kMaxExposure = 32.0;

} // namespace pt
