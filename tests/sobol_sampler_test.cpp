#include "sampling/sobol_lanes.h"
#include "sampling/sobol_sampler.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <vector>

namespace pt {
namespace {

// The first 2^m samples of every dimension pair form a (0, m, 2)-net: each elementary interval
// [a / 2^i, (a + 1) / 2^i) x [b / 2^j, (b + 1) / 2^j) with i + j = m holds exactly one point.
// Owen scrambling and the index shuffle must both preserve that.
TEST(SobolSampler, PowerOfTwoPrefixesAreNets) {
    const int m = 6, n = 1 << m;
    for (uint32_t pixel : {0u, 7u, 123456u})
        for (uint32_t pair = 0; pair < SobolSampler::kSobolDimensions; ++pair) {
            std::vector<Vec2> points;
            for (int i = 0; i < n; ++i) points.push_back(SobolSampler(pixel, uint32_t(i), 3).get2D(uint32_t(pair)));
            for (int i = 0; i <= m; ++i) {
                int j = m - i;
                std::set<std::pair<int, int>> cells;
                for (const Vec2& p : points) {
                    ASSERT_GE(p.x, 0.0f);
                    ASSERT_LT(p.x, 1.0f);
                    cells.insert({int(p.x * float(1 << i)), int(p.y * float(1 << j))});
                }
                EXPECT_EQ(cells.size(), size_t(n)) << "pixel " << pixel << " pair " << pair << " intervals 2^" << i
                                                   << " x 2^" << j;
            }
        }
}

TEST(SobolSampler, OneDimensionalPrefixesAreStratified) {
    const int n = 32;
    std::set<int> strata;
    for (int i = 0; i < n; ++i) strata.insert(int(SobolSampler(42, uint32_t(i), 0).get1D(sampleDimension(0, SampleUse::LightChoice)) * n));
    EXPECT_EQ(strata.size(), size_t(n));
}

// Pixels and seeds get independent scrambles: the same sample index differs between them.
TEST(SobolSampler, PixelsAndSeedsAreDecorrelated) {
    EXPECT_NE(SobolSampler(1, 0, 0).get2D(kPixelDimension), SobolSampler(2, 0, 0).get2D(kPixelDimension));
    EXPECT_NE(SobolSampler(1, 0, 0).get2D(kPixelDimension), SobolSampler(1, 0, 1).get2D(kPixelDimension));
    // Mean over many pixels of one sample index is uniform (no shared offset).
    double sum = 0;
    for (uint32_t p = 0; p < 20000; ++p) sum += SobolSampler(p, 5, 0).get1D(1);
    EXPECT_NEAR(sum / 20000, 0.5, 0.01);
}


// The byte tables give the second Sobol dimension exactly: compare with the definition (XOR of
// direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1) over the set bits of the index).
TEST(SobolSampler, SecondDimensionTablesMatchDefinition) {
    Pcg32 rng(9, 9);
    for (int n = 0; n < 10000; ++n) {
        uint32_t index = n < 100 ? uint32_t(n) : rng.nextUint();
        uint32_t v = 1u << 31, expected = 0;
        for (uint32_t i = index; i; i >>= 1, v ^= v >> 1)
            if (i & 1u) expected ^= v;
        ASSERT_EQ(sobol::dimension1(index), expected) << index;
    }
    EXPECT_EQ(sobol::dimension1(1), 0x80000000u);
    EXPECT_EQ(sobol::dimension1(2), 0xc0000000u);
    EXPECT_EQ(sobol::dimension1(3), 0x40000000u);
}

} // namespace
} // namespace pt

namespace pt {
namespace {

// Pearson's chi-square of n points in a k x k grid of [0, 1)^2 against the uniform density.
template <typename Point>
double chiSquareUniform(int n, int k, Point&& point) {
    std::vector<int> bins(size_t(k * k), 0);
    for (int i = 0; i < n; ++i) {
        Vec2 p = point(i);
        EXPECT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f);
        ++bins[size_t(std::min(k - 1, int(p.y * float(k))) * k + std::min(k - 1, int(p.x * float(k))))];
    }
    const double expected = double(n) / double(k * k);
    double chi2 = 0.0;
    for (int b : bins) chi2 += (b - expected) * (b - expected) / expected;
    return chi2;
}

// Every dimension, Sobol or hashed, is uniform over the samples of a pixel, and two dimensions of
// one path are independent: chi-square over 16 x 16 cells (255 degrees of freedom; 370 is five
// standard deviations above the mean) for a 2D draw, two 1D draws of neighbouring dimensions
// (the last Sobol one against the first hashed one, and two hashed ones), and the same decision
// at two depths. The independent sampler is held to the same.
TEST(SobolSampler, DimensionsAreUniformAndIndependent) {
    const int n = 64000, k = 16;
    const uint32_t lastSobol = SobolSampler::kSobolDimensions - 1;
    const uint32_t deepDirection = sampleDimension(4, SampleUse::Direction);
    const uint32_t pairs[][2] = {{lastSobol, lastSobol + 1}, {lastSobol + 1, lastSobol + 2},
                                 {sampleDimension(1, SampleUse::Lobe), sampleDimension(3, SampleUse::Lobe)}};
    for (uint32_t pixel : {3u, 99999u}) {
        EXPECT_LT(chiSquareUniform(n, k, [&](int i) { return SobolSampler(pixel, uint32_t(i), 5).get2D(deepDirection); }), 370.0);
        EXPECT_LT(chiSquareUniform(n, k, [&](int i) { return IndependentSampler(pixel, uint32_t(i), 5).get2D(deepDirection); }), 370.0);
        for (auto [a, b] : pairs) {
            EXPECT_LT(chiSquareUniform(n, k, [&](int i) {
                          SobolSampler s(pixel, uint32_t(i), 5);
                          return Vec2(s.get1D(a), s.get1D(b));
                      }), 370.0) << a << " " << b;
            EXPECT_LT(chiSquareUniform(n, k, [&](int i) {
                          IndependentSampler s(pixel, uint32_t(i), 5);
                          return Vec2(s.get1D(a), s.get1D(b));
                      }), 370.0) << a << " " << b;
        }
    }
}

// A path's dimensions are laid out by vertex and purpose: no two decisions share one, and the
// camera's is apart from all.
TEST(SobolSampler, EachDecisionHasItsOwnDimension) {
    std::set<uint32_t> seen{kPixelDimension};
    for (int depth = 0; depth < 64; ++depth)
        for (SampleUse use : {SampleUse::LightChoice, SampleUse::LightPoint, SampleUse::Lobe, SampleUse::Direction, SampleUse::Roulette})
            EXPECT_TRUE(seen.insert(sampleDimension(depth, use)).second) << depth << " " << uint32_t(use);
}

// The draw stage's kernels give what one path's sampler gives, bit for bit: the dispatched one
// (AVX2 where the CPU has it), and the 1- and 4-lane forms of the same source, for every Sobol
// and some hashed dimensions, 1D and 2D, at counts that leave a partial last block.
TEST(SobolSampler, DrawManyMatchesOnePathAtATime) {
    std::printf("drawMany kernel: %s\n", SobolSampler::drawKernel());
    for (size_t count : {1u, 7u, 8u, 13u, 300u}) {
        std::vector<uint32_t> seeds(count), indices(count);
        std::vector<SobolSampler> samplers;
        for (size_t k = 0; k < count; ++k) {
            samplers.emplace_back(uint32_t(k * 97 + 5), uint32_t(k * k % 1031), 3);
            seeds[k] = samplers.back().pixelSeed();
            indices[k] = samplers.back().sampleIndex();
        }
        for (uint32_t d = 0; d < SobolSampler::kSobolDimensions + 4; ++d)
            for (bool pair : {false, true}) {
                std::vector<float> x(count), y(count), x1(count), y1(count), x4(count), y4(count);
                SobolSampler::drawMany(seeds.data(), indices.data(), count, d, x.data(), pair ? y.data() : nullptr);
                const bool sobol = d < SobolSampler::kSobolDimensions;
                if (sobol) {
                    SobolLanes<1>::draw(seeds.data(), indices.data(), count, d, x1.data(), pair ? y1.data() : nullptr);
                    SobolLanes<4>::draw(seeds.data(), indices.data(), count, d, x4.data(), pair ? y4.data() : nullptr);
                }
                for (size_t k = 0; k < count; ++k) {
                    const Vec2 want = pair ? samplers[k].get2D(d) : Vec2(samplers[k].get1D(d), 0.0f);
                    ASSERT_EQ(x[k], want.x) << "count " << count << " dimension " << d << " path " << k;
                    if (pair) ASSERT_EQ(y[k], want.y) << "count " << count << " dimension " << d << " path " << k;
                    if (!sobol) continue;
                    ASSERT_EQ(x1[k], want.x) << "1 lane, dimension " << d;
                    ASSERT_EQ(x4[k], want.x) << "4 lanes, dimension " << d;
                    if (pair) {
                        ASSERT_EQ(y1[k], want.y) << "1 lane, dimension " << d;
                        ASSERT_EQ(y4[k], want.y) << "4 lanes, dimension " << d;
                    }
                }
            }
    }
}

} // namespace
} // namespace pt
