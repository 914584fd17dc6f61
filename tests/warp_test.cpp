#include "sampling/distribution1d.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"
#include "tests/chi_square.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

TEST(ChiSquare, SurvivalFunctionMatchesTables) {
    EXPECT_NEAR(chiSquareSurvival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSurvival(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSurvival(124.342, 100), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSurvival(10.0, 10), 0.4405, 1e-4);
}

// The tester must be able to fail: cosine samples against a uniform pdf.
TEST(ChiSquare, RejectsAWrongPdf) {
    auto r = chiSquareDirections([](Vec2 u, Vec3& d) { d = squareToCosineHemisphere(u); return true; },
                                 [](const Vec3& d) { return d.z > 0 ? uniformHemispherePdf() : 0.0; });
    EXPECT_FALSE(r.pass) << r.report;
}

TEST(Warp, CosineHemisphere) {
    auto r = chiSquareDirections([](Vec2 u, Vec3& d) { d = squareToCosineHemisphere(u); return true; },
                                 [](const Vec3& d) { return cosineHemispherePdf(d.z); });
    EXPECT_TRUE(r.pass) << r.report;
}

TEST(Warp, UniformHemisphereAndSphere) {
    auto h = chiSquareDirections([](Vec2 u, Vec3& d) { d = squareToUniformHemisphere(u); return true; },
                                 [](const Vec3& d) { return d.z > 0 ? uniformHemispherePdf() : 0.0; });
    EXPECT_TRUE(h.pass) << h.report;
    auto s = chiSquareDirections([](Vec2 u, Vec3& d) { d = squareToUniformSphere(u); return true; },
                                 [](const Vec3&) { return uniformSpherePdf(); });
    EXPECT_TRUE(s.pass) << s.report;
}

TEST(Warp, UniformConeOfSeveralSizes) {
    for (float cosMax : {-0.5f, 0.0f, 0.5f, 0.9f}) {
        float omc = 1.0f - cosMax;
        auto r = chiSquareDirections([&](Vec2 u, Vec3& d) { d = squareToUniformCone(u, omc); return true; },
                                     [&](const Vec3& d) { return d.z >= cosMax ? uniformConePdf(omc) : 0.0; },
                                     200000, 1e-4, 20, 20);
        EXPECT_TRUE(r.pass) << "cos max " << cosMax << ": " << r.report;
    }
}

// A cone too narrow for 1 - cos(theta) in float still produces unit directions inside it.
TEST(Warp, TinyConeStaysExact) {
    float omc = 1e-12f; // half-angle about 1.4e-6 rad
    for (float a : {0.0f, 0.5f, 0.999f})
        for (float b : {0.0f, 0.3f}) {
            Vec3 d = squareToUniformCone(Vec2(a, b), omc);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
            EXPECT_LE(std::hypot(d.x, d.y), 1.5e-6f);
        }
    EXPECT_TRUE(std::isfinite(uniformConePdf(omc)));
}

TEST(Warp, UniformTriangleCoversEvenly) {
    // Bin the barycentrics (b1, b2) on a grid; each cell's expected share is its area inside the
    // triangle b1 + b2 <= 1, found by fine sub-sampling.
    const int n = 10, samples = 200000;
    std::vector<double> observed(n * n, 0.0);
    Pcg32 rng(3, 5);
    for (int i = 0; i < samples; ++i) {
        Vec2 b = squareToUniformTriangle(Vec2(rng.nextFloat(), rng.nextFloat()));
        ASSERT_GE(b.x, 0.0f);
        ASSERT_GE(b.y, 0.0f);
        ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
        observed[std::min(n - 1, int(b.x * n)) * n + std::min(n - 1, int(b.y * n))] += 1;
    }
    double chi2 = 0;
    int dof = -1;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            int inside = 0, sub = 64;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) inside += (i + (a + 0.5) / sub) + (j + (b + 0.5) / sub) <= n;
            double expected = 2.0 * samples * inside / double(sub * sub * n * n);
            if (expected < 20) continue;
            chi2 += std::pow(observed[i * n + j] - expected, 2) / expected;
            ++dof;
        }
    EXPECT_GT(chiSquareSurvival(chi2, dof), 1e-4) << "chi2 " << chi2 << " dof " << dof;
}

TEST(Distribution1D, SamplesInProportionAndNeverZeroWeights) {
    Distribution1D d({1.0, 0.0, 3.0, 0.0, 4.0});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.125f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(4), 0.5f);
    std::vector<int> counts(5, 0);
    Pcg32 rng(1, 2);
    for (int i = 0; i < 80000; ++i) {
        float pmf, u2;
        size_t k = d.sample(rng.nextFloat(), &pmf, &u2);
        ASSERT_GT(pmf, 0.0f);
        ASSERT_EQ(pmf, d.pmf(k));
        ASSERT_GE(u2, 0.0f);
        ASSERT_LT(u2, 1.0f);
        counts[k]++;
    }
    EXPECT_EQ(counts[1], 0);
    EXPECT_EQ(counts[3], 0);
    EXPECT_NEAR(counts[0], 10000, 400);
    EXPECT_NEAR(counts[2], 30000, 600);
    float pmf;
    EXPECT_EQ(d.sample(0.0f, &pmf), 0u);
    EXPECT_EQ(d.sample(0x1.fffffep-1f, &pmf), 4u);
}

TEST(Distribution1D, AllZeroFallsBackToUniform) {
    Distribution1D d({0.0, 0.0});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.5f);
    float pmf;
    EXPECT_EQ(d.sample(0.75f, &pmf), 1u);
}

TEST(Sampler, ValuesDependOnPixelSampleSeedAndDimensionOnly) {
    const float x = IndependentSampler(10, 3, 0).get1D(7);
    EXPECT_EQ(x, IndependentSampler(10, 3, 0).get1D(7));
    EXPECT_NE(x, IndependentSampler(11, 3, 0).get1D(7));
    EXPECT_NE(x, IndependentSampler(10, 4, 0).get1D(7));
    EXPECT_NE(x, IndependentSampler(10, 3, 1).get1D(7));
    EXPECT_NE(x, IndependentSampler(10, 3, 0).get1D(8));
}

} // namespace
} // namespace pt::test
