// Sample values as pure functions of (pixel, sample index, seed, dimension): no stream, no
// counter, so any decision of any path can be drawn in any order (a staged loop draws a batch's
// light choices together, then their directions) and the image never depends on the thread or
// tile order. Which dimension a decision reads is fixed by the vertex and its purpose.
#pragma once

#include "core/math.h"
#include "sampling/rng.h"

namespace pt {

// What a path vertex draws a sample for. Every vertex owns all five dimensions, used or not, so a
// dimension keeps its meaning whatever the path did before.
enum class SampleUse : uint32_t { LightChoice, LightPoint, Lobe, Direction, Roulette };
constexpr uint32_t kPixelDimension = 0; // the camera ray's position inside its pixel
constexpr uint32_t kDimensionsPerVertex = 5;

// The dimension a vertex at `depth` (scattering events before it) reads for `use`.
constexpr uint32_t sampleDimension(int depth, SampleUse use) {
    return 1 + kDimensionsPerVertex * uint32_t(depth) + uint32_t(use);
}

// Two 24-bit uniform floats in [0, 1) from a 64-bit hash (its top and middle bits).
inline Vec2 unitPairOf(uint64_t h) { return Vec2(float(h >> 40) * 0x1p-24f, float((h >> 16) & 0xffffffu) * 0x1p-24f); }

// A pixel's part of a sampler's key (pixel index and seed), made by Sampler::pixelKey.
struct PixelKey {
    uint64_t value;
};

// Independent uniform values: each dimension a hash of the pixel's key and the dimension.
class IndependentSampler {
public:
    IndependentSampler() = default;
    IndependentSampler(uint32_t pixelIndex, uint32_t sampleIndex, uint64_t seed)
        : IndependentSampler(pixelKey(pixelIndex, seed), sampleIndex) {}
    // What the sampler keeps of (pixel, seed): computed once per pixel, not once per sample.
    static PixelKey pixelKey(uint32_t pixelIndex, uint64_t seed) { return PixelKey{hashCombine(seed, pixelIndex)}; }
    IndependentSampler(PixelKey pixel, uint32_t sampleIndex) : key_(hashCombine(pixel.value, sampleIndex)) {}
    float get1D(uint32_t dimension) const { return unitPairOf(hashCombine(key_, dimension)).x; }
    Vec2 get2D(uint32_t dimension) const { return unitPairOf(hashCombine(key_, dimension)); }

private:
    uint64_t key_ = 0;
};

} // namespace pt
