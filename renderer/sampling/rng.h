// Random numbers keyed by (pixel, sample index, seed), never by thread or tile order, so that
// any thread count gives the same image.
#pragma once

#include <cstdint>

namespace pt {

// 64-bit finaliser of MurmurHash3: a cheap, well-mixing hash for building seeds.
inline uint64_t mixBits(uint64_t v) {
    v ^= v >> 33;
    v *= 0xff51afd7ed558ccdULL;
    v ^= v >> 33;
    v *= 0xc4ceb9fe1a85ec53ULL;
    v ^= v >> 33;
    return v;
}

inline uint64_t hashCombine(uint64_t a, uint64_t b) { return mixBits(a ^ (mixBits(b) + 0x9e3779b97f4a7c15ULL)); }

// PCG32 (O'Neill 2014): small state, good statistics, fast.
class Pcg32 {
public:
    Pcg32() = default;
    Pcg32(uint64_t seed, uint64_t stream) { seedWith(seed, stream); }

    void seedWith(uint64_t seed, uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextUint();
        state_ += seed;
        nextUint();
    }
    uint32_t nextUint() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }
    // Uniform in [0, 1): 24 random mantissa bits, so 1 is never returned.
    float nextFloat() { return float(nextUint() >> 8) * 0x1p-24f; }

private:
    uint64_t state_ = 0x853c49e6748fea9bULL;
    uint64_t inc_ = 0xda3e39cb94b95bdbULL;
};

} // namespace pt
