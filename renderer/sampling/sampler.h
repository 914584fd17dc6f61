// The per-path source of sample values. Each (pixel, sample index, seed) starts its own stream;
// dimensions are consumed in a fixed order by the path loop.
#pragma once

#include "core/math.h"
#include "sampling/rng.h"

namespace pt {

class IndependentSampler {
public:
    void startPixelSample(uint32_t pixelIndex, uint32_t sampleIndex, uint64_t seed) {
        uint64_t key = hashCombine(hashCombine(seed, pixelIndex), sampleIndex);
        rng_.seedWith(key, mixBits(key ^ 0x2545f4914f6cdd1dULL));
    }
    float get1D() { return rng_.nextFloat(); }
    Vec2 get2D() {
        float a = rng_.nextFloat();
        return Vec2(a, rng_.nextFloat());
    }
    // Independent streams have no dimensions to keep aligned: nothing to skip.
    void skip(uint32_t) {}

private:
    Pcg32 rng_;
};

} // namespace pt
