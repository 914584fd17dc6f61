// The microfacet pieces against their defining integrals and against each other: D is
// normalized, the visible normals integrate to one and are sampled with the density claimed,
// masking stays in [0, 1], the Fresnel terms agree at their known points.
#include "material/microfacet.h"
#include "tests/chi_square.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

constexpr float kAlphas[] = {0.01f, 0.05f, 0.2f, 0.5f, 1.0f};

// Integral over the hemisphere of f(m) dm, on a grid in theta that is dense near the pole
// (theta = pi/2 x^3), where narrow lobes live.
template <typename F>
double integrateHemisphere(F f, int nTheta = 4000, int nPhi = 256) {
    double sum = 0.0;
    for (int i = 0; i < nTheta; ++i) {
        double x0 = double(i) / nTheta, x1 = double(i + 1) / nTheta;
        double t0 = 0.5 * M_PI * x0 * x0 * x0, t1 = 0.5 * M_PI * x1 * x1 * x1;
        double theta = 0.5 * (t0 + t1);
        double ring = (std::cos(t0) - std::cos(t1)) * 2.0 * M_PI / nPhi; // solid angle of one cell
        for (int j = 0; j < nPhi; ++j) sum += f(fromAngles(theta, (j + 0.5) * 2.0 * M_PI / nPhi)) * ring;
    }
    return sum;
}

TEST(Microfacet, DistributionIsNormalized) {
    for (float alpha : kAlphas) {
        double projected = integrateHemisphere([&](const Vec3& m) { return double(ggxD(m, alpha)) * m.z; }, 20000, 4);
        EXPECT_NEAR(projected, 1.0, 2e-3) << "alpha " << alpha;
    }
}

TEST(Microfacet, VisibleNormalsIntegrateToOne) {
    for (float alpha : kAlphas)
        for (double thetaO : {0.0, 0.5, 1.0, 1.4, 1.55}) {
            Vec3 wo = fromAngles(thetaO, 0.3);
            double total = integrateHemisphere([&](const Vec3& m) { return double(visibleNormalPdf(wo, m, alpha)); });
            EXPECT_NEAR(total, 1.0, alpha < 0.05f ? 2e-2 : 3e-3) << "alpha " << alpha << " theta_o " << thetaO;
        }
}

// Samples of sampleVisibleNormal follow visibleNormalPdf (chi-square in stretched bins).
ChiSquareResult chiSquareVisibleNormals(const Vec3& wo, float alpha) {
    return chiSquareHalfVectors(
        [&](float, Vec2 u, int& side, Vec3& m) {
            side = 0;
            m = sampleVisibleNormal(wo, alpha, u);
            return true;
        },
        [&](int, const Vec3& m) { return double(visibleNormalPdf(wo, m, alpha)); }, alpha);
}

TEST(Microfacet, VisibleNormalSamplingMatchesItsPdf) {
    for (float alpha : {0.002f, 0.01f, 0.05f, 0.2f, 0.5f, 1.0f})
        for (double thetaO : {0.0, 0.7, 1.3, 1.55, 1.5608, 1.5698}) {
            ChiSquareResult r = chiSquareVisibleNormals(fromAngles(thetaO, 1.1), alpha);
            EXPECT_TRUE(r.pass) << "alpha " << alpha << " theta_o " << thetaO << ": " << r.report;
        }
}

TEST(Microfacet, MaskingIsAFraction) {
    for (float alpha : kAlphas)
        for (double t : {0.0, 0.3, 1.0, 1.5, 1.5707}) {
            Vec3 w = fromAngles(t, 0.2), n(0, 0, 1);
            float g1 = smithG1(w, n, alpha);
            EXPECT_GE(g1, 0.0f);
            EXPECT_LE(g1, 1.0f);
            if (t == 0.0) EXPECT_FLOAT_EQ(g1, 1.0f);
            Vec3 wi = fromAngles(0.8, 2.0);
            // Height correlation only ever adds visibility to the separable product.
            EXPECT_GE(smithG2HeightCorrelated(w, wi, n, alpha) + 1e-6f, smithG2Separable(w, wi, n, alpha));
        }
    EXPECT_EQ(smithG1(Vec3(0, 0, 1), glm::normalize(Vec3(1, 0, -0.1f)), 0.5f), 0.0f); // back of the facet
}

// Single-scattering reflection with white microfacets keeps at most all the energy, and close
// to all of it when smooth.
TEST(Microfacet, ReflectionAlbedoIsAtMostOne) {
    for (float alpha : kAlphas) {
        Vec3 wo = fromAngles(0.5, 0.0);
        double albedo = integrateHemisphere([&](const Vec3& wi) {
            Vec3 m = glm::normalize(wo + wi);
            return double(ggxD(m, alpha) * smithG2Separable(wo, wi, m, alpha) / (4.0f * wo.z));
        });
        EXPECT_LE(albedo, 1.0 + 3e-3) << "alpha " << alpha;
        if (alpha <= 0.05f) EXPECT_GT(albedo, 0.97) << "alpha " << alpha;
    }
}

TEST(Microfacet, FresnelKnownValues) {
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelDielectric(0.0f, 1.5f), 1.0f, 1e-6f);
    EXPECT_EQ(fresnelDielectric(0.2f, 1.0f / 1.5f), 1.0f); // beyond the critical angle
    EXPECT_NEAR(fresnelDielectric(0.8f, 1.0f), 0.0f, 1e-7f);
    for (float c : {0.1f, 0.5f, 0.9f, 1.0f}) // a conductor without absorption is a dielectric
        EXPECT_NEAR(fresnelConductor(c, 1.5f, 0.0f), fresnelDielectric(c, 1.5f), 1e-5f) << c;
    EXPECT_NEAR(fresnelConductor(1.0f, 0.2f, 3.0f), ((0.8f * 0.8f + 9.0f) / (1.2f * 1.2f + 9.0f)), 1e-5f);
}

// The Jacobians match finite differences of the mapping from m to the scattered direction.
TEST(Microfacet, JacobiansMatchFiniteDifferences) {
    Vec3 wo = glm::normalize(Vec3(0.3f, -0.2f, 0.9f));
    for (float etaRel : {1.5f, 1.0f / 1.33f}) {
        Vec3 m = glm::normalize(Vec3(0.05f, 0.1f, 1.0f));
        auto refract = [&](const Vec3& mm) {
            float c = glm::dot(wo, mm), s2 = (1 - c * c) / (etaRel * etaRel);
            return glm::normalize(-wo / etaRel + (c / etaRel - std::sqrt(1 - s2)) * mm);
        };
        auto reflect = [&](const Vec3& mm) { return 2.0f * glm::dot(wo, mm) * mm - wo; };
        for (int kind = 0; kind < 2; ++kind) {
            auto map = [&](const Vec3& mm) { return kind == 0 ? reflect(mm) : refract(mm); };
            Frame f(m);
            double h = 1e-3;
            Vec3 a = map(glm::normalize(f.toWorld(Vec3(float(h), 0, 1)))), b = map(glm::normalize(f.toWorld(Vec3(-float(h), 0, 1))));
            Vec3 c = map(glm::normalize(f.toWorld(Vec3(0, float(h), 1)))), d = map(glm::normalize(f.toWorld(Vec3(0, -float(h), 1))));
            double area = glm::length(glm::cross(a - b, c - d)) / (4.0 * h * h); // d(wi) / d(m), m area ~ (2h)^2
            Vec3 wi = map(m);
            double expected = 1.0 / (kind == 0 ? reflectionJacobian(wi, m) : refractionJacobian(wo, wi, m, etaRel));
            EXPECT_NEAR(area / expected, 1.0, 1e-2) << (kind == 0 ? "reflection" : "refraction") << " eta " << etaRel;
        }
    }
}

} // namespace
} // namespace pt::test
