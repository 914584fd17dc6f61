// The lab's material tree, evaluated at one hit.
//
//   f  = w * FresnelBlend(R0)[reflect: Spec(Ks), otherwise: B1] + (1 - w) * B1
//   B1 = T * Refr(eta) + (1 - T) * Diffuse(Kd)
//   FresnelBlend picks the reflection branch with weight F = R0 + (1 - R0)(1 - |cos theta_o|)^5
//
// For a fixed outgoing direction the blends are constants, so the tree collapses into a sum of
// three lobes with per-hit weights:
//   mirror  (Spec)      w F Ks
//   refract (Refr)      (1 - w F) T
//   diffuse (Lambert)   (1 - w F)(1 - T) Kd
// With roughness alpha = specularroughness <= 0.001 Spec and Refr are delta lobes. Above it they
// are GGX microfacet lobes (material/microfacet.h), with the separable Smith G of Walter et al.
// 2007 and no Fresnel of their own (the tree's FresnelBlend applies it):
//   Spec: f |cos theta_i| = Ks D(h) G(wo, wi, h) / (4 |cos theta_o|)
//   Refr: per microfacet normal m, the smooth rule: refract through m with throughput 1 (and the
//         same (eta_o / eta_i)^2 radiance scaling), or where refraction through m is impossible,
//         reflect about m with reflectance 1: Walter et al.'s BTDF (eq. 21) with F = 0, plus the
//         reflection of the totally internally reflecting microfacets.
//         Thin-walled (glTF transmission without a volume): light crosses a sheet without bending,
//         so Refr is the mirror lobe reflected through the surface (wi's z negated): smooth, -wo.
// Both are sampled through the normals visible from wo, so a sample's weight is the lobe weight
// times G1(wi, m); single scattering loses the energy of paths that would bounce between
// microfacets (tests/lab_bsdf_test.cpp tabulates how much).
// One lobe is sampled with probability proportional to its average weight, which is unbiased for
// the whole tree and never samples a lobe of weight zero.
//
// Conventions (as in pbrt): directions are in the local shading frame (z = shading normal, which
// points to the outside of the object) and both wo and wi point away from the surface; wo is the
// direction the path came from. theta_o in F is the angle of wo. eval() returns f * |cos theta_i|
// of the non-delta lobes; pdf() is the solid-angle density with which sample() returns wi through
// a non-delta lobe, lobe choice included.
#pragma once

#include "core/math.h"
#include "material/bsdf_sample.h"
#include "material/microfacet.h"
#include "scene/scene.h"

namespace pt {

// The lab tree's parameters at one hit, after textures and the Pm rule (evaluate_material.h).
struct LabParameters {
    Spectrum kd{0.7f}, ks{1.0f}, r0{0.0f};
    float blend = 0.0f, transparency = 0.0f, eta = 1.0f;
    float alpha = 0.001f; // GGX roughness of Spec and Refr; <= kSmoothAlpha: delta lobes
    Spectrum refractTint{1.0f}; // multiplies Refr: white in the lab, the base colour for glTF transmission
    bool thin = false;          // Refr passes straight through a thin wall (glTF transmission without a volume)
    // glTF transmission mixes a metal and a dielectric by metallic: the metal's share reflects by
    // its own Fresnel (in r0, mixed) and the rest of it is absorbed; only the dielectric's share
    // of what its own Fresnel (dielectricR0) does not reflect is split between Refr and Diffuse.
    // 0: the lab's tree, where all that the blend does not reflect is split.
    float metalShare = 0.0f;
    float dielectricR0 = 0.0f;
};

// The parameters of a material whose Kd, after its texture, is `kd`. With Pm (the PBR
// extension), metallic m mixes the dielectric's F0 towards Ks, the blend is always on, the mirror
// is white and the diffuse part fades out with m.
// `ks`, `alpha` and `metallic` are the material's after their maps (metallic < 0: no Pm).
inline LabParameters labParameters(const Material& m, const Spectrum& kd, const Spectrum& ks, float alpha,
                                   float metallic) {
    LabParameters p{kd, ks, m.r0, m.blend, m.transparency, m.eta, alpha};
    if (metallic >= 0.0f) {
        float f0 = sqr((m.eta - 1.0f) / (m.eta + 1.0f));
        p.r0 = glm::mix(Spectrum(f0), ks, metallic);
        p.blend = 1.0f;
        p.ks = Spectrum(1.0f);
        p.kd = kd * (1.0f - metallic);
    }
    return p;
}
inline LabParameters labParameters(const Material& m, const Spectrum& kd) {
    return labParameters(m, kd, m.ks, m.roughnessAlpha, m.metallic);
}

struct LabBsdf {
    Spectrum mirror{0.0f}, refract{0.0f}, diffuse{0.0f};
    float pMirror = 0.0f, pRefract = 0.0f, pDiffuse = 0.0f;
    float eta = 1.0f; // index of refraction inside the surface; the outside is 1
    float alpha = 0.0f; // GGX roughness of the mirror and refraction lobes; 0 when they are smooth
    bool thin = false;  // Refr is the mirror lobe turned through the surface
    HemisphereSampling hemisphere = HemisphereSampling::Cosine;

    bool rough() const { return alpha > 0.0f; }

    // The tree for outgoing direction cosThetaO = wo.z: made, or set in place (every field).
    static LabBsdf make(const LabParameters& p, float cosThetaO, HemisphereSampling hemisphere = HemisphereSampling::Cosine);
    void init(const LabParameters& p, float cosThetaO, HemisphereSampling hemisphere);
    // Same for a material whose Kd, after its texture, is `kd` (tests; the renderer goes through
    // evaluate_material.h).
    static LabBsdf make(const Material& m, const Spectrum& kd, float cosThetaO,
                        HemisphereSampling hemisphere = HemisphereSampling::Cosine) {
        return make(labParameters(m, kd), cosThetaO, hemisphere);
    }

    // The BsdfLobe flags of the lobes with weight at this wo (0: black).
    uint8_t lobes() const {
        const uint8_t shape = rough() ? kLobeGlossy : kLobeSpecular;
        return (pMirror > 0.0f ? kLobeReflection | shape : 0) | (pRefract > 0.0f ? kLobeTransmission | shape : 0) |
               (pDiffuse > 0.0f ? kLobeReflection | kLobeDiffuse : 0);
    }
    // Reflectance at wo for the albedo AOV: the three lobe weights, each with its colour.
    Spectrum albedo(const Vec3&) const { return mirror + refract + diffuse; }

    // eval() and pdf() of the same pair of directions, in one pass.
    Spectrum evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const;
    Spectrum eval(const Vec3& wo, const Vec3& wi) const {
        float unused;
        return evalPdf(wo, wi, unused);
    }
    float pdf(const Vec3& wo, const Vec3& wi) const {
        float p;
        evalPdf(wo, wi, p);
        return p;
    }
    // u1 chooses the lobe, u2 the direction inside it. Returns false if the path ends here.
    bool sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const;
    // The chance that sample() takes a delta lobe, and whether u1 makes it take one (a path
    // guide leaves those choices to the BSDF, as sample() makes them).
    float deltaShare() const { return rough() ? 0.0f : pMirror + pRefract; }
    bool picksDelta(float u1) const { return !rough() && (u1 < pMirror + pRefract || pDiffuse == 0.0f); }
};

// Schlick's approximation, per channel: R0 + (1 - R0)(1 - cos)^5.
inline Spectrum schlickFresnel(const Spectrum& r0, float cosTheta) {
    float m = 1.0f - std::min(1.0f, std::abs(cosTheta));
    float m2 = m * m;
    return r0 + (Spectrum(1.0f) - r0) * (m2 * m2 * m);
}

// Inline, so that the lobes are built where the caller keeps them: a LabBsdf returned from
// another file was copied twice on its way into a Bsdf, each copy a failed store forwarding.
inline void LabBsdf::init(const LabParameters& m, float cosThetaO, HemisphereSampling hemisphere) {
    LabBsdf& b = *this;
    b.eta = m.eta;
    b.alpha = m.alpha > kSmoothAlpha ? m.alpha : 0.0f;
    b.thin = m.thin;
    b.hemisphere = hemisphere;
    Spectrum wF = m.blend * schlickFresnel(m.r0, cosThetaO);
    Spectrum rest = m.metalShare > 0.0f
                        ? (1.0f - m.metalShare) * (Spectrum(1.0f) - schlickFresnel(Spectrum(m.dielectricR0), cosThetaO))
                        : Spectrum(1.0f) - wF;
    b.mirror = wF * m.ks;
    b.refract = rest * m.transparency * m.refractTint;
    b.diffuse = rest * (1.0f - m.transparency) * m.kd;

    float am = average(b.mirror), at = average(b.refract), ad = average(b.diffuse);
    float sum = am + at + ad;
    const bool any = sum > 0.0f;
    b.pMirror = any ? am / sum : 0.0f;
    b.pRefract = any ? at / sum : 0.0f;
    b.pDiffuse = any ? ad / sum : 0.0f;
}
inline LabBsdf LabBsdf::make(const LabParameters& m, float cosThetaO, HemisphereSampling hemisphere) {
    LabBsdf b;
    b.init(m, cosThetaO, hemisphere);
    return b;
}

// Refracts wo through the plane z = 0 with relative index etaRel = eta_transmitted /
// eta_incident. Returns false on total internal reflection.
bool refractDirection(const Vec3& wo, float etaRel, Vec3& wt);

} // namespace pt
