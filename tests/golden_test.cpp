// Golden-image regression: each case of golden/manifest.txt is rendered at a low sample count and
// compared statistically with its committed reference (renderer/image/compare.h).
#include "accel/accel.h"
#include "image/compare.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pt {
namespace {

struct GoldenCase {
    std::string name, scene, camera, resolution;
    uint32_t referenceSpp = 0, testSpp = 0;
    std::string extra;
};

std::vector<GoldenCase> readManifest() {
    std::vector<GoldenCase> cases;
    std::ifstream in(PT_SOURCE_DIR "/golden/manifest.txt");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        GoldenCase c;
        s >> c.name >> c.scene >> c.camera >> c.resolution >> c.referenceSpp >> c.testSpp;
        std::getline(s, c.extra);
        cases.push_back(c);
    }
    return cases;
}

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesReferenceStatistically) {
    const GoldenCase& c = GetParam();
    ASSERT_TRUE(c.extra.find_first_not_of(" \t") == std::string::npos)
        << "extra options in the manifest are not supported by this driver yet: " << c.extra;
    std::string scenePath = std::string(PT_SOURCE_DIR) + "/" + c.scene;
    if (!std::filesystem::exists(scenePath)) GTEST_SKIP() << "scene " << c.scene << " not found; case skipped";

    Warnings warnings;
    Scene scene = loadScene(scenePath, warnings);
    int width = 0, height = 0;
    ASSERT_EQ(std::sscanf(c.resolution.c_str(), "%dx%d", &width, &height), 2);
    size_t camera = size_t(std::stoul(c.camera));
    ASSERT_LT(camera, scene.cameras.size());

    Image reference;
    std::string refPath = std::string(PT_SOURCE_DIR) + "/golden/" + c.name + ".exr";
    ASSERT_EQ(readImage(refPath, reference), "") << "run golden/update " << c.name;

    Accel accel(scene, 0);
    RenderSettings settings;
    settings.seed = 1; // references use seed 1000: independent noise
    if (const char* seed = std::getenv("PT_GOLDEN_SEED")) settings.seed = std::stoull(seed); // to probe flakiness
    RenderResult result = renderImage(scene, accel, scene.cameras[camera], width, height, c.testSpp, 0, settings);
    Image test;
    test.width = width;
    test.height = height;
    test.rgb = result.film.mean();
    test.layers.push_back({"variance", {"R", "G", "B"}, result.film.varianceOfMean()});

    CompareOptions options;
    options.testSpp = c.testSpp;
    options.referenceSpp = c.referenceSpp;
    CompareReport report = compareImages(test, reference, options);
    ASSERT_EQ(report.inputError, "");
    std::ostringstream worst;
    for (const BlockDifference& d : report.worst)
        worst << "\n  block [" << d.x0 << "," << d.x1 << ")x[" << d.y0 << "," << d.y1 << ") channel " << d.channel
              << ": test " << d.test << " reference " << d.reference << " z " << d.z;
    EXPECT_TRUE(report.pass) << c.name << ": " << report.failedBlocks << " of " << report.blocks
                             << " blocks differ beyond |z| > " << report.zThreshold << ", relMSE " << report.relativeMse
                             << worst.str();
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(readManifest()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) { return info.param.name; });

} // namespace
} // namespace pt
