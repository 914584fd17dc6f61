#include "sampling/sobol_sampler.h"

#include <gtest/gtest.h>

#include <set>

namespace pt {
namespace {

// The first 2^m samples of every dimension pair form a (0, m, 2)-net: each elementary interval
// [a / 2^i, (a + 1) / 2^i) x [b / 2^j, (b + 1) / 2^j) with i + j = m holds exactly one point.
// Owen scrambling and the index shuffle must both preserve that.
TEST(SobolSampler, PowerOfTwoPrefixesAreNets) {
    const int m = 6, n = 1 << m;
    for (uint32_t pixel : {0u, 7u, 123456u})
        for (int pair = 0; pair < 8; ++pair) {
            std::vector<Vec2> points;
            SobolSampler s;
            for (int i = 0; i < n; ++i) {
                s.startPixelSample(pixel, uint32_t(i), 3);
                for (int skip = 0; skip < pair; ++skip) s.get2D();
                points.push_back(s.get2D());
            }
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
    SobolSampler s;
    std::set<int> strata;
    for (int i = 0; i < n; ++i) {
        s.startPixelSample(42, uint32_t(i), 0);
        s.get2D(); // the pixel position
        strata.insert(int(s.get1D() * n));
    }
    EXPECT_EQ(strata.size(), size_t(n));
}

// Pixels and seeds get independent scrambles: the same sample index differs between them.
TEST(SobolSampler, PixelsAndSeedsAreDecorrelated) {
    SobolSampler a, b;
    a.startPixelSample(1, 0, 0);
    b.startPixelSample(2, 0, 0);
    EXPECT_NE(a.get2D(), b.get2D());
    a.startPixelSample(1, 0, 0);
    b.startPixelSample(1, 0, 1);
    EXPECT_NE(a.get2D(), b.get2D());
    // Mean over many pixels of one sample index is uniform (no shared offset).
    double sum = 0;
    for (uint32_t p = 0; p < 20000; ++p) {
        a.startPixelSample(p, 5, 0);
        sum += a.get1D();
    }
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

// Beyond the Sobol dimensions values come from an independent stream of the same (pixel,
// sample, seed): reached by drawing or by skipping, it never depends on what the sampler did
// for an earlier path (which would make the image depend on the thread that ran it).
TEST(SobolSampler, DeepDimensionsDependOnPixelSampleAndSeedOnly) {
    const uint32_t deep = SobolSampler::kSobolDimensions + 3;
    SobolSampler fresh;
    fresh.startPixelSample(17, 5, 2);
    fresh.skip(deep);
    float expected = fresh.get1D();

    SobolSampler used;
    used.startPixelSample(3, 9, 2);
    for (int i = 0; i < 40; ++i) used.get2D(); // another path, deep into its stream
    used.startPixelSample(17, 5, 2);
    used.skip(deep);
    EXPECT_EQ(used.get1D(), expected);

    // Uniform and uncorrelated across samples of a pixel.
    double sum = 0, sumProduct = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        SobolSampler s;
        s.startPixelSample(4, uint32_t(i), 0);
        s.skip(deep);
        Vec2 v = s.get2D();
        sum += v.x;
        sumProduct += (v.x - 0.5) * (v.y - 0.5);
    }
    EXPECT_NEAR(sum / n, 0.5, 0.01);
    EXPECT_NEAR(sumProduct / n, 0.0, 0.005);
}

} // namespace
} // namespace pt
