// glTF's metallic-roughness BRDF: against the specification's formulas written out here in their
// own form, sampling against the density it reports (chi-square), eval / pdf as the weight,
// reciprocity, the delta mirror, and a white furnace that reports the energy kept.
#include "material/metal_rough_bsdf.h"
#include "sampling/rng.h"
#include "tests/chi_square.h"
#include "tests/gltf_brdf_reference.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace pt::test {
namespace {

Vec3 direction(float cosTheta, float phi) {
    float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return Vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

TEST(MetalRoughBsdf, MatchesTheSpecification) {
    const Spectrum base(0.8f, 0.5f, 0.2f);
    for (float metallic : {0.0f, 0.3f, 1.0f})
        for (float roughness : {0.1f, 0.4f, 0.8f, 1.0f})
            for (auto [co, ci, dphi] : {std::tuple{0.9f, 0.8f, 3.0f}, {0.5f, 0.3f, 2.5f}, {0.2f, 0.9f, 1.0f}, {0.05f, 0.6f, 3.1f}}) {
                Vec3 wo = direction(co, 0.2f), wi = direction(ci, 0.2f + dphi);
                MetalRoughBsdf b = MetalRoughBsdf::make(base, metallic, roughness * roughness, 1.5f, wo.z);
                Spectrum got = b.eval(wo, wi) / wi.z, want = specBrdf(base, metallic, roughness, wo, wi);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 2e-4f * want[c] + 1e-7f)
                        << "metallic " << metallic << " roughness " << roughness << " cos " << co << "/" << ci << " channel " << c;
            }
}

// KHR_materials_specular: its weight and colour against the extension's formula; weight 0 is
// Lambert exactly (what lets a glTF file say what an OBJ's Kd says); and sampling still follows
// the density.
TEST(MetalRoughBsdf, SpecularExtension) {
    const Spectrum base(0.8f, 0.5f, 0.2f), color(2.0f, 1.0f, 0.3f);
    for (float s : {0.0f, 0.5f, 1.0f})
        for (float metallic : {0.0f, 0.4f})
            for (auto [co, ci, dphi] : {std::tuple{0.9f, 0.8f, 3.0f}, {0.2f, 0.9f, 1.0f}, {0.05f, 0.6f, 3.1f}}) {
                Vec3 wo = direction(co, 0.2f), wi = direction(ci, 0.2f + dphi);
                MetalRoughBsdf b = MetalRoughBsdf::make(base, metallic, 0.3f * 0.3f, 1.5f, wo.z, color, s);
                Spectrum got = b.eval(wo, wi) / wi.z, want = specBrdf(base, metallic, 0.3f, wo, wi, s, color);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 2e-4f * want[c] + 1e-7f) << "s " << s << " metallic " << metallic << " channel " << c;
            }
    MetalRoughBsdf lambert = MetalRoughBsdf::make(base, 0.0f, 0.25f, 1.5f, 0.7f, Spectrum(1.0f), 0.0f);
    Vec3 wo = direction(0.7f, 0.0f);
    for (float ci : {1.0f, 0.5f, 0.1f}) {
        Vec3 wi = direction(ci, 2.0f);
        float pdf;
        Spectrum f = lambert.evalPdf(wo, wi, pdf);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], base[c] * kInvPi * ci, 1e-6f);
        EXPECT_NEAR(pdf, ci * kInvPi, 1e-6f); // all of it cosine-sampled
    }
    Vec3 wo2 = direction(0.4f, 0.4f);
    MetalRoughBsdf b = MetalRoughBsdf::make(base, 0.2f, 0.5f, 1.5f, wo2.z, color, 0.5f);
    Pcg32 rng(3, 9);
    auto r = chiSquareDirections(
        [&](Vec2 u, Vec3& wi) {
            BsdfSample s;
            if (!b.sample(wo2, rng.nextFloat(), u, s)) return false;
            wi = s.wi;
            return true;
        },
        [&](const Vec3& wi) {
            float pdf;
            b.evalPdf(wo2, wi, pdf);
            return double(pdf);
        },
        100000);
    EXPECT_TRUE(r.pass) << r.report;
}

TEST(MetalRoughBsdf, IsReciprocal) {
    MetalRoughBsdf a = MetalRoughBsdf::make(Spectrum(0.7f, 0.4f, 0.9f), 0.4f, 0.09f, 1.5f, 0.6f);
    Pcg32 rng(5, 1);
    for (int k = 0; k < 200; ++k) {
        Vec3 u = direction(0.05f + 0.95f * rng.nextFloat(), 6.28f * rng.nextFloat());
        Vec3 v = direction(0.05f + 0.95f * rng.nextFloat(), 6.28f * rng.nextFloat());
        Spectrum fuv = a.eval(u, v) / v.z, fvu = a.eval(v, u) / u.z;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(fuv[c], fvu[c], 1e-4f * fuv[c] + 1e-7f);
    }
}

// Broad lobes on the sphere of directions; narrow ones in half-vector space (metal only, where
// the whole BRDF is the specular lobe). Every sample's weight must be eval / pdf.
TEST(MetalRoughBsdf, SamplingMatchesPdf) {
    const Spectrum base(0.9f, 0.6f, 0.3f);
    for (float metallic : {0.0f, 0.5f, 1.0f})
        for (float roughness : {0.45f, 0.7f, 1.0f})
            for (float cosO : {1.0f, 0.6f, 0.2f, 0.03f}) {
                Vec3 wo = direction(cosO, 0.4f);
                MetalRoughBsdf b = MetalRoughBsdf::make(base, metallic, roughness * roughness, 1.5f, wo.z);
                Pcg32 rng(3, 7);
                bool weightsOk = true;
                auto r = chiSquareDirections(
                    [&](Vec2 u, Vec3& wi) {
                        BsdfSample s;
                        if (!b.sample(wo, rng.nextFloat(), u, s)) return false;
                        float pdf;
                        Spectrum f = b.evalPdf(wo, s.wi, pdf);
                        if (std::abs(pdf - s.pdf) > 1e-4f * pdf || glm::length(s.weight - f / pdf) > 1e-4f * glm::length(s.weight))
                            weightsOk = false;
                        wi = s.wi;
                        return true;
                    },
                    [&](const Vec3& wi) {
                        float pdf;
                        b.evalPdf(wo, wi, pdf);
                        return double(pdf);
                    },
                    100000);
                EXPECT_TRUE(r.pass) << "metallic " << metallic << " roughness " << roughness << " cos " << cosO << ": " << r.report;
                EXPECT_TRUE(weightsOk) << "metallic " << metallic << " roughness " << roughness << " cos " << cosO;
            }
    for (float alpha : {0.002f, 0.01f, 0.05f, 0.2f})
        for (float cosO : {1.0f, 0.5f, 0.1f}) {
            Vec3 wo = direction(cosO, 0.4f);
            MetalRoughBsdf b = MetalRoughBsdf::make(base, 1.0f, alpha, 1.5f, wo.z);
            auto r = chiSquareHalfVectors(
                [&](float u1, Vec2 u2, int& side, Vec3& half) {
                    BsdfSample s;
                    if (!b.sample(wo, u1, u2, s)) return false;
                    side = 0;
                    half = glm::normalize(wo + s.wi);
                    return true;
                },
                [&](int, const Vec3& half) {
                    if (glm::dot(wo, half) <= 0.0f) return 0.0;
                    Vec3 wi = 2.0f * glm::dot(wo, half) * half - wo;
                    if (wi.z <= 0.0f) return 0.0;
                    float pdf;
                    b.evalPdf(wo, wi, pdf);
                    return double(pdf) / reflectionJacobian(wi, half);
                },
                alpha, 1, 200000);
            EXPECT_TRUE(r.pass) << "alpha " << alpha << " cos " << cosO << ": " << r.report;
        }
}

TEST(MetalRoughBsdf, SmoothMetalIsAFresnelMirror) {
    const Spectrum base(0.9f, 0.6f, 0.3f);
    Vec3 wo = direction(0.5f, 1.0f);
    MetalRoughBsdf b = MetalRoughBsdf::make(base, 1.0f, 0.0f, 1.5f, wo.z);
    EXPECT_FALSE(b.hasNonDelta());
    BsdfSample s;
    ASSERT_TRUE(b.sample(wo, 0.5f, Vec2(0.3f, 0.7f), s));
    EXPECT_TRUE(s.delta);
    EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);
    EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
    float w = std::pow(0.5f, 5.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], base[c] + (1.0f - base[c]) * w, 1e-5f);
    EXPECT_TRUE(isBlack(b.eval(wo, Vec3(0, 0, 1))));
}

// White furnace: a white base colour, metal and dielectric, roughness 0 to 1. The table is
// printed (the README has it). Metals lose energy at high roughness (single scattering) and may
// never exceed 1. The dielectric is the specification's fresnel_mix, which Appendix B calls an
// approximation: the diffuse base is weighted by 1 - F at the half vector, not by what the
// specular layer really reflects, so at grazing incidence a white base returns more than
// arrives (1.55 at cos 0.1 when smooth). pt follows the specification; the bound checked is
// that it stays below 1.6.
TEST(MetalRoughBsdf, FurnaceTable) {
    std::printf("energy kept, white base    cos 1    cos 0.5  cos 0.1\n");
    for (float metallic : {1.0f, 0.0f})
        for (float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            std::printf("  metallic %g roughness %-4g", metallic, roughness);
            for (float cosO : {1.0f, 0.5f, 0.1f}) {
                Vec3 wo = direction(cosO, 0.0f);
                MetalRoughBsdf b = MetalRoughBsdf::make(Spectrum(1.0f), metallic, roughness * roughness, 1.5f, wo.z);
                Pcg32 rng(9, 2);
                const int n = 100000;
                double sum = 0.0, sum2 = 0.0;
                for (int k = 0; k < n; ++k) {
                    BsdfSample s;
                    double e = b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()), s) ? s.weight.x : 0.0;
                    sum += e;
                    sum2 += e * e;
                }
                double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
                std::printf(" %7.4f", mean);
                EXPECT_LE(mean, (metallic == 1.0f ? 1.0 : 1.6) + 4.0 * se + 1e-6)
                    << "metallic " << metallic << " roughness " << roughness << " cos " << cosO;
                if (roughness == 0.0f && metallic == 1.0f) EXPECT_NEAR(mean, 1.0, 1e-6);
            }
            std::printf("\n");
        }
}

} // namespace
} // namespace pt::test
