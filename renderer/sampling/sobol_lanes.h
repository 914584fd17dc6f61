// Owen-scrambled Sobol draws for W paths at once: sobol_sampler.h's bit-level steps (templates)
// run on vectors of W 32-bit lanes (GCC vector extensions). W = 1 is the scalar form, which
// tests hold the wider ones to bit for bit; sobol_draws.cpp instantiates W = 4 (SSE2, any
// x86-64) and sobol_draws_avx2.cpp W = 8 (compiled with -mavx2, chosen at run time).
//
// Nothing built for AVX2 may reach code that runs without it. What is here has internal linkage
// (an unnamed namespace): each file keeps its own copy, built for its own instruction set. The
// shared steps it calls are instantiated for the lane vector type, and the 8-lane type only in
// the AVX2 file, so no other file links to those copies; 8 lanes must stay there.
#pragma once

#include "sampling/sobol_sampler.h"
#include "simd/lanes.h"

#include <cstddef>
#include <cstdint>

namespace pt {
namespace {

static_assert(sizeof(sobol::kDimension1ByteTables) == 4 * 256 * sizeof(uint32_t), "four tables of 256, contiguous");

template <int W>
struct SobolLanes {
    using U32 = typename Lanes<W>::U32;
    using I32 = typename Lanes<W>::I32;
    using F32 = typename Lanes<W>::F32;

    static U32 load(const uint32_t* p) {
        U32 v;
        __builtin_memcpy(&v, p, sizeof v);
        return v;
    }

    // The byte tables, lane by lane (no gather below AVX2, and AVX2's is no faster for four).
    // Read as plain memory: sobol::dimension1Reversed takes a uint32_t, and an out-of-line copy
    // of it from the AVX2 file could serve every other file.
    static U32 dimension1Reversed(U32 index) {
        const uint32_t* t = reinterpret_cast<const uint32_t*>(&sobol::kDimension1ByteTables);
        U32 r;
        for (int k = 0; k < W; ++k) {
            const uint32_t v = index[k];
            r[k] = t[v & 0xffu] ^ t[256 + ((v >> 8) & 0xffu)] ^ t[512 + ((v >> 16) & 0xffu)] ^ t[768 + (v >> 24)];
        }
        return r;
    }
    static F32 toUnitFloat(U32 x) { return __builtin_convertvector(I32(x >> 8), F32) * 0x1p-24f; }

    static void store(float* p, F32 v) { __builtin_memcpy(p, &v, sizeof v); }

    // W paths' values of one Sobol dimension: what SobolSampler::get1D (and get2D's second
    // coordinate, into y where given) return.
    static void block(const uint32_t* pixelSeed, const uint32_t* sampleIndex, uint32_t dimension, float* x, float* y) {
        const U32 s = sobol::mix32(load(pixelSeed) + 0x9e3779b9u * (dimension + 1));
        const U32 i = sobol::reverseBits(sobol::laineKarrasPermutation(sobol::reverseBits(load(sampleIndex)), s));
        store(x, toUnitFloat(sobol::scrambleReversed(i, s ^ 0xa511e9b3u)));
        if (y) store(y, toUnitFloat(sobol::scrambleReversed(dimension1Reversed(i), s ^ 0x63d83595u)));
    }

    // Dimension `dimension` (below SobolSampler::kSobolDimensions) of `count` paths, each given
    // by its pixel seed and sample index, in blocks of W (the last one padded).
    static void draw(const uint32_t* pixelSeed, const uint32_t* sampleIndex, size_t count, uint32_t dimension, float* x,
                     float* y) {
        size_t first = 0;
        for (; first + W <= count; first += W)
            block(pixelSeed + first, sampleIndex + first, dimension, x + first, y ? y + first : nullptr);
        if (first == count) return;
        uint32_t seeds[W] = {}, indices[W] = {};
        float xs[W], ys[W];
        for (size_t k = first; k < count; ++k) {
            seeds[k - first] = pixelSeed[k];
            indices[k - first] = sampleIndex[k];
        }
        block(seeds, indices, dimension, xs, y ? ys : nullptr);
        for (size_t k = first; k < count; ++k) {
            x[k] = xs[k - first];
            if (y) y[k] = ys[k - first];
        }
    }
};

} // namespace
} // namespace pt
