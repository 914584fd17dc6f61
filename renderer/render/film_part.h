// A film as a part of a split render (an EXR): per pixel the sample count and the double sums
// (radiance, its square, the first-hit layers), each written as two floats, a high and a low
// word, which carry a double to about 2^-48, so that merging gives exactly the image of one
// process. The job's identity and the part's sample range go in the metadata; the window is the
// EXR's data window inside the full image.
//
// A part is read from a file pt merge and --resume did not write, so it is checked as any input
// is: every field against the others and against this machine's memory before anything is
// allocated, and every pixel's sums against its count, which must lie in the part's range.
#pragma once

#include "image/image_io.h"
#include "render/film.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// What a part's metadata says of it, once checked.
struct PartInfo {
    uint32_t first = 0, last = 0, spp = 0; // pt:samplesFirst, pt:samplesLast, pt:sppRequested
    int fullWidth = 0, fullHeight = 0;     // pt:fullWidth, pt:fullHeight
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;    // its pixels in the full image
    double exposure = 0.0, seconds = 0.0;  // pt:exposure, pt:renderSeconds
};

// The film's pixels as layers of `image` (its size, window and metadata are the caller's).
void addPartLayers(Image& image, const Film& film);

// Checks the part read as `image` and takes its film and fields; `name` stands for it in
// messages. Returns "" or the error, naming the part and the field or pixel at fault.
std::string partFromImage(const Image& image, const std::string& name, Film& film, PartInfo& info);

// Reads the part at `path` (see partFromImage).
std::string readPart(const std::string& path, Image& image, Film& film, PartInfo& info);

} // namespace pt
