// glTF 2.0's metallic-roughness BRDF (the specification's Appendix B) at one hit:
//
//   f          = (1 - metallic) dielectric + metallic metal
//   dielectric = (1 - s max(F_d(v.h))) baseColor / pi + s F_d(v.h) S
//   metal      = F_m(v.h) S
//   S          = D(h) G2(v, l) / (4 |n.v| |n.l|),  GGX with alpha = roughness^2, G2 height-correlated
//   F_d        = F0 + (1 - F0)(1 - |v.h|)^5, F0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1)
//   F_m        = baseColor + (1 - baseColor)(1 - |v.h|)^5
// where s and specularColor are KHR_materials_specular's (1 and white without it: then F0 = 0.04
// for ior 1.5 and the dielectric is the core specification's fresnel_mix).
//
// KHR_materials_clearcoat puts a coat over all of it, as the extension's fresnel_coat does:
//
//   coated = (1 - c Fc(v.nc)) f + c Fc(v.nc) C,   Fc = 0.04 + 0.96 (1 - |v.nc|)^5 (ior 1.5)
//   C      = D(h) G2(v, l) / (4 |nc.v| |nc.l|),  GGX with the coat's own alpha, about the coat's
//            own normal nc (its normal map, else the interpolated normal without the base's map)
//
// with c the clearcoat weight. KHR_materials_sheen lies between the coat and f, the base scaled
// by what the sheen's albedo leaves (the extension's albedo-scaling):
//
//   sheened = S_sheen + f min(1 - max3(sheenColor) E(v.n), 1 - max3(sheenColor) E(l.n))
//
// S_sheen and E in material/sheen.h; reciprocal like f. The coat mixes over `sheened`. Fc is taken at the view direction, so the coated BSDF is not
// reciprocal (the extension defines it so). A smooth coat (alpha <= kSmoothAlpha) is a delta
// mirror about nc.
//
// Fresnel is taken at the half vector, as the specification writes it; the specular lobe has no
// multiple-scattering compensation, so rough metals lose energy as the lab's rough lobes do.
// At alpha <= kSmoothAlpha the specular lobe is a delta mirror with Fresnel at the normal.
// Surfaces are two-sided: evaluate_material.h turns the frame to the side wo arrives from.
//
// Sampling picks the specular lobe (visible normals, microfacet.h) or the cosine-weighted
// diffuse one in proportion to their weights at wo, and reports the density of the mixture, so
// that eval / pdf is the sample's weight and MIS sees the true density.
#pragma once

#include "material/bsdf_sample.h"
#include "material/microfacet.h"

namespace pt {

// The BRDF's parameters at one hit, after textures (evaluate_material.h).
struct MetalRoughParameters {
    Spectrum baseColor{1.0f};
    float metallic = 0.0f;
    float alpha = 0.0f;                // GGX alpha = roughness^2
    float ior = 1.5f;
    Spectrum specularColor{1.0f};      // KHR_materials_specular
    float specular = 1.0f;
    float clearcoat = 0.0f;            // KHR_materials_clearcoat's weight c
    float clearcoatAlpha = 0.0f;       // the coat's GGX alpha
    Vec3 clearcoatNormal{0.0f, 0.0f, 1.0f}; // the coat's normal in the shading frame (z: the base's)
    Spectrum sheenColor{0.0f};         // KHR_materials_sheen (black: no sheen)
    float sheenRoughness = 0.0f;
};

struct MetalRoughBsdf {
    Spectrum baseColor{1.0f};
    float metallic = 0.0f;
    float alpha = 0.0f; // 0: smooth (delta) specular lobe
    Spectrum f0{0.04f}; // dielectric reflectance at normal incidence
    float specular = 1.0f; // s, the dielectric's specular weight
    float coat = 0.0f;     // c Fc(v.nc): the share the clear coat takes, the rest (1 - coat) the base
    float coatAlpha = 0.0f; // 0: smooth (delta) coat
    Vec3 coatNormal{0.0f, 0.0f, 1.0f};
    Spectrum sheenColor{0.0f};
    float sheenAlpha = 0.0f;    // 0: no sheen
    float sheenScaleO = 1.0f;   // 1 - max3(sheenColor) E(wo.z): the base's scaling seen from wo
    float pSpecular = 0.0f, pDiffuse = 0.0f, pCoat = 0.0f, pSheen = 0.0f;

    // The BRDF for outgoing direction wo (local): made, or set in place.
    static MetalRoughBsdf make(const MetalRoughParameters& p, const Vec3& wo);
    void init(const MetalRoughParameters& p, const Vec3& wo);
    // Without a coat only wo's cosine matters.
    static MetalRoughBsdf make(const MetalRoughParameters& p, float cosThetaO) {
        return make(p, Vec3(std::sqrt(std::max(0.0f, 1.0f - cosThetaO * cosThetaO)), 0.0f, cosThetaO));
    }
    static MetalRoughBsdf make(const Spectrum& baseColor, float metallic, float alpha, float ior, float cosThetaO,
                               const Spectrum& specularColor = Spectrum(1.0f), float specular = 1.0f) {
        return make(MetalRoughParameters{baseColor, metallic, alpha, ior, specularColor, specular}, cosThetaO);
    }

    bool smooth() const { return alpha <= 0.0f; }
    bool coatSmooth() const { return coatAlpha <= 0.0f; }
    // The BsdfLobe flags of the lobes with weight at this wo (0: black).
    uint8_t lobes() const {
        return (pSpecular > 0.0f ? kLobeReflection | (smooth() ? kLobeSpecular : kLobeGlossy) : 0) |
               (pCoat > 0.0f ? kLobeReflection | (coatSmooth() ? kLobeSpecular : kLobeGlossy) : 0) |
               (pSheen > 0.0f ? kLobeReflection | kLobeGlossy : 0) | (pDiffuse > 0.0f ? kLobeReflection | kLobeDiffuse : 0);
    }
    bool isBlack() const { return pSpecular + pDiffuse + pCoat + pSheen == 0.0f; }
    // The chance that sample() takes a delta lobe (a smooth coat or specular), and whether u1
    // makes it take one: the intervals sample() reads u1 by.
    float deltaShare() const { return (coatSmooth() ? pCoat : 0.0f) + (smooth() ? pSpecular : 0.0f); }
    bool picksDelta(float u1) const {
        return u1 < pCoat ? coatSmooth() : u1 < pCoat + pSpecular ? smooth() : false;
    }
    // Reflectance at wo for the albedo AOV: each lobe's colour times its share at wo, with
    // Fresnel at the normal (the weights that choose a lobe, per channel), as the lab model's.
    Spectrum albedo(const Vec3& wo) const;

    Spectrum evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const;
    Spectrum eval(const Vec3& wo, const Vec3& wi) const {
        float unused;
        return evalPdf(wo, wi, unused);
    }
    bool sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const;
};

} // namespace pt
