// Warps from the unit square to directions and points, each with the density it produces.
// Directions are in a local frame with z up; densities are per unit solid angle.
#pragma once

#include "core/math.h"

namespace pt {

// Shirley-Chiu concentric map: keeps strata compact, which helps low-discrepancy samplers.
inline Vec2 squareToConcentricDisk(Vec2 u) {
    float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return Vec2(0.0f);
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
    }
    return Vec2(r * std::cos(phi), r * std::sin(phi));
}

// Malley's method: project the disk up onto the hemisphere. pdf = cos(theta) / pi.
inline Vec3 squareToCosineHemisphere(Vec2 u) {
    Vec2 d = squareToConcentricDisk(u);
    float z = safeSqrt(1.0f - d.x * d.x - d.y * d.y);
    return Vec3(d.x, d.y, z);
}
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

inline Vec3 squareToUniformHemisphere(Vec2 u) {
    float z = u.x;
    float r = safeSqrt(1.0f - z * z);
    float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
inline float uniformHemispherePdf() { return 0.5f * kInvPi; }

inline Vec3 squareToUniformSphere(Vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = safeSqrt(1.0f - z * z);
    float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
inline float uniformSpherePdf() { return 0.25f * kInvPi; }

// Uniform directions in the cone around +z whose half-angle has 1 - cos = oneMinusCosMax.
// Taking 1 - cos as the input keeps tiny cones (distant or small lights) exact, where
// 1 - cos(theta) computed from cos(theta) would round to zero.
inline Vec3 squareToUniformCone(Vec2 u, float oneMinusCosMax) {
    float oneMinusCos = u.x * oneMinusCosMax;
    float cosTheta = 1.0f - oneMinusCos;
    float sinTheta = safeSqrt(oneMinusCos * (2.0f - oneMinusCos));
    float phi = 2.0f * kPi * u.y;
    return Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}
inline float uniformConePdf(float oneMinusCosMax) { return 1.0f / (2.0f * kPi * oneMinusCosMax); }

// Uniform barycentrics (b1, b2) on a triangle; b0 = 1 - b1 - b2. pdf = 1 / area.
inline Vec2 squareToUniformTriangle(Vec2 u) {
    float su = std::sqrt(u.x);
    return Vec2(1.0f - su, u.y * su);
}

} // namespace pt
