// SobolSampler::drawMany: Sobol dimensions through the widest kernel the CPU runs (sobol_lanes.h),
// hashed ones path by path (they are a tenth of the cost).
#include "sampling/sobol_lanes.h"

#include <cstdlib>
#include <cstring>

namespace pt {

void sobolDrawsAvx2(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension, float* x,
                    float* y);

namespace {

using DrawKernel = void (*)(const uint32_t*, const uint32_t*, size_t, uint32_t, float*, float*);

void sobolDrawsSse2(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension, float* x,
                    float* y) {
    SobolLanes<4>::draw(pixelSeed, sampleIndex, count, dimension, x, y);
}

bool useAvx2() {
    const char* forced = std::getenv("PT_SIMD");
    if (forced && !std::strcmp(forced, "sse2")) return false;
    return __builtin_cpu_supports("avx2");
}

const bool kAvx2 = useAvx2();

} // namespace

const char* SobolSampler::drawKernel() { return kAvx2 ? "avx2" : "sse2"; }

void SobolSampler::drawMany(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension,
                            float* x, float* y) {
    if (dimension >= kSobolDimensions) {
        for (size_t k = 0; k < count; ++k) {
            SobolSampler s;
            s.pixelSeed_ = pixelSeed[k];
            s.sampleIndex_ = sampleIndex[k];
            Vec2 v = s.deep(dimension);
            x[k] = v.x;
            if (y) y[k] = v.y;
        }
        return;
    }
    (kAvx2 ? sobolDrawsAvx2 : sobolDrawsSse2)(pixelSeed, sampleIndex, count, dimension, x, y);
}

} // namespace pt
