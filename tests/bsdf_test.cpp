// The BSDF seam (material/bsdf.h, bsdf_sample.h): each model's lobe flags say what its samples
// are. Every sample's lobe is one the BSDF declares at that wo; reflection and transmission match
// the side wi leaves to; specular samples, and only they, have no density; a BSDF without
// diffuse or glossy lobes has no density anywhere. Light sampling and MIS trust these flags.
#include "material/bsdf.h"
#include "sampling/rng.h"
#include "tests/scene_builders.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

Vec3 directionAt(float cosTheta, float phi) {
    float s = safeSqrt(1.0f - cosTheta * cosTheta);
    return Vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

std::vector<std::pair<std::string, Bsdf>> bsdfsAt(const Vec3& wo) {
    std::vector<std::pair<std::string, Bsdf>> out;
    for (float alpha : {0.001f, 0.2f})
        for (auto [name, m] : labMaterials()) {
            m.roughnessAlpha = alpha;
            Bsdf b;
            b.initLab(labParameters(m, m.kd), wo.z, HemisphereSampling::Cosine);
            out.emplace_back("lab " + name + " alpha " + std::to_string(alpha), b);
            LabParameters thin = labParameters(m, m.kd);
            thin.thin = true;
            b.initLab(thin, wo.z, HemisphereSampling::Uniform);
            out.emplace_back("lab thin " + name + " alpha " + std::to_string(alpha), b);
        }
    for (float alpha : {0.0f, 0.2f})
        for (float metallic : {0.0f, 1.0f})
            for (float coat : {0.0f, 0.7f})
                for (float sheen : {0.0f, 0.5f}) {
                    MetalRoughParameters p{Spectrum(0.6f, 0.4f, 0.2f), metallic, alpha};
                    p.clearcoat = coat;
                    p.clearcoatAlpha = alpha;
                    p.sheenColor = Spectrum(sheen);
                    p.sheenRoughness = 0.5f;
                    Bsdf b;
                    b.initMetalRough(p, wo);
                    out.emplace_back("metal-rough alpha " + std::to_string(alpha) + " metallic " + std::to_string(metallic) +
                                         " coat " + std::to_string(coat) + " sheen " + std::to_string(sheen),
                                     b);
                }
    return out;
}

TEST(Bsdf, SamplesAreOfTheLobesItDeclares) {
    Pcg32 rng(7, 1);
    int samples = 0;
    for (float cosO : {0.9f, 0.4f, 0.05f, -0.6f})
        for (float phi : {0.3f, 2.1f}) {
            const Vec3 wo = directionAt(cosO, phi);
            for (const auto& [name, b] : bsdfsAt(wo)) {
                const uint8_t lobes = b.lobes();
                EXPECT_EQ(b.isBlack(), lobes == 0) << name;
                EXPECT_EQ(b.hasNonDelta(), (lobes & kLobeNonSpecular) != 0) << name;
                for (int k = 0; k < 2000; ++k) {
                    BsdfSample s;
                    if (!b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()), s)) continue;
                    ++samples;
                    const uint8_t shape = s.lobe & (kLobeDiffuse | kLobeGlossy | kLobeSpecular);
                    const uint8_t side = s.lobe & (kLobeReflection | kLobeTransmission);
                    ASSERT_TRUE(shape == kLobeDiffuse || shape == kLobeGlossy || shape == kLobeSpecular) << name;
                    ASSERT_TRUE(side == kLobeReflection || side == kLobeTransmission) << name;
                    ASSERT_EQ(s.lobe & ~lobes, 0) << name << ": sampled lobe " << int(s.lobe) << " not in " << int(lobes);
                    ASSERT_EQ(side == kLobeReflection, s.wi.z * wo.z > 0.0f) << name;
                    ASSERT_EQ(s.isDelta(), !(s.pdf > 0.0f)) << name;
                    if (!s.isDelta()) {
                        float pdf;
                        b.evalPdf(wo, s.wi, pdf);
                        ASSERT_NEAR(pdf, s.pdf, 1e-3f * s.pdf) << name;
                    }
                }
                if (!b.hasNonDelta()) { // no density anywhere: only specular lobes
                    for (int k = 0; k < 64; ++k) {
                        float pdf;
                        Vec3 wi = directionAt(2.0f * rng.nextFloat() - 1.0f, 6.28f * rng.nextFloat());
                        EXPECT_EQ(b.evalPdf(wo, wi, pdf), Spectrum(0.0f)) << name;
                        EXPECT_EQ(pdf, 0.0f) << name;
                    }
                }
            }
        }
    EXPECT_GT(samples, 100000);
}

// Albedo means one thing in both models: a surface the two can both describe has one albedo at
// every angle. A lab Fresnel blend of a mirror over Lambert (R0 0.04) is glTF's dielectric of
// ior 1.5; a lab mirror with R0 = c is glTF's metal of base colour c.
TEST(Bsdf, AlbedoMeansOneThingInBothModels) {
    const Spectrum color(0.7f, 0.4f, 0.1f);
    for (float cosO : {1.0f, 0.7f, 0.3f, 0.05f}) {
        const Vec3 wo = directionAt(cosO, 0.4f);
        Material plastic;
        plastic.kd = color;
        plastic.blend = 1.0f;
        plastic.r0 = Spectrum(0.04f);
        Material mirror;
        mirror.kd = Spectrum(0.0f);
        mirror.blend = 1.0f;
        mirror.r0 = color;
        for (auto [lab, metallic] : {std::pair{plastic, 0.0f}, std::pair{mirror, 1.0f}}) {
            Bsdf a, b;
            a.initLab(labParameters(lab, lab.kd), wo.z, HemisphereSampling::Cosine);
            b.initMetalRough(MetalRoughParameters{color, metallic, 0.0f, 1.5f}, wo);
            const Spectrum la = a.albedo(wo), gb = b.albedo(wo);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(la[c], gb[c], 1e-5f) << "metallic " << metallic << " cos " << cosO << " channel " << c;
        }
    }
}

} // namespace
} // namespace pt::test
