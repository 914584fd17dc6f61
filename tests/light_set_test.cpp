#include "light/light_set.h"
#include "light/sphere_light_sampling.h"
#include "sampling/rng.h"
#include "tests/chi_square.h"
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

Scene sceneWithLights() {
    Scene s;
    LocalLight big;
    big.center = Vec3(0, 3, 0);
    big.radius = 1.0f;
    big.intensity = Spectrum(2.0f);
    s.lights.push_back(big);
    LocalLight point;
    point.center = Vec3(1, 1, 1);
    point.intensity = Spectrum(6.0f);
    s.lights.push_back(point);
    Material lamp;
    lamp.emission = Spectrum(1.0f, 2.0f, 3.0f);
    addTriangle(s, Vec3(-1, 2, -1), Vec3(1, 2, -1), Vec3(0, 2, 1), addMaterial(s, lamp));
    Material plain;
    addTriangle(s, Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, 0, 1), addMaterial(s, plain));
    return s;
}

TEST(LightSet, EmittersChosenByPower) {
    Scene s = sceneWithLights();
    LightSet lights(s, LightChoice::Power);
    ASSERT_EQ(lights.size(), 3u); // two lab lights and the one emissive triangle
    float sphere = 4 * kPi * 2.0f, point = 4 * kPi * 6.0f, tri = 2 * kPi * 2.0f * 2.0f; // area 2, mean Le 2
    float total = sphere + point + tri;
    EXPECT_NEAR(lights.pmf(lights.emitterOfLight(0), Vec3(0), Vec3(0)), sphere / total, 1e-6f);
    EXPECT_NEAR(lights.pmf(lights.emitterOfLight(1), Vec3(0), Vec3(0)), point / total, 1e-6f);
    EXPECT_NEAR(lights.pmf(lights.emitterOfTriangle(0), Vec3(0), Vec3(0)), tri / total, 1e-6f);
    EXPECT_EQ(lights.emitterOfTriangle(1), ~0u);
}

// Cone sampling of a sphere light: directions land on the sphere, pdf() gives the density that
// sample() reported, and the directions are uniform over the cap. Uniformity is tested after
// mapping the cap's cos(theta) range onto [-1, 1], so no bin straddles the cap's rim.
TEST(LightSet, SphereSamplingMatchesPdf) {
    Scene s = sceneWithLights();
    LightSet lights(s);
    size_t e = lights.emitterOfLight(0);
    for (Vec3 p : {Vec3(0, 0, 0), Vec3(5, 3, 0), Vec3(0, 1.9f, 0), Vec3(0, 3.5f, 0.2f) /* inside */}) {
        SphereCap cap = sphereCap(p, s.lights[0].center, 1.0f);
        Frame frame(cap.axis);
        float cosMax = 1.0f - cap.oneMinusCosMax;
        bool consistent = true;
        auto r = chiSquareDirections(
            [&](Vec2 u, Vec3& mapped) {
                LightSample ls = lights.sample(e, p, u);
                if (ls.pdf <= 0) return false;
                Vec3 onSphere = p + ls.distance * ls.wi;
                if (std::abs(glm::length(onSphere - s.lights[0].center) - 1.0f) > 1e-4f) consistent = false;
                if (std::abs(lights.pdf(e, p, ls.wi, ls.distance) - ls.pdf) > 1e-4f * ls.pdf) consistent = false;
                if (std::abs(ls.pdf - sphereCapPdf(cap)) > 1e-4f * ls.pdf) consistent = false;
                Vec3 local = frame.toLocal(ls.wi);
                float z = 2.0f * (local.z - cosMax) / cap.oneMinusCosMax - 1.0f;
                float r = std::hypot(local.x, local.y), q = safeSqrt(1 - z * z) / std::max(r, 1e-30f);
                mapped = Vec3(local.x * q, local.y * q, z);
                return true;
            },
            [&](const Vec3&) { return double(uniformSpherePdf()); });
        EXPECT_TRUE(r.pass) << "p = " << p.x << "," << p.y << "," << p.z << ": " << r.report;
        EXPECT_TRUE(consistent);
    }
}

// Area sampling of a triangle, converted to solid angle: E[1 / pdf] is the triangle's solid
// angle (Van Oosterom and Strackee's formula).
TEST(LightSet, TriangleSamplingIntegratesSolidAngle) {
    Scene s = sceneWithLights();
    LightSet lights(s);
    size_t e = lights.emitterOfTriangle(0);
    Vec3 p(0.3f, 0.5f, 0.2f);
    Vec3 a = s.positions[0] - p, b = s.positions[1] - p, c = s.positions[2] - p;
    float la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    float num = std::abs(glm::dot(a, glm::cross(b, c)));
    float den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    double solidAngle = 2.0 * std::atan2(num, den);

    Pcg32 rng(5, 9);
    double sum = 0, sumSq = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        LightSample ls = lights.sample(e, p, Vec2(rng.nextFloat(), rng.nextFloat()));
        ASSERT_GT(ls.pdf, 0.0f);
        ASSERT_NEAR(lights.pdf(e, p, ls.wi, ls.distance), ls.pdf, 1e-3f * ls.pdf);
        ASSERT_NEAR(ls.point.y, 2.0f, 1e-6f);
        ASSERT_EQ(ls.radiance, Spectrum(1.0f, 2.0f, 3.0f));
        sum += 1.0 / ls.pdf;
        sumSq += 1.0 / (double(ls.pdf) * ls.pdf);
    }
    double mean = sum / n, stdErr = std::sqrt((sumSq / n - mean * mean) / n);
    EXPECT_NEAR(mean, solidAngle, 5 * stdErr + 1e-6);
}

TEST(LightSet, PointLightIsDelta) {
    Scene s = sceneWithLights();
    LightSet lights(s);
    LightSample ls = lights.sample(lights.emitterOfLight(1), Vec3(1, 1, 3), Vec2(0.5f));
    EXPECT_TRUE(ls.isDelta());
    EXPECT_FLOAT_EQ(ls.distance, 2.0f);
    EXPECT_EQ(ls.radiance, Spectrum(6.0f / 4.0f));
    EXPECT_EQ(lights.pdf(lights.emitterOfLight(1), Vec3(0), Vec3(0, 0, 1), 1.0f), 0.0f);
}

} // namespace
} // namespace pt::test
