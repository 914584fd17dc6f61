// Generic microfacet pieces, in the local shading frame (z = macro normal): the isotropic GGX
// (Trowbridge-Reitz) distribution, Smith masking in its separable and height-correlated forms,
// sampling of the visible normals with its exact density, and Fresnel terms. The lab tree's
// rough lobes and the glTF material are both built from these.
//
// References: Walter, Marschner, Li, Torrance 2007 (D, G1, the reflection and refraction
// Jacobians); Heitz 2014 (Lambda, height-correlated G2); Heitz 2018 and Dupuy, Benyoub 2023
// (visible normals sampled as a spherical cap of the stretched configuration).
#pragma once

#include "core/math.h"

#include <algorithm>

namespace pt {

// Roughness at or below this is the smooth (delta) lobe.
inline constexpr float kSmoothAlpha = 0.001f;

// D(m) = alpha^2 / (pi cos^4(theta_m) (alpha^2 + tan^2(theta_m))^2) for unit m, written as
// alpha^2 / (pi (alpha^2 cos^2 + sin^2)^2) with sin^2 from x and y: the common form
// cos^2 (alpha^2 - 1) + 1 cancels catastrophically near the pole (2 % off at alpha = 0.002).
inline float ggxD(const Vec3& m, float alpha) {
    if (m.z <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float t = a2 * m.z * m.z + (m.x * m.x + m.y * m.y);
    return a2 / (kPi * t * t);
}

// Smith's Lambda for GGX: (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2, computed from cos^2 and
// sin^2 so that grazing directions stay finite.
inline float ggxLambda(const Vec3& w, float alpha) {
    float cos2 = w.z * w.z;
    if (cos2 == 0.0f) return kInf;
    float sin2 = std::max(0.0f, w.x * w.x + w.y * w.y);
    float a2tan2 = alpha * alpha * sin2 / cos2;
    return 0.5f * (std::sqrt(1.0f + a2tan2) - 1.0f);
}

// G1(w, m): the fraction of microfacets with normal m visible from w. Zero when w sees m's back
// (Walter's chi+ on w.m / w.n).
inline float smithG1(const Vec3& w, const Vec3& m, float alpha) {
    if (glm::dot(w, m) * w.z <= 0.0f) return 0.0f;
    return 1.0f / (1.0f + ggxLambda(w, alpha));
}

// The separable masking-shadowing of Walter et al. 2007: G1(wo, m) G1(wi, m).
inline float smithG2Separable(const Vec3& wo, const Vec3& wi, const Vec3& m, float alpha) {
    return smithG1(wo, m, alpha) * smithG1(wi, m, alpha);
}

// The height-correlated form (Heitz 2014): 1 / (1 + Lambda(wo) + Lambda(wi)), for the glTF material.
inline float smithG2HeightCorrelated(const Vec3& wo, const Vec3& wi, const Vec3& m, float alpha) {
    if (glm::dot(wo, m) * wo.z <= 0.0f || glm::dot(wi, m) * wi.z <= 0.0f) return 0.0f;
    return 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}

// Density of the normals visible from wo (wo.z > 0): D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z.
// It integrates to 1 over the hemisphere of m.
inline float visibleNormalPdf(const Vec3& wo, const Vec3& m, float alpha) {
    if (wo.z <= 0.0f) return 0.0f;
    float cosOM = glm::dot(wo, m);
    if (cosOM <= 0.0f) return 0.0f;
    return smithG1(wo, m, alpha) * cosOM * ggxD(m, alpha) / wo.z;
}

// Samples m with density visibleNormalPdf(wo, m) (wo.z > 0): in the configuration stretched to
// alpha = 1 the visible normals are a spherical cap around wo (Dupuy and Benyoub 2023).
inline Vec3 sampleVisibleNormal(const Vec3& wo, float alpha, Vec2 u) {
    Vec3 ws = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float phi = 2.0f * kPi * u.x;
    float z = (1.0f - u.y) * (1.0f + ws.z) - ws.z;
    float sinTheta = safeSqrt(1.0f - z * z);
    Vec3 h = Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z) + ws;
    Vec3 m(alpha * h.x, alpha * h.y, std::max(h.z, 0.0f));
    float len = glm::length(m);
    return len > 0.0f ? m / len : Vec3(0.0f, 0.0f, 1.0f);
}

// Unpolarized Fresnel reflectance of a dielectric interface for light arriving at cosThetaI
// (> 0 on the side of the normal) with etaRel = eta_transmitted / eta_incident; 1 on total
// internal reflection.
inline float fresnelDielectric(float cosThetaI, float etaRel) {
    cosThetaI = std::clamp(cosThetaI, 0.0f, 1.0f);
    float sin2T = (1.0f - cosThetaI * cosThetaI) / (etaRel * etaRel);
    if (sin2T >= 1.0f) return 1.0f;
    float cosT = std::sqrt(1.0f - sin2T);
    float rs = (cosThetaI - etaRel * cosT) / (cosThetaI + etaRel * cosT);
    float rp = (etaRel * cosThetaI - cosT) / (etaRel * cosThetaI + cosT);
    return 0.5f * (rs * rs + rp * rp);
}

// Fresnel reflectance of a conductor with complex index eta + i k (per channel), relative to the
// outside medium, for light arriving at cosThetaI.
inline float fresnelConductor(float cosThetaI, float eta, float k) {
    float c = std::clamp(cosThetaI, 0.0f, 1.0f), c2 = c * c, s2 = 1.0f - c2;
    float t0 = eta * eta - k * k - s2;
    float a2b2 = std::sqrt(std::max(0.0f, t0 * t0 + 4.0f * eta * eta * k * k));
    float a = safeSqrt(0.5f * (a2b2 + t0));
    float t1 = a2b2 + c2, t2 = 2.0f * a * c;
    float rs = (t1 - t2) / (t1 + t2);
    float t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    float rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5f * (rs + rp);
}

inline Spectrum fresnelConductor(float cosThetaI, const Spectrum& eta, const Spectrum& k) {
    return Spectrum(fresnelConductor(cosThetaI, eta.x, k.x), fresnelConductor(cosThetaI, eta.y, k.y),
                    fresnelConductor(cosThetaI, eta.z, k.z));
}

// Jacobian from the half vector to the reflected direction: dwm / dwi = 1 / (4 |wi.m|).
inline float reflectionJacobian(const Vec3& wi, const Vec3& m) { return 1.0f / (4.0f * std::abs(glm::dot(wi, m))); }

// Jacobian from the microfacet normal to the refracted direction (Walter et al. eq. 17), with
// etaRel = eta_transmitted / eta_incident: eta_t^2 |wi.m| / (eta_i wo.m + eta_t wi.m)^2.
inline float refractionJacobian(const Vec3& wo, const Vec3& wi, const Vec3& m, float etaRel) {
    float denom = glm::dot(wo, m) + etaRel * glm::dot(wi, m);
    return etaRel * etaRel * std::abs(glm::dot(wi, m)) / (denom * denom);
}

} // namespace pt
