// The golden comparison must be neither flaky nor blind. Renders of the cornell_box case with
// other seeds must pass against the committed reference; the same render with a planted error
// (a region 2 % brighter, a filled-in shadow, a shifted image, a NaN) must not.
#include "accel/accel.h"
#include "image/compare.h"
#include "render/renderer.h"
#include "load/scene_loader.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

constexpr int kSize = 128;
constexpr uint32_t kTestSpp = 256; // as in golden/manifest.txt

class DiffPower : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        Warnings w;
        scene_ = new Scene(loadScene(PT_SOURCE_DIR "/scenes/cornell_box.obj", w));
        accel_ = new Accel(*scene_, 0);
        reference_ = new Image;
        ASSERT_EQ(readImage(PT_SOURCE_DIR "/golden/cornell_box.exr", *reference_), "");
    }
    static void TearDownTestSuite() {
        delete accel_;
        delete scene_;
        delete reference_;
    }
    static Image render(uint64_t seed) {
        RenderSettings s;
        s.seed = seed;
        RenderResult r = renderImage(*scene_, *accel_, scene_->cameras[0], kSize, kSize, kTestSpp, 0, s);
        Image img;
        img.width = img.height = kSize;
        img.rgb = r.film.mean();
        img.layers.push_back({"variance", {"R", "G", "B"}, r.film.varianceOfMean()});
        return img;
    }
    static CompareReport compare(const Image& test) {
        CompareOptions o;
        std::string error;
        o.testCounts.assign(size_t(kSize) * kSize, float(kTestSpp));
        o.referenceCounts = pixelSampleCounts(*reference_, error);
        return compareImages(test, *reference_, o);
    }
    static float& at(Image& img, int x, int y, int c) { return img.rgb[3 * (size_t(y) * kSize + x) + c]; }

    static Scene* scene_;
    static Accel* accel_;
    static Image* reference_;
};
Scene* DiffPower::scene_ = nullptr;
Accel* DiffPower::accel_ = nullptr;
Image* DiffPower::reference_ = nullptr;

TEST_F(DiffPower, OtherSeedsPass) {
    ASSERT_GT(samplesPerPixel(*reference_), 0.0);
    int failures = 0;
    const int seeds = 12;
    for (uint64_t seed = 1; seed <= uint64_t(seeds); ++seed) {
        CompareReport r = compare(render(seed));
        ASSERT_EQ(r.inputError, "");
        if (!r.pass) ++failures;
        EXPECT_TRUE(r.pass) << "seed " << seed << ": " << r.failedTests << " of " << r.tests << " tests, worst z "
                            << r.worst[0].z;
    }
    std::printf("[ false failures ] %d of %d seeds\n", failures, seeds);
}

TEST_F(DiffPower, RegionTwoPercentBrighterFails) {
    Image test = render(1);
    ASSERT_TRUE(compare(test).pass);
    for (int y = 40; y < 72; ++y)
        for (int x = 52; x < 84; ++x)
            for (int c = 0; c < 3; ++c) at(test, x, y, c) *= 1.02f;
    CompareReport r = compare(test);
    EXPECT_FALSE(r.pass) << "largest |z| " << r.worst[0].z << " of threshold " << r.zThreshold;
    // The worst block overlaps the planted region.
    EXPECT_TRUE(r.worst[0].x0 < 84 && r.worst[0].x1 > 52 && r.worst[0].y0 < 72 && r.worst[0].y1 > 40);
}

// A shadow filled in: the darkest 12x12 patch of floor (relative to its surroundings) brought up
// to the brightness around it, as if an occluder had been lost.
TEST_F(DiffPower, MissingShadowFails) {
    Image test = render(1);
    auto lum = [&](const Image& img, int x, int y) {
        const float* p = &img.rgb[3 * (size_t(y) * kSize + x)];
        return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    };
    auto mean = [&](const Image& img, int x0, int y0, int s) {
        double m = 0;
        for (int y = y0; y < y0 + s; ++y)
            for (int x = x0; x < x0 + s; ++x) m += lum(img, x, y);
        return m / (s * s);
    };
    int bx = 0, by = 0;
    double best = 1e30;
    for (int y = kSize / 2; y + 24 <= kSize; y += 4) // the floor is in the lower half
        for (int x = 12; x + 24 <= kSize - 12; x += 4) {
            double ratio = mean(*reference_, x + 6, y + 6, 12) / (mean(*reference_, x, y, 24) + 1e-6);
            if (ratio < best) best = ratio, bx = x + 6, by = y + 6;
        }
    ASSERT_LT(best, 0.97) << "found no shadow to remove";
    double scale = 1.0 / best;
    for (int y = by; y < by + 12; ++y)
        for (int x = bx; x < bx + 12; ++x)
            for (int c = 0; c < 3; ++c) at(test, x, y, c) *= float(scale);
    CompareReport r = compare(test);
    EXPECT_FALSE(r.pass) << "shadow at " << bx << "," << by << " brightened by " << scale;
}

TEST_F(DiffPower, ShiftedImageFails) {
    Image test = render(1);
    Image shifted = test;
    for (int y = 0; y < kSize; ++y)
        for (int x = 1; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) at(shifted, x, y, c) = at(test, x - 1, y, c);
    EXPECT_FALSE(compare(shifted).pass);
}

TEST_F(DiffPower, NanIsAnInputErrorWithItsLocation) {
    Image test = render(1);
    at(test, 17, 93, 1) = std::nanf("");
    CompareReport r = compare(test);
    EXPECT_FALSE(r.pass);
    EXPECT_EQ(r.inputError, "test image has NaN at pixel (17, 93)");
}

TEST_F(DiffPower, SizeMismatchIsAnInputError) {
    Image small;
    small.width = small.height = 64;
    small.rgb.assign(64 * 64 * 3, 0.5f);
    EXPECT_NE(compare(small).inputError.find("size mismatch"), std::string::npos);
}

// A comparison that cannot fail must not pass: blocks larger than the image (--block 129 on a
// 128 x 128 image) test it as one block, and a brighter lamp fails there.
TEST_F(DiffPower, BlocksLargerThanTheImageTestItWhole) {
    Image test = render(1);
    CompareOptions o;
    std::string error;
    o.testCounts.assign(size_t(kSize) * kSize, float(kTestSpp));
    o.referenceCounts = pixelSampleCounts(*reference_, error);
    o.blockSize = 129;
    o.maxBlockSize = 129;
    CompareReport same = compareImages(test, *reference_, o);
    EXPECT_TRUE(same.pass);
    ASSERT_GE(same.tests, 3u) << "the whole image (and its halves, on the grid shifted by half a block)";
    EXPECT_EQ(same.smallestBlock, kSize);
    for (float& v : test.rgb) v *= 1.03f;
    CompareReport brighter = compareImages(test, *reference_, o);
    EXPECT_FALSE(brighter.pass) << "z " << brighter.worst[0].z << " of threshold " << brighter.zThreshold;
}

// Images of any shape, against blocks of any size: every pixel lies in a tested block, so a
// difference planted in any one pixel (with no noise to hide it, and large enough to stand out of
// a block of 300 x 129 pixels beyond the comparison's floor of 0.1 % of the mean) fails.
TEST(DiffBlocks, EveryPixelOfEveryShapeIsTested) {
    for (auto [w, h] : {std::pair{1, 1}, {4, 4}, {1, 40}, {40, 1}, {7, 300}, {3, 9}, {128, 128}})
        for (int block : {1, 8, 129}) {
            Image ref;
            ref.width = w;
            ref.height = h;
            ref.rgb.assign(size_t(w) * h * 3, 1.0f);
            ref.layers.push_back({"variance", {"R", "G", "B"}, std::vector<float>(size_t(w) * h * 3, 1e-6f)});
            CompareOptions o;
            o.blockSize = block;
            o.maxBlockSize = std::max(64, block);
            ASSERT_TRUE(compareImages(ref, ref, o).pass);
            for (int y = 0; y < h; y += std::max(1, h / 5))
                for (int x = 0; x < w; x += std::max(1, w / 5)) {
                    Image test = ref;
                    test.rgb[3 * (size_t(y) * w + x) + 1] = 1000.0f;
                    CompareReport r = compareImages(test, ref, o);
                    EXPECT_GT(r.tests, 0u);
                    EXPECT_FALSE(r.pass) << w << "x" << h << ", --block " << block << ": pixel (" << x << ", " << y
                                         << ") is in no tested block";
                }
        }
}

} // namespace
} // namespace pt
