// A film as an image. For viewing: the mean and the AOV layers asked for. As a part of a split
// render (an EXR): also what merging needs to give exactly the image of one process: per pixel the sample count
// and the double sums (radiance, its square, the first-hit layers), each written as two floats,
// a high and a low word, which carry a double to about 2^-48. The job's identity and the part's
// sample range go in the metadata; the window is the EXR's data window inside the full image.
#pragma once

#include "image/image_io.h"
#include "render/film.h"

#include <string>

namespace pt {

// Which extra layers an image carries (pt render --aov).
struct AovSelection {
    bool variance = false, albedo = false, normal = false, depth = false;
    bool firstHit() const { return albedo || normal || depth; } // layers the film must gather
    bool any() const { return variance || firstHit(); }
};

// The film's mean as RGB times 2^exposure (its variance by the square), with the AOVs asked for;
// first-hit layers need a film that has them. Scaled in double: a value the exposure takes past
// float's range is written as the largest float and counted in `overflowed`, for a warning.
Image filmImage(const Film& film, const AovSelection& aovs, double exposure, size_t& overflowed);

// The largest |exposure| pt accepts, in EV: 2^32 either way is beyond any photographic use, and
// its square (the variance layer's factor, 2^64) still leaves ordinary values inside float.
inline constexpr double kMaxExposure = 32.0;

// The film's pixels as layers of `image` (its size, window and metadata are the caller's).
void addPartLayers(Image& image, const Film& film);

// A part's film, sized like the image; "" or what is missing from it.
std::string filmFromPart(const Image& image, Film& film);

// Reads the part at `path` (pt:part in its metadata) and its film; "" or the error, naming the file.
std::string readPart(const std::string& path, Image& image, Film& film);

} // namespace pt
