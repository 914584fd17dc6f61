// Owen-scrambled Sobol points, shuffled per dimension pair (Burley 2020, "Practical Hash-based
// Owen Scrambling"). Each sample dimension (sampler.h) is a pair of the first two Sobol
// dimensions, with the sample index shuffled and both coordinates scrambled by hashes of
// (pixel, seed, dimension).
// Every pixel gets its own randomization, so the estimate stays unbiased, and a power-of-two
// prefix of samples is stratified in each pair: the cheapest variance reduction there is.
#pragma once

#include "core/math.h"
#include "sampling/sampler.h"

#include <array>
#include <cstddef>

namespace pt {

namespace sobol {

// The bit-level steps below are templates over a 32-bit integer or a vector of them, so that
// the SIMD draw kernels (sobol_lanes.h) run this same source on their lanes.
template <typename U>
inline U reverseBits(U x) {
    x = (x >> 16) | (x << 16); // with the next line, a byte swap (GCC emits bswap for 32 bits)
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

// A hash in which each bit depends only on lower bits: applied to bit-reversed values it is an
// Owen scramble (Laine and Karras 2011, with Burley's constants).
template <typename U>
inline U laineKarrasPermutation(U x, U seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scramble of a 32-bit fraction given in bit-reversed form; returns it in normal order.
template <typename U>
inline U scrambleReversed(U reversed, U seed) {
    return reverseBits(laineKarrasPermutation(reversed, seed));
}


// The second Sobol dimension (direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), v_0 = 2^31),
// in bit-reversed order. The shuffled index has random high bits, so a loop over its bits would
// run 32 unpredictable iterations; instead four byte tables hold the XOR of the directions of
// every bit pattern of each index byte, built at compile time.
constexpr uint32_t reverseBitsConstexpr(uint32_t x) {
    uint32_t r = 0;
    for (int i = 0; i < 32; ++i) r |= ((x >> i) & 1u) << (31 - i);
    return r;
}
inline constexpr auto kDimension1ByteTables = [] {
    std::array<std::array<uint32_t, 256>, 4> tables{};
    uint32_t directions[32] = {};
    uint32_t v = 1u << 31;
    for (int k = 0; k < 32; ++k, v ^= v >> 1) directions[k] = reverseBitsConstexpr(v);
    for (int byte = 0; byte < 4; ++byte)
        for (uint32_t pattern = 0; pattern < 256; ++pattern) {
            uint32_t x = 0;
            for (int bit = 0; bit < 8; ++bit)
                if (pattern & (1u << bit)) x ^= directions[8 * byte + bit];
            tables[byte][pattern] = x;
        }
    return tables;
}();
inline uint32_t dimension1Reversed(uint32_t index) {
    const auto& t = kDimension1ByteTables;
    return t[0][index & 0xffu] ^ t[1][(index >> 8) & 0xffu] ^ t[2][(index >> 16) & 0xffu] ^ t[3][index >> 24];
}
// The first two Sobol dimensions in normal order (for tests and reference).
inline uint32_t dimension0(uint32_t index) { return reverseBits(index); }
inline uint32_t dimension1(uint32_t index) { return reverseBits(dimension1Reversed(index)); }

inline float toUnitFloat(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

// A cheap 32-bit mix (the "lowbias32" finalizer) for per-dimension seeds.
template <typename U>
inline U mix32(U x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

} // namespace sobol

// Owen-scrambled Sobol values for the first kSobolDimensions dimensions, independent hashed
// values beyond: every value a pure function of (pixel, sample index, seed, dimension).
class SobolSampler {
public:
    // Stratification pays on the first bounces; deeper dimensions are hashed, which costs a
    // fraction as much per value. 12 covers the camera, two whole vertices and the third
    // vertex's light choice (sampleDimension).
    static constexpr uint32_t kSobolDimensions = 12;

    SobolSampler() = default;
    SobolSampler(uint32_t pixelIndex, uint32_t sampleIndex, uint64_t seed)
        : SobolSampler(pixelKey(pixelIndex, seed), sampleIndex) {}
    // What the sampler keeps of (pixel, seed): computed once per pixel, not once per sample.
    static PixelKey pixelKey(uint32_t pixelIndex, uint64_t seed) {
        return PixelKey{uint32_t(hashCombine(seed ^ 0x5bd1e995ULL, pixelIndex))};
    }
    SobolSampler(PixelKey pixel, uint32_t sampleIndex)
        : pixelSeed_(uint32_t(pixel.value)), sampleIndex_(sampleIndex),
          reversedIndex_(sobol::reverseBits(sampleIndex)) {} // the shuffle works on the reversed index

    float get1D(uint32_t dimension) const {
        if (dimension >= kSobolDimensions) return deep(dimension).x;
        uint32_t s = seedOf(dimension);
        // van der Corput is reverseBits(i): its reversed form is i itself.
        return sobol::toUnitFloat(sobol::scrambleReversed(shuffledIndex(s), s ^ 0xa511e9b3u));
    }
    Vec2 get2D(uint32_t dimension) const {
        if (dimension >= kSobolDimensions) return deep(dimension);
        uint32_t s = seedOf(dimension);
        uint32_t i = shuffledIndex(s);
        uint32_t x = sobol::scrambleReversed(i, s ^ 0xa511e9b3u);
        uint32_t y = sobol::scrambleReversed(sobol::dimension1Reversed(i), s ^ 0x63d83595u);
        return Vec2(sobol::toUnitFloat(x), sobol::toUnitFloat(y));
    }

    uint32_t pixelSeed() const { return pixelSeed_; }
    uint32_t sampleIndex() const { return sampleIndex_; }

    // Dimension `dimension` of many paths at once (the staged loop's draw stage), each given by
    // its pixelSeed() and sampleIndex(): x[k], and y[k] where y is given (a 2D draw), exactly as
    // get1D and get2D return them. Sobol dimensions go 8 paths per instruction where the CPU has
    // AVX2, 4 otherwise (sobol_draws.cpp).
    static void drawMany(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension,
                         float* x, float* y);
    // Which kernel drawMany uses: "avx2" or "sse2" (PT_SIMD=sse2 in the environment forces the latter).
    static const char* drawKernel();

private:
    // One hash per dimension (a 2D draw is one dimension of pairs): the Laine-Karras
    // permutations that use it mix it further.
    uint32_t seedOf(uint32_t dimension) const { return sobol::mix32(pixelSeed_ + 0x9e3779b9u * (dimension + 1)); }
    uint32_t shuffledIndex(uint32_t seed) const {
        return sobol::reverseBits(sobol::laineKarrasPermutation(reversedIndex_, seed));
    }
    Vec2 deep(uint32_t dimension) const {
        return unitPairOf(hashCombine((uint64_t(pixelSeed_) << 32) | sampleIndex_, dimension));
    }

    uint32_t pixelSeed_ = 0;
    uint32_t sampleIndex_ = 0;
    uint32_t reversedIndex_ = 0;
};

} // namespace pt
