// What pt render writes into an image's metadata: the job's fields (render/render_job.h), so a
// file says how to make it again and which parts merge, then what this run did.
#pragma once

#include "cli/render_options.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene.h"

#include <string>

namespace pt::cli {

// Every option that changes the image, and what else describes the scene and its options.
void addJobMetadata(Image& image, const RenderArgs& args, const Scene& scene, size_t cameraIndex,
                    const std::string& sceneHash);

// What this run did, after the job's fields; for a part, its share of the job, its window and
// the sums merging needs.
void addRunMetadata(Image& image, const RenderArgs& args, const RenderResult& result, int threads,
                    uint32_t first, uint32_t last, const PixelWindow& window, bool part);

} // namespace pt::cli
