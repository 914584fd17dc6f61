// FLIP against NVIDIA's own implementation, and its basic properties.
//
// tests/data/flip holds a reference (a crop of golden/lab_cornell.exr) and a test image (a
// 1024-spp render of the same crop with a patch made 30 % redder and a band shifted by a pixel),
// and the error maps that NVIDIA's flip-evaluator 1.7 (PyPI) computes for them at 67 ppd:
// HDR-FLIP on the linear images, LDR-FLIP on the images clamped to [0, 1] (inputsRGB=False).
// tools/crosscheck/flip_reference.py regenerates those two maps.
#include "image/flip.h"
#include "image/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace pt {
namespace {

const std::string kData = std::string(PT_SOURCE_DIR) + "/tests/data/flip/";

Image load(const std::string& name) {
    Image image;
    std::string error = readImage(kData + name, image);
    EXPECT_EQ(error, "");
    return image;
}

std::vector<float> clamped(std::vector<float> rgb) {
    for (float& v : rgb) v = std::clamp(v, 0.0f, 1.0f);
    return rgb;
}

void expectMatchesOfficial(const FlipResult& ours, const std::string& officialMap, double officialMean) {
    Image official = load(officialMap);
    ASSERT_EQ(ours.error.size(), size_t(official.width) * official.height);
    double worst = 0, sum = 0;
    for (size_t i = 0; i < ours.error.size(); ++i) {
        worst = std::max(worst, double(std::abs(ours.error[i] - official.rgb[3 * i])));
        sum += official.rgb[3 * i];
    }
    EXPECT_NEAR(sum / double(ours.error.size()), officialMean, 1e-6) << "fixture and its recorded mean disagree";
    // Float rounding (exp, pow, summation order) is all that may differ: measured 3e-5 per pixel
    // and 1e-7 on the mean.
    EXPECT_LT(worst, 2e-4) << "largest per-pixel difference from the official map";
    EXPECT_NEAR(ours.mean, officialMean, 1e-6);
}

TEST(Flip, HdrMatchesOfficialImplementation) {
    Image test = load("test.exr"), reference = load("reference.exr");
    FlipResult flip = hdrFlip(test.rgb, reference.rgb, test.width, test.height);
    // The exposure range the official tool chose for this reference.
    EXPECT_NEAR(flip.startExposure, -2.6618457, 1e-4);
    EXPECT_NEAR(flip.stopExposure, 3.5488935, 1e-4);
    EXPECT_EQ(flip.exposures, 7);
    expectMatchesOfficial(flip, "official_hdr_error.exr", 0.033940091729164124);
}

TEST(Flip, LdrMatchesOfficialImplementation) {
    Image test = load("test.exr"), reference = load("reference.exr");
    FlipResult flip = ldrFlip(clamped(test.rgb), clamped(reference.rgb), test.width, test.height);
    expectMatchesOfficial(flip, "official_ldr_error.exr", 0.027136407792568207);
}

TEST(Flip, IdenticalImagesHaveNoError) {
    Image reference = load("reference.exr");
    for (const FlipResult& flip : {hdrFlip(reference.rgb, reference.rgb, reference.width, reference.height),
                                   ldrFlip(clamped(reference.rgb), clamped(reference.rgb), reference.width,
                                           reference.height)}) {
        EXPECT_EQ(*std::max_element(flip.error.begin(), flip.error.end()), 0.0f);
        EXPECT_EQ(flip.mean, 0.0);
    }
}

TEST(Flip, ErrorStaysInUnitRangeAndGrowsWithTheChange) {
    const int w = 32, h = 24;
    std::vector<float> black(size_t(w) * h * 3, 0.0f), white(black.size(), 1.0f), grey(black.size(), 0.5f);
    FlipResult opposite = ldrFlip(white, black, w, h);
    EXPECT_GT(opposite.mean, 0.9);
    EXPECT_LE(opposite.mean, 1.0);
    double previous = 0;
    for (float gain : {1.01f, 1.05f, 1.2f, 1.6f}) {
        std::vector<float> brighter = grey;
        for (float& v : brighter) v *= gain;
        FlipResult flip = ldrFlip(brighter, grey, w, h);
        for (float e : flip.error) ASSERT_TRUE(e >= 0.0f && e <= 1.0f) << e;
        EXPECT_GT(flip.mean, previous) << "gain " << gain;
        previous = flip.mean;
    }
    // HDR inputs far above 1, and a black reference, stay finite and in range.
    std::vector<float> bright(black.size(), 1e4f);
    for (const FlipResult& flip : {hdrFlip(bright, black, w, h), hdrFlip(black, bright, w, h)}) {
        for (float e : flip.error) ASSERT_TRUE(e >= 0.0f && e <= 1.0f) << e;
        EXPECT_GT(flip.mean, 0.5);
    }
}

} // namespace
} // namespace pt
