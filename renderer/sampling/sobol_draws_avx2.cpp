// SobolSampler::drawMany's kernel for AVX2: 8 lanes. This file alone is compiled with -mavx2
// (renderer/CMakeLists.txt) and is called only where the CPU has AVX2 (sobol_draws.cpp).
#include "sampling/sobol_lanes.h"

namespace pt {

void sobolDrawsAvx2(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension, float* x,
                    float* y) {
    SobolLanes<8>::draw(pixelSeed, sampleIndex, count, dimension, x, y);
}

} // namespace pt
