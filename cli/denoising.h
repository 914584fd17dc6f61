// What pt render --denoise, pt merge --denoise and pt denoise share: opening Intel Open Image
// Denoise before any work, and turning an image's RGB into the denoised picture while keeping the
// raw estimate beside it (layer "noisy"), which is what pt diff and a later pt denoise read.
#pragma once

#include "denoise/denoiser.h"
#include "image/image_io.h"

#include <cstdio>
#include <memory>
#include <string>

namespace pt::cli {

// The layer that holds the raw estimate of a denoised image, and the attribute naming the filter.
inline constexpr const char* kNoisyLayer = "noisy";
inline constexpr const char* kDenoiserAttribute = "pt:denoiser";

// Opens OIDN with `threads` threads, or prints why not under `command` ("pt render") and sets
// `status`: 2 when no library is installed (a usage matter: the message says how to install
// it), 1 when the one found cannot serve (wrong version, not OIDN, a device that fails).
std::unique_ptr<Denoiser> openDenoiser(const char* command, int threads, FILE* err, int& status);

// Replaces image.rgb with its denoised version, guided by the albedo and normal features (RGB,
// the image's size): the raw values become the first layer, "noisy"; pt:denoiser, pt:denoiserVersion
// and pt:denoiseSeconds are added to the metadata. Returns "" or OIDN's error (the image is
// then unchanged).
std::string denoiseImage(const Denoiser& denoiser, Image& image, std::vector<float> albedo, std::vector<float> normal,
                         const DenoiseOptions& options, DenoiseReport& report);

// A denoised image read from a file (pt:denoiser set): its raw estimate, the "noisy" layer, moved
// back into rgb and the layer, its channel names and the denoiser's attributes removed. Returns
// false, leaving the image as read, if it is not denoised; sets `error` if it is but holds no
// raw estimate.
bool restoreRawEstimate(Image& image, std::string& error);

// "high", "balanced" or "fast" (--quality); a UsageError for anything else.
DenoiseQuality parseQuality(const std::string& option, const std::string& value);

} // namespace pt::cli
