// Texel storage and the mip pyramid: 8-bit sRGB and half encodings round to the nearest value,
// every level keeps the image's mean (odd sizes too), the pyramid is the same on any number of
// threads, and a lookup blends the two levels nearest its footprint.
#include "texture/mip_pyramid.h"
#include "texture/texel_format.h"
#include "texture/texture_sampler.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <random>

namespace pt {
namespace {

TEST(TexelFormat, SrgbEncodingIsTheNearestCode) {
    for (int i = 0; i < 256; ++i) {
        uint8_t code = 0;
        storeTexel(TexelFormat::Srgb8, srgbTable.linear[i], &code);
        EXPECT_EQ(code, i) << "code " << i << " does not round-trip";
    }
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (int n = 0; n < 20000; ++n) {
        float v = n < 10000 ? u01(rng) : 0.01f * u01(rng); // the dark end, where codes are close in value
        int best = 0;
        for (int i = 1; i < 256; ++i)
            if (std::abs(srgbTable.linear[i] - v) < std::abs(srgbTable.linear[best] - v)) best = i;
        uint8_t code = 0;
        storeTexel(TexelFormat::Srgb8, v, &code);
        ASSERT_EQ(code, best) << "linear " << v;
    }
    uint8_t code = 7;
    storeTexel(TexelFormat::Srgb8, 2.0f, &code);
    EXPECT_EQ(code, 255);
    storeTexel(TexelFormat::Srgb8, -1.0f, &code);
    EXPECT_EQ(code, 0);
}

TEST(TexelFormat, HalfRoundsToNearestEven) {
    for (uint32_t h = 0; h < 65536; ++h) {
        float v = halfToFloat(uint16_t(h));
        if (std::isnan(v)) continue;
        ASSERT_EQ(floatToHalf(v), h) << "half " << h << " (" << v << ") does not round-trip";
    }
    EXPECT_EQ(halfToFloat(0x3c00), 1.0f);
    EXPECT_EQ(floatToHalf(1.0f + 1.0f / 2048.0f), 0x3c00);         // a tie: to the even 1.0
    EXPECT_EQ(floatToHalf(1.0f + 3.0f / 2048.0f), 0x3c02);         // a tie: to the even 1 + 2/1024
    EXPECT_EQ(floatToHalf(65519.0f), 0x7bff);                       // 65504, the largest
    EXPECT_EQ(floatToHalf(65520.0f), 0x7c00);                       // rounds past it: infinity
    EXPECT_EQ(floatToHalf(-3.0f * std::ldexp(1.0f, -24)), 0x8003);  // subnormal
    EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(NAN))));
}

// A 7 x 5 texture of random values: levels of 3 x 2 and 1 x 1, each with level 0's mean.
TEST(MipPyramid, LevelsKeepTheMeanAtOddSizes) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<float> values(7 * 5 * 3);
    double sum[3] = {};
    for (size_t i = 0; i < values.size(); ++i) sum[i % 3] += values[i] = u01(rng);
    Texture t = Texture::fromFloats(7, 5, 3, values);
    buildMipPyramid(t);
    ASSERT_EQ(t.levels.size(), 3u);
    EXPECT_EQ(t.levels[1].width, 3);
    EXPECT_EQ(t.levels[1].height, 2);
    EXPECT_EQ(t.levels[2].width, 1);
    EXPECT_EQ(t.levels[2].height, 1);
    for (int c = 0; c < 3; ++c) {
        double mean1 = 0.0;
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) mean1 += t.texel(x, y, c, 1) / 6.0;
        EXPECT_NEAR(mean1, sum[c] / 35.0, 1e-5) << "level 1, channel " << c;
        EXPECT_NEAR(t.texel(0, 0, c, 2), sum[c] / 35.0, 1e-5) << "level 2, channel " << c;
    }
    EXPECT_NEAR(t.mean, (sum[0] + sum[1] + sum[2]) / 105.0, 1e-6);
    float peak = 0.0f;
    for (float v : values) peak = std::max(peak, v);
    EXPECT_EQ(t.peak, peak);
}

TEST(MipPyramid, SameOnAnyNumberOfThreads) {
    std::mt19937 rng(9);
    Texture t;
    t.width = 301;
    t.height = 257;
    t.channels = 3;
    t.format = TexelFormat::Srgb8;
    t.data.resize(size_t(t.width) * t.height * 3);
    for (uint8_t& b : t.data) b = uint8_t(rng());
    t.levels = {MipLevel{t.width, t.height, 0}};
    Texture one = t, two = t;
    tbb::task_arena(1).execute([&] { buildMipPyramid(one); });
    tbb::task_arena(2).execute([&] { buildMipPyramid(two); });
    EXPECT_EQ(one.data, two.data);
    EXPECT_EQ(one.mean, two.mean);
    EXPECT_EQ(one.levels.size(), 9u); // 301 x 257, 150 x 128, ... 2 x 2, 1 x 1
}

// An 8-bit black-and-white checker averages to the code of half the light (188), not to 128.
TEST(MipPyramid, EightBitLevelsAverageLight) {
    Texture t;
    t.width = t.height = 2;
    t.channels = 3;
    t.format = TexelFormat::Srgb8;
    t.data = {0, 0, 0, 255, 255, 255, 255, 255, 255, 0, 0, 0};
    t.levels = {MipLevel{2, 2, 0}};
    buildMipPyramid(t);
    ASSERT_EQ(t.levels.size(), 2u);
    EXPECT_EQ(t.data[t.levels[1].offset], 188);
    EXPECT_NEAR(t.texel(0, 0, 0, 1), 0.5f, 0.003f); // codes 187 and 188 are 0.497 and 0.503
}

// A 4 x 4 texture of 0 with one 16 in texel (1, 1): level 1 holds 4 in its texel (0, 0), level 2
// holds 1. A footprint of sqrt(2) texels (lod 0.5) at texel (1, 1)'s centre reads half of level 0
// (16) and half of level 1 (bilinear between 4 and its three zero neighbours, at a quarter each
// way: 4 * 0.75 * 0.75).
TEST(MipPyramid, LookupBlendsTheTwoNearestLevels) {
    std::vector<float> values(16, 0.0f);
    values[1 * 4 + 1] = 16.0f;
    Texture t = Texture::fromFloats(4, 4, 1, values, false);
    buildMipPyramid(t);
    const Vec2 st(1.5f / 4.0f, 1.0f - 1.5f / 4.0f);
    float v;
    sampleTexture<1>(t, TextureWrap::Clamp, TextureWrap::Clamp, st, Vec2(0.0f), Vec2(0.0f), 0, 8, &v);
    EXPECT_NEAR(v, 16.0f, 1e-5f) << "no footprint: the texel";
    const float w = std::sqrt(2.0f) / 4.0f;
    sampleTexture<1>(t, TextureWrap::Clamp, TextureWrap::Clamp, st, Vec2(w, 0.0f), Vec2(0.0f, w), 0, 8, &v);
    EXPECT_NEAR(v, 0.5f * 16.0f + 0.5f * 4.0f * 0.75f * 0.75f, 1e-4f) << "lod 0.5";
    sampleTexture<1>(t, TextureWrap::Clamp, TextureWrap::Clamp, st, Vec2(4.0f, 0.0f), Vec2(0.0f, 4.0f), 0, 8, &v);
    EXPECT_NEAR(v, 1.0f, 1e-5f) << "beyond the coarsest level: the mean";
}

// A footprint stretched 8:1 across a texture of vertical stripes one texel wide: taps along the
// major axis (across the stripes) average them at a fine level; one tap (isotropic) must go to
// the level of the major axis. Both give the mean. Stretched 8:1 along the stripes instead, the
// taps keep the stripe the lookup is in, and one tap blurs it into its neighbours.
TEST(MipPyramid, TapsFollowTheMajorAxis) {
    std::vector<float> values;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) values.push_back(float(x % 2));
    Texture t = Texture::fromFloats(64, 64, 1, values, false);
    buildMipPyramid(t);
    const Vec2 onStripe(0.5f / 64.0f, 0.5f); // texel column 0: value 0
    float v;
    sampleTexture<1>(t, TextureWrap::Repeat, TextureWrap::Repeat, onStripe, Vec2(16.0f / 64, 0.0f), Vec2(0.0f, 2.0f / 64),
                     0, 8, &v);
    EXPECT_NEAR(v, 0.5f, 0.05f) << "across the stripes";
    sampleTexture<1>(t, TextureWrap::Repeat, TextureWrap::Repeat, onStripe, Vec2(0.0f, 4.0f / 64), Vec2(0.5f / 64, 0.0f),
                     0, 8, &v);
    EXPECT_NEAR(v, 0.0f, 0.05f) << "along a stripe, 8 taps of half a texel keep it";
    sampleTexture<1>(t, TextureWrap::Repeat, TextureWrap::Repeat, onStripe, Vec2(0.0f, 4.0f / 64), Vec2(0.5f / 64, 0.0f),
                     0, 1, &v);
    EXPECT_NEAR(v, 0.5f, 0.05f) << "one tap blurs the stripe away";
}

} // namespace
} // namespace pt
