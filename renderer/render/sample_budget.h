// When a render stops besides its sample cap: a time budget (--time) and a noise target
// (--noise) that stops each pixel on its own (render/convergence.h).
#pragma once

#include <cstdint>

namespace pt {

struct SampleBudget {
    double seconds = 0.0;     // wall-clock budget of the render; 0: none
    float noise = 0.0f;       // relative standard error at which a pixel stops; 0: every pixel takes every sample
    uint32_t minSpp = 16;     // samples a pixel takes before it may stop (cut to the cap)
    // Pixels darker than this (in the film's units) count as this bright when their relative error
    // is taken, so that near-black pixels do not sample forever for an error nobody can see.
    float darkFloor = 1e-3f;

    bool adaptive() const { return noise > 0.0f; }
};

} // namespace pt
