#include "material/lab_bsdf.h"
#include "sampling/rng.h"
#include "tests/chi_square.h"
#include "tests/scene_builders.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

// The same materials with rough Spec and Refr lobes.
std::vector<std::pair<std::string, Material>> roughMaterials(const std::vector<float>& alphas) {
    std::vector<std::pair<std::string, Material>> out;
    for (float alpha : alphas)
        for (auto [name, m] : labMaterials()) {
            if (name == "lambert") continue;
            m.roughnessAlpha = alpha;
            out.emplace_back(name + " alpha " + std::to_string(alpha), m);
        }
    return out;
}

Vec3 directionAt(float cosTheta, float phi = 0.3f) {
    float s = safeSqrt(1.0f - cosTheta * cosTheta);
    return Vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

TEST(Fresnel, SchlickEndpoints) {
    EXPECT_FLOAT_EQ(schlickFresnel(Spectrum(0.04f), 1.0f).x, 0.04f);
    EXPECT_FLOAT_EQ(schlickFresnel(Spectrum(0.04f), 0.0f).x, 1.0f);
    EXPECT_FLOAT_EQ(schlickFresnel(Spectrum(0.04f), -1.0f).x, 0.04f); // |cos|
    EXPECT_NEAR(schlickFresnel(Spectrum(0.1f), 0.5f).x, 0.1f + 0.9f * std::pow(0.5f, 5.0f), 1e-7f);
}

// Lobe weights of the collapsed tree, computed by hand from the lab's formula.
TEST(LabBsdf, LobeWeightsFollowTheTree) {
    Material m;
    m.kd = Spectrum(0.5f);
    m.ks = Spectrum(0.8f);
    m.r0 = Spectrum(0.1f);
    m.blend = 0.6f;
    m.transparency = 0.25f;
    float cosO = 0.7f;
    float F = 0.1f + 0.9f * std::pow(0.3f, 5.0f);
    LabBsdf b = LabBsdf::make(m, m.kd, cosO);
    EXPECT_NEAR(b.mirror.x, 0.6f * F * 0.8f, 1e-6f);
    EXPECT_NEAR(b.refract.x, (1.0f - 0.6f * F) * 0.25f, 1e-6f);
    EXPECT_NEAR(b.diffuse.x, (1.0f - 0.6f * F) * 0.75f * 0.5f, 1e-6f);
    EXPECT_NEAR(b.pMirror + b.pRefract + b.pDiffuse, 1.0f, 1e-6f);
}

TEST(LabBsdf, RefractionFollowsSnell) {
    for (float eta : {1.33f, 1.5f, 2.4f})
        for (float cosI : {1.0f, 0.8f, 0.3f, 0.05f}) {
            Vec3 wo = directionAt(cosI);
            Vec3 wt;
            ASSERT_TRUE(refractDirection(wo, eta, wt));
            EXPECT_NEAR(glm::length(wt), 1.0f, 1e-5f);
            EXPECT_LT(wt.z, 0.0f);
            float sinI = safeSqrt(1 - cosI * cosI), sinT = safeSqrt(1 - wt.z * wt.z);
            EXPECT_NEAR(sinI, eta * sinT, 1e-5f);
            // Reversibility: the path coming back out along wt leaves along wo.
            Vec3 back;
            ASSERT_TRUE(refractDirection(wt, 1.0f / eta, back));
            EXPECT_NEAR(glm::length(back - wo), 0.0f, 1e-4f);
        }
    Vec3 wt;
    EXPECT_FALSE(refractDirection(Vec3(directionAt(-0.2f)), 1.0f / 1.5f, wt)); // beyond the critical angle
}

// Delta lobes: the mirror reflects, refraction carries the (eta_o / eta_i)^2 radiance scaling and
// total internal reflection has reflectance 1.
TEST(LabBsdf, DeltaLobeWeights) {
    Material glass = labMaterials()[2].second;
    LabBsdf outside = LabBsdf::make(glass, glass.kd, 0.8f);
    BsdfSample s;
    Vec3 wo = directionAt(0.8f);
    ASSERT_TRUE(outside.sample(wo, 0.99f, Vec2(0.5f), s)); // refraction (mirror prob is small)
    EXPECT_TRUE(s.isDelta());
    EXPECT_LT(s.wi.z, 0.0f);
    float F = 0.04f + 0.96f * std::pow(0.2f, 5.0f);
    EXPECT_NEAR(s.weight.x * outside.pRefract, (1 - F) / (1.5f * 1.5f), 1e-5f);
    ASSERT_TRUE(outside.sample(wo, 0.0f, Vec2(0.5f), s)); // mirror
    EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
    EXPECT_NEAR(s.weight.x * outside.pMirror, F, 1e-5f);

    Vec3 inside = directionAt(-0.2f); // from inside, beyond the critical angle of 1.5
    LabBsdf in = LabBsdf::make(glass, glass.kd, inside.z);
    ASSERT_TRUE(in.sample(inside, 0.999f, Vec2(0.5f), s));
    EXPECT_NEAR(s.wi.z, inside.z, 1e-6f); // reflected, staying inside
    EXPECT_NEAR(s.weight.x * in.pRefract, in.refract.x, 1e-5f);
}

// sample() and pdf() agree (chi-square) and sample()'s weight equals eval / pdf, for every
// material over incident angles down to grazing, from both sides.
TEST(LabBsdf, SamplingMatchesPdfAndEval) {
    auto materials = labMaterials();
    for (auto& [name, m] : roughMaterials({0.5f, 1.0f})) // narrower lobes: RoughLobesSampleTheirPdf
        if (name.rfind("plastic", 0) == 0 || name.rfind("mixed", 0) == 0) materials.emplace_back(name, m);
    for (const auto& [name, m] : materials)
        for (float cosO : {1.0f, 0.7f, 0.2f, 0.01f, 0.001f, -0.05f, -0.5f, -0.99f})
            for (HemisphereSampling h : {HemisphereSampling::Cosine, HemisphereSampling::Uniform}) {
                // At cos 0.001 the rough lobes' bins on the sphere are too coarse to integrate.
                if (m.roughnessAlpha > kSmoothAlpha && std::abs(cosO) < 0.01f) continue;
                Vec3 wo = directionAt(cosO);
                LabBsdf b = LabBsdf::make(m, m.kd, wo.z, h);
                Pcg32 rng(7, 11);
                bool weightsOk = true;
                auto r = chiSquareDirections(
                    [&](Vec2 u, Vec3& wi) {
                        BsdfSample s;
                        if (!b.sample(wo, rng.nextFloat(), u, s) || s.isDelta()) return false;
                        float pdf = b.pdf(wo, s.wi);
                        Spectrum f = b.eval(wo, s.wi);
                        if (std::abs(pdf - s.pdf) > 1e-4f * pdf || glm::length(s.weight - f / pdf) > 1e-4f * glm::length(s.weight))
                            weightsOk = false;
                        wi = s.wi;
                        return true;
                    },
                    [&](const Vec3& wi) { return double(b.pdf(wo, wi)); }, 100000);
                EXPECT_TRUE(r.pass) << name << " cos " << cosO << ": " << r.report;
                EXPECT_TRUE(weightsOk) << name << " cos " << cosO;
            }
}

// The rough lobes, from alpha 0.002 to 1 and from normal incidence down to grazing, outside and
// inside glass (with totally internally reflecting microfacets): sample() follows pdf() (a
// chi-square test on the half vectors, one set of bins for reflection and one for transmission)
// and its weight is eval() / pdf().
TEST(LabBsdf, RoughLobesSampleTheirPdf) {
    for (float alpha : {0.002f, 0.01f, 0.05f, 0.2f, 0.5f, 1.0f})
        for (const auto& [name, m] : roughMaterials({alpha}))
            for (float cosO : {1.0f, 0.7f, 0.3f, 0.1f, 0.01f, -0.3f, -0.9f}) {
                // With a Lambert lobe beside them (plastic, mixed) the stretched bins cannot hold the
                // broad part: those are SamplingMatchesPdfAndEval's, on the sphere, at alpha >= 0.2.
                if (name.rfind("plastic", 0) == 0 || name.rfind("mixed", 0) == 0) continue;
                Vec3 wo = directionAt(cosO);
                LabBsdf b = LabBsdf::make(m, m.kd, wo.z);
                float sign = wo.z > 0.0f ? 1.0f : -1.0f, etaRel = wo.z > 0.0f ? b.eta : 1.0f / b.eta;
                Vec3 o = wo * sign;
                bool weightsOk = true;
                std::string firstBad;
                auto r = chiSquareHalfVectors(
                    [&](float u1, Vec2 u2, int& side, Vec3& half) {
                        BsdfSample s;
                        if (!b.sample(wo, u1, u2, s)) return false;
                        EXPECT_FALSE(s.isDelta()) << name;
                        float pdf = b.pdf(wo, s.wi);
                        Spectrum f = b.eval(wo, s.wi);
                        if (!(std::abs(pdf - s.pdf) <= 1e-4f * pdf) ||
                            !(glm::length(s.weight - f / pdf) <= 1e-3f * glm::length(s.weight))) {
                            if (weightsOk) firstBad = "pdf " + std::to_string(pdf) + " vs " + std::to_string(s.pdf);
                            weightsOk = false;
                        }
                        Vec3 i = s.wi * sign;
                        side = i.z > 0.0f ? 0 : 1;
                        half = side == 0 ? glm::normalize(o + i) : glm::normalize(-(o + etaRel * i));
                        if (half.z < 0.0f) half = -half;
                        return true;
                    },
                    [&](int side, const Vec3& half) {
                        if (glm::dot(o, half) <= 0.0f) return 0.0;
                        if (side == 0) {
                            Vec3 i = 2.0f * glm::dot(o, half) * half - o;
                            return i.z > 0.0f ? double(b.pdf(wo, i * sign)) / reflectionJacobian(i, half) : 0.0;
                        }
                        float c = glm::dot(o, half), sin2T = (1.0f - c * c) / (etaRel * etaRel);
                        if (sin2T >= 1.0f) return 0.0;
                        Vec3 i = (c / etaRel - std::sqrt(1.0f - sin2T)) * half - o / etaRel;
                        return i.z < 0.0f ? double(b.pdf(wo, i * sign)) / refractionJacobian(o, i, half, etaRel) : 0.0;
                    },
                    alpha, 2, 200000);
                EXPECT_TRUE(r.pass) << name << " cos " << cosO << ": " << r.report;
                EXPECT_TRUE(weightsOk) << name << " cos " << cosO << ": " << firstBad;
            }
}

// The tree's delta lobes are chosen as often as their probabilities say: a chi-square test on
// which lobe sample() took (mirror, refraction or Lambert), for every material and angle. From
// inside at -0.9 no direction is beyond the critical angle, so a same-side delta is the mirror.
TEST(LabBsdf, LobeChoiceMatchesProbabilities) {
    for (const auto& [name, m] : labMaterials())
        for (float cosO : {1.0f, 0.5f, 0.05f, 0.001f, -0.9f}) {
            Vec3 wo = directionAt(cosO);
            LabBsdf b = LabBsdf::make(m, m.kd, wo.z);
            const int n = 200000;
            double counts[3] = {0, 0, 0};
            Pcg32 rng(5, 9);
            for (int i = 0; i < n; ++i) {
                BsdfSample s;
                ASSERT_TRUE(b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()), s)) << name;
                int lobe = !s.isDelta() ? 2 : s.wi.z * wo.z < 0.0f ? 1 : 0;
                counts[lobe] += 1;
            }
            double expected[3] = {b.pMirror * double(n), b.pRefract * double(n), b.pDiffuse * double(n)};
            double chi2 = 0;
            int dof = -1;
            for (int k = 0; k < 3; ++k) {
                if (expected[k] == 0.0) {
                    EXPECT_EQ(counts[k], 0.0) << name << " cos " << cosO << ": lobe " << k << " has probability 0";
                    continue;
                }
                chi2 += (counts[k] - expected[k]) * (counts[k] - expected[k]) / expected[k];
                ++dof;
            }
            if (dof > 0) EXPECT_GT(chiSquareSurvival(chi2, dof), 1e-4) << name << " cos " << cosO << ": chi2 " << chi2;
        }
}

// White furnace per material: the expected sample weight (the albedo) never exceeds 1, and a
// Lambert surface of albedo 1 reflects exactly 1 with cosine sampling.
TEST(LabBsdf, AlbedoNeverAboveOne) {
    for (auto [name, m] : labMaterials()) {
        m.kd = Spectrum(1.0f);
        m.ks = Spectrum(1.0f);
        for (float cosO : {1.0f, 0.5f, 0.1f, 0.001f, -0.3f, -0.9f}) {
            Vec3 wo = directionAt(cosO);
            LabBsdf b = LabBsdf::make(m, m.kd, wo.z);
            Pcg32 rng(1, 3);
            glm::dvec3 sum(0.0), sumSq(0.0);
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                BsdfSample s;
                if (!b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()), s)) continue;
                ASSERT_TRUE(isFinite(s.weight)) << name;
                ASSERT_GE(std::min(s.weight.x, std::min(s.weight.y, s.weight.z)), 0.0f) << name;
                // Radiance scaling is not energy: take it out before summing.
                glm::dvec3 w(s.weight / s.radianceScale);
                sum += w;
                sumSq += w * w;
            }
            glm::dvec3 albedo = sum / double(n);
            glm::dvec3 stdErr = glm::sqrt(glm::max(sumSq / double(n) - albedo * albedo, 0.0) / double(n));
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(albedo[c], 1.0 + 5.0 * stdErr[c] + 1e-6) << name << " cos " << cosO << " channel " << c;
            if (name == "lambert") EXPECT_NEAR(albedo.x, 1.0, 1e-6) << "cos " << cosO;
            if (name == "glass") EXPECT_NEAR(albedo.x, 1.0, 1e-6) << "cos " << cosO; // mirror + refraction, all white
        }
    }
}

// Directions in the surface plane and unnormalised inputs give no NaN, no Inf, nothing negative.
TEST(LabBsdf, DegenerateDirectionsAreSafe) {
    std::vector<Vec3> wos = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 1e-30f), Vec3(1, 0, -1e-30f),
                             Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(3, 0, 4), Vec3(1e-20f, 0, 1e-20f)};
    for (const auto& [name, m] : labMaterials())
        for (const Vec3& wo : wos) {
            LabBsdf b = LabBsdf::make(m, m.kd, wo.z);
            for (float u1 : {0.0f, 0.3f, 0.6f, 0.9999f})
                for (Vec2 u2 : {Vec2(0.0f), Vec2(0.5f, 0.25f), Vec2(0.9999f)}) {
                    BsdfSample s;
                    if (!b.sample(wo, u1, u2, s)) continue;
                    EXPECT_TRUE(isFinite(s.wi) && isFinite(s.weight) && std::isfinite(s.pdf)) << name;
                    EXPECT_GE(s.pdf, 0.0f);
                    EXPECT_GE(std::min(s.weight.x, std::min(s.weight.y, s.weight.z)), 0.0f) << name;
                    Spectrum f = b.eval(wo, s.wi);
                    EXPECT_TRUE(isFinite(f));
                    EXPECT_TRUE(std::isfinite(b.pdf(wo, s.wi)));
                }
        }
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// White furnace of the rough lobes alone: the energy each keeps (a white mirror, w = 1 and
// R0 = 1; clear glass from outside and inside), E[weight] over its samples, lost samples counting
// 0. Single scattering loses what would bounce between microfacets: the table is printed, not
// hidden; it must never exceed 1, and must approach 1 as the lobe becomes smooth.
TEST(LabBsdf, RoughLobesFurnaceTable) {
    Material mirror;
    mirror.kd = Spectrum(0.0f);
    mirror.blend = 1.0f;
    mirror.r0 = Spectrum(1.0f);
    Material glass;
    glass.transparency = 1.0f;
    glass.eta = 1.5f;
    std::printf("energy kept (1 = none lost)       cos 1    cos 0.5  cos 0.1  | glass out: 1  0.5   0.1  | in: 1  0.5   0.1\n");
    for (float alpha : {0.002f, 0.01f, 0.05f, 0.2f, 0.5f, 1.0f}) {
        std::printf("  alpha %-5g  mirror", alpha);
        for (int kind = 0; kind < 3; ++kind) {
            if (kind > 0) std::printf("  | ");
            for (float cosO : {1.0f, 0.5f, 0.1f}) {
                Material m = kind == 0 ? mirror : glass;
                m.roughnessAlpha = alpha;
                Vec3 wo = directionAt(kind == 2 ? -cosO : cosO);
                LabBsdf b = LabBsdf::make(m, m.kd, wo.z);
                Pcg32 rng(3, 5);
                const int n = 100000;
                double sum = 0.0, sum2 = 0.0;
                for (int k = 0; k < n; ++k) {
                    BsdfSample s;
                    double e = 0.0;
                    if (b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()), s))
                        e = double(s.weight.x) / s.radianceScale; // energy, without the radiance compression
                    sum += e;
                    sum2 += e * e;
                }
                double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
                std::printf(" %7.4f", mean);
                EXPECT_LE(mean, 1.0 + 4.0 * se + 1e-6) << "alpha " << alpha << " kind " << kind << " cos " << cosO;
                if (alpha <= 0.01f && cosO >= 0.5f) EXPECT_GT(mean, 0.99) << "alpha " << alpha << " kind " << kind;
            }
        }
        std::printf("\n");
    }
}

// The rough mirror lobe is reciprocal: f(wo, wi) = f(wi, wo), with eval() = f |cos theta_i|.
TEST(LabBsdf, RoughReflectionIsReciprocal) {
    Material mirror;
    mirror.kd = Spectrum(0.0f);
    mirror.blend = 1.0f;
    mirror.r0 = Spectrum(1.0f); // F = 1 at every angle, so the blend weight does not depend on wo
    Pcg32 rng(9, 1);
    for (float alpha : {0.01f, 0.2f, 1.0f}) {
        mirror.roughnessAlpha = alpha;
        for (int k = 0; k < 200; ++k) {
            Vec3 a = directionAt(0.05f + 0.95f * rng.nextFloat(), 6.28f * rng.nextFloat());
            Vec3 c = directionAt(0.05f + 0.95f * rng.nextFloat(), 6.28f * rng.nextFloat());
            float fac = LabBsdf::make(mirror, mirror.kd, a.z).eval(a, c).x / c.z;
            float fca = LabBsdf::make(mirror, mirror.kd, c.z).eval(c, a).x / a.z;
            EXPECT_NEAR(fac, fca, 1e-4f * std::max(1.0f, fac)) << "alpha " << alpha;
        }
    }
}

// A thin wall (glTF transmission without a volume): smooth, the refraction lobe leaves along -wo
// with the lobe's weight and no radiance scaling; rough, it is the mirror lobe turned through the
// surface, so it samples its pdf (chi-square on the sphere, both sides), its weights are eval /
// pdf, and a white thin wall keeps exactly what the rough mirror keeps.
TEST(LabBsdf, ThinWallPassesUnbent) {
    LabParameters p;
    p.kd = Spectrum(0.0f);
    p.blend = 1.0f;
    p.r0 = Spectrum(0.04f);
    p.transparency = 1.0f;
    p.eta = 1.5f;
    p.alpha = 0.0f;
    p.thin = true;
    for (float cosO : {1.0f, 0.5f, -0.3f}) {
        Vec3 wo = directionAt(cosO);
        LabBsdf b = LabBsdf::make(p, wo.z);
        BsdfSample s;
        ASSERT_TRUE(b.sample(wo, 0.999f, Vec2(0.5f), s));
        EXPECT_TRUE(s.isDelta());
        EXPECT_EQ(s.wi, -wo);
        EXPECT_EQ(s.radianceScale, 1.0f);
        float f = 0.04f + 0.96f * std::pow(1.0f - std::abs(cosO), 5.0f);
        EXPECT_NEAR(s.weight.x * b.pRefract, 1.0f - f, 1e-5f) << "cos " << cosO;
    }
    for (float alpha : {0.1f, 0.5f})
        for (float cosO : {0.9f, 0.4f, -0.6f}) {
            p.alpha = alpha;
            Vec3 wo = directionAt(cosO);
            LabBsdf b = LabBsdf::make(p, wo.z);
            Pcg32 rng(3, 5);
            bool weightsOk = true;
            double through = 0.0, mirrored = 0.0;
            auto r = chiSquareDirections(
                [&](Vec2 u, Vec3& wi) {
                    BsdfSample s;
                    if (!b.sample(wo, rng.nextFloat(), u, s)) return false;
                    float pdf = b.pdf(wo, s.wi);
                    Spectrum f = b.eval(wo, s.wi);
                    if (std::abs(pdf - s.pdf) > 1e-4f * pdf || glm::length(s.weight - f / pdf) > 1e-4f * glm::length(s.weight))
                        weightsOk = false;
                    (s.wi.z * wo.z < 0.0f ? through : mirrored) += s.weight.x;
                    wi = s.wi;
                    return true;
                },
                [&](const Vec3& wi) { return double(b.pdf(wo, wi)); }, 100000);
            EXPECT_TRUE(r.pass) << "alpha " << alpha << " cos " << cosO << ": " << r.report;
            EXPECT_TRUE(weightsOk) << "alpha " << alpha << " cos " << cosO;
            // Turned through the wall, the lobe keeps the mirror's energy: transmitted over
            // reflected is the lobes' weight ratio.
            EXPECT_NEAR(through / mirrored, average(b.refract) / average(b.mirror), 0.03 * average(b.refract) / average(b.mirror))
                << "alpha " << alpha << " cos " << cosO;
        }
}

} // namespace
} // namespace pt::test
