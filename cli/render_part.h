// A render as a part of a job: the share it renders (--samples, --crop), the part it resumes
// (--resume), and where an interrupted render puts what it finished.
#pragma once

#include "cli/render_options.h"
#include "image/image_io.h"
#include "render/film.h"
#include "render/renderer.h"

#include <cstdint>
#include <string>

namespace pt::cli {

// The share of the job this run renders: sample indices [first, last) of the window's pixels.
struct JobShare {
    uint32_t first = 0, last = 0;
    PixelWindow window;
};

// The share --samples and --crop ask for, checked against -spp and the image (the size is
// known only once the camera is chosen); "" or why not.
std::string jobShare(const RenderArgs& args, JobShare& share);

// out.exr -> out.partial.exr: where an interrupted render puts what it finished. A name that
// would then be too long for the file system loses the end of its stem instead.
std::string partialPath(const std::string& output);

// Reads the part to resume and checks it belongs to this job, window and range; "" or why not.
std::string readResumePart(const std::string& path, const Image& job, const JobShare& share, bool firstHitLayers,
                           Image& part, Film& film);

} // namespace pt::cli
