// FLIP, a perceptual difference between a test image and its reference (Andersson et al., "FLIP:
// A Difference Evaluator for Alternating Images", HPG 2020), and HDR-FLIP, its extension to
// linear high-dynamic-range images (Andersson et al., Eurographics 2021), which takes the largest
// LDR-FLIP error over a range of exposures chosen from the reference.
//
// Per pixel the error lies in [0, 1]: 0 is indistinguishable when flipping between the images at
// the assumed viewing distance (`ppd`, pixels per degree of visual angle; 67 is a 0.7 m wide 4K
// monitor seen from 0.7 m), 1 the largest difference. It is reported by `pt diff` beside the
// statistical test, which stays the pass/fail criterion: FLIP says how visible a difference is,
// not whether it is noise.
#pragma once

#include <vector>

namespace pt {

constexpr float kFlipDefaultPpd = 67.0206f; // 0.7 m * (3840 px / 0.7 m) * pi / 180

struct FlipResult {
    std::vector<float> error; // per pixel, row 0 at the top
    double mean = 0;
    // HDR only: the exposure range (stops) and the number of exposures evaluated.
    float startExposure = 0, stopExposure = 0;
    int exposures = 0;
};

// LDR-FLIP of two images in linear RGB, each channel in [0, 1] (values outside are clamped);
// interleaved RGB, width * height * 3 floats each.
FlipResult ldrFlip(const std::vector<float>& test, const std::vector<float>& reference, int width, int height,
                   float ppd = kFlipDefaultPpd);

// HDR-FLIP of two linear, non-negative images: each exposure 2^c, c from the start to the stop
// exposure, is tone mapped with ACES, clamped to [0, 1] and compared by LDR-FLIP; a pixel's error
// is its largest. The exposure range follows the reference: from where its brightest pixel, to
// where its median pixel, maps to 0.85.
FlipResult hdrFlip(const std::vector<float>& test, const std::vector<float>& reference, int width, int height,
                   float ppd = kFlipDefaultPpd);

} // namespace pt
