#include "light/light_set.h"
#include "light/light_tree.h"
#include "sampling/rng.h"
#include "tests/chi_square.h"
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

Vec3 randomDirection(Pcg32& rng) {
    float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * kPi * rng.nextFloat();
    float r = safeSqrt(1.0f - z * z);
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Small emissive triangles of every orientation and power scattered through a box, two sphere
// lights, a point light and a spot: every kind of leaf the tree holds.
Scene scatteredEmitters(int triangles) {
    Scene s = emptyScene(lookAt({0, 0, 6}, {0, 0, 0}, 45));
    Pcg32 rng(7, 1);
    std::vector<uint32_t> lamps;
    for (int k = 0; k < 5; ++k) {
        Material lamp;
        lamp.kd = Spectrum(0.0f);
        lamp.emission = Spectrum(0.5f + k, 1.0f, 3.0f / (k + 1));
        lamps.push_back(addMaterial(s, lamp));
    }
    for (int t = 0; t < triangles; ++t) {
        Vec3 c(4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2);
        float size = 0.02f + 0.2f * rng.nextFloat();
        addTriangle(s, c + size * randomDirection(rng), c + size * randomDirection(rng), c + size * randomDirection(rng),
                    lamps[t % lamps.size()]);
    }
    for (Vec3 c : {Vec3(1.5f, 1.5f, 1.5f), Vec3(-2, 0, 0)}) {
        LocalLight l;
        l.center = c;
        l.radius = 0.1f;
        l.intensity = Spectrum(2.0f);
        s.lights.push_back(l);
    }
    LocalLight point, spot;
    point.center = Vec3(0, 2.5f, 0);
    point.intensity = Spectrum(5.0f);
    spot.center = Vec3(0, -2.5f, 1);
    spot.intensity = Spectrum(20.0f);
    spot.spotDirection = glm::normalize(Vec3(0, 1, -1));
    spot.cosInner = std::cos(0.3f), spot.cosOuter = std::cos(0.5f);
    s.lights.push_back(point);
    s.lights.push_back(spot);
    return s;
}

// The same with distant lights beside the tree: a directional light and an environment map.
Scene scatteredEmittersUnderTheSky(int triangles) {
    Scene s = scatteredEmitters(triangles);
    DirectionalLight sun;
    sun.direction = glm::normalize(Vec3(1, 2, 0.5f));
    sun.irradiance = Spectrum(3.0f);
    s.directionalLights.push_back(sun);
    auto map = std::make_shared<EnvironmentMap>();
    map->width = 8, map->height = 4;
    map->rgb.assign(8 * 4 * 3, 0.2f);
    s.environment.map = map;
    return s;
}

// Everything that can light p: for a triangle, some point on it seen from p at a non-zero
// cosine on both ends; for spheres and points, anything (a spot: inside its outer cone).
bool canLight(const LightSet& lights, uint32_t e, const Vec3& p, const Vec3& n, Pcg32& rng) {
    const Emitter& em = lights.emitter(e);
    if (std::holds_alternative<SphereEmitter>(em)) return true;
    if (const PointEmitter* point = std::get_if<PointEmitter>(&em))
        return point->falloff(glm::normalize(point->position - p), 1.0f) > 0.0f;
    for (int k = 0; k < 64; ++k) {
        LightSample ls = lights.sample(e, p, Vec2(rng.nextFloat(), rng.nextFloat()));
        if (ls.pdf > 0.0f && std::abs(glm::dot(ls.wi, n)) > 1e-3f) return true;
    }
    return false;
}

// Over every emitter, the tree's probabilities at a point sum to one, and no emitter that can
// light the point has probability 0 (that would be light lost: bias, not noise).
TEST(LightTree, PmfSumsToOneAndMissesNoEmitter) {
  for (bool sky : {false, true}) {
    Scene s = sky ? scatteredEmittersUnderTheSky(300) : scatteredEmitters(300);
    LightSet lights(s, LightChoice::Tree);
    ASSERT_TRUE(lights.usesTree());
    Pcg32 rng(3, 1);
    int zeroButLit = 0, points = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Vec3 p(6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3);
        Vec3 n = trial % 4 == 0 ? Vec3(0.0f) : randomDirection(rng);
        double sum = 0.0;
        for (uint32_t e = 0; e < lights.size(); ++e) {
            float pmf = lights.pmf(e, p, n);
            sum += pmf;
            if (pmf == 0.0f && canLight(lights, e, p, n, rng)) ++zeroButLit;
        }
        EXPECT_NEAR(sum, 1.0, 1e-4) << "at p = " << p.x << ", " << p.y << ", " << p.z;
        ++points;
    }
    EXPECT_EQ(zeroButLit, 0) << "emitters that can light a point but that the tree never picks there";
  }
}

// What choose() draws follows pmf(), and each draw reports the pmf() of what it drew.
TEST(LightTree, ChoicesFollowPmf) {
    Scene s = scatteredEmittersUnderTheSky(60);
    LightSet lights(s, LightChoice::Tree);
    Pcg32 rng(11, 1);
    for (int trial = 0; trial < 4; ++trial) {
        Vec3 p(4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2, 4 * rng.nextFloat() - 2);
        Vec3 n = randomDirection(rng);
        const int samples = 200000;
        std::vector<double> observed(lights.size() + 1, 0.0), expected(lights.size() + 1, 0.0);
        int mismatched = 0;
        for (int i = 0; i < samples; ++i) {
            float pmf;
            uint32_t e = lights.choose((i + rng.nextFloat()) / samples, p, n, pmf);
            if (e == ~0u) {
                observed.back() += 1;
                continue;
            }
            observed[e] += 1;
            if (std::abs(pmf - lights.pmf(e, p, n)) > 1e-5f * pmf) ++mismatched;
        }
        for (uint32_t e = 0; e < lights.size(); ++e) expected[e] = samples * double(lights.pmf(e, p, n));
        ChiSquareResult r = chiSquareOfCounts(observed, expected, 1.0, samples, 1e-4);
        EXPECT_TRUE(r.pass) << r.report;
        EXPECT_EQ(mismatched, 0);
    }
}

// The tree prefers what is near and faces the point: of two equal panels, one a metre above a
// point and facing it, one ten metres away, the near one gets nearly all the choices; and a
// one-sided spot behind the point's cone is never chosen.
TEST(LightTree, PrefersNearFacingEmitters) {
    std::vector<LightBounds> b(3);
    for (LightBounds& x : b) x.phi = 1.0f, x.cosThetaO = 1.0f, x.twoSided = true, x.axis = Vec3(0, 1, 0);
    b[0].lo = Vec3(-0.1f, 1, -0.1f), b[0].hi = Vec3(0.1f, 1, 0.1f);
    b[1].lo = Vec3(9.9f, 1, -0.1f), b[1].hi = Vec3(10.1f, 1, 0.1f);
    b[2].lo = b[2].hi = Vec3(0, 1, 0.5f); // a spot pointing up, away from the point below it
    b[2].twoSided = false, b[2].cosThetaE = std::cos(0.4f);
    LightTree tree(b);
    Vec3 p(0, 0, 0), n(0, 1, 0);
    float near = tree.pmf(p, n, 0), far = tree.pmf(p, n, 1);
    EXPECT_GT(near, 0.99f);
    EXPECT_GT(far, 0.0f); // it does light the point, a little
    EXPECT_EQ(tree.pmf(p, n, 2), 0.0f);
    EXPECT_NEAR(near + far, 1.0f, 1e-6f);
    // A point above the spot, inside its cone, sees it.
    EXPECT_GT(tree.pmf(Vec3(0, 3, 0.5f), Vec3(0.0f), 2), 0.0f);
}

// A point that nothing can light: every emitter faces away or is cut off; no emitter is drawn.
TEST(LightTree, NothingToChoose) {
    std::vector<LightBounds> b(2);
    for (LightBounds& x : b) {
        x.phi = 1.0f, x.cosThetaO = 1.0f, x.axis = Vec3(0, 1, 0), x.cosThetaE = std::cos(0.2f);
        x.twoSided = false;
    }
    b[0].lo = b[0].hi = Vec3(0, 1, 0);
    b[1].lo = b[1].hi = Vec3(1, 1, 0);
    LightTree tree(b);
    float pmf = 1.0f;
    EXPECT_EQ(tree.sample(Vec3(0.5f, 0, 0), Vec3(0.0f), 0.3f, pmf), ~0u);
    EXPECT_EQ(pmf, 0.0f);
    EXPECT_EQ(tree.pmf(Vec3(0.5f, 0, 0), Vec3(0.0f), 0), 0.0f);
}

// The same room lit by 400 small panels of every orientation: light sampling through the tree,
// BSDF sampling and MIS give one image; and choosing by power gives it too.
TEST(LightTree, ImagesAgreeWithBsdfSamplingAndPowerChoice) {
    Scene s = emptyScene(lookAt({0, 0.2f, 3.2f}, {0, 0, 0}, 50));
    Material wall, glossy;
    wall.kd = Spectrum(0.6f);
    glossy.kd = Spectrum(0.2f, 0.3f, 0.5f);
    glossy.ks = Spectrum(1.0f);
    glossy.r0 = Spectrum(0.05f);
    glossy.blend = 1.0f;
    glossy.roughnessAlpha = 0.2f;
    uint32_t w = addMaterial(s, wall), g = addMaterial(s, glossy);
    addQuad(s, Vec3(-1, -1, 1), Vec3(1, -1, 1), Vec3(1, -1, -1), Vec3(-1, -1, -1), g);
    addQuad(s, Vec3(-1, -1, -1), Vec3(1, -1, -1), Vec3(1, 1, -1), Vec3(-1, 1, -1), w);
    addQuad(s, Vec3(-1, -1, 1), Vec3(-1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, 1, 1), w);
    Pcg32 rng(5, 1);
    std::vector<uint32_t> lamps;
    for (int k = 0; k < 3; ++k) {
        Material lamp;
        lamp.kd = Spectrum(0.0f);
        lamp.emission = Spectrum(k == 0 ? 8.0f : 1.0f, k == 1 ? 8.0f : 1.0f, k == 2 ? 8.0f : 1.0f);
        lamps.push_back(addMaterial(s, lamp));
    }
    for (int i = 0; i < 200; ++i) {
        Vec3 c(1.8f * rng.nextFloat() - 0.9f, 1.8f * rng.nextFloat() - 0.9f, 1.8f * rng.nextFloat() - 1.0f);
        Vec3 a = 0.06f * randomDirection(rng), b = 0.06f * randomDirection(rng);
        addQuad(s, c - a - b, c + a - b, c + a + b, c - a + b, lamps[i % 3]);
    }
    expectStrategiesAgree(s); // the default, Auto, takes the tree here

    RenderSettings tree, power;
    tree.lightChoice = LightChoice::Tree, power.lightChoice = LightChoice::Power;
    tree.seed = 3, power.seed = 4;
    tree.lightSampling = power.lightSampling = LightSampling::Nee;
    // Point lights and a spot, which only light sampling finds, through both choices.
    LocalLight point, spot;
    point.center = Vec3(0.5f, 0.8f, 0.3f), point.intensity = Spectrum(0.5f);
    spot.center = Vec3(-0.5f, 0.9f, 0.0f), spot.intensity = Spectrum(4.0f);
    spot.spotDirection = Vec3(0, -1, 0), spot.cosInner = 0.95f, spot.cosOuter = 0.85f;
    s.lights = {point, spot};
    DirectionalLight sun; // a distant light beside them: the choice between it and the tree
    sun.direction = glm::normalize(Vec3(0.3f, 1.0f, 0.6f));
    sun.irradiance = Spectrum(0.8f, 0.7f, 0.5f);
    s.directionalLights.push_back(sun);
    expectSameImage(render(s, 32, 24, 1024, tree), render(s, 32, 24, 4096, power), "tree against power");
}

} // namespace
} // namespace pt::test
