// Sampling a sphere light by the solid angle of the cap visible from the shading point.
#pragma once

#include "core/math.h"
#include "sampling/warp.h"

namespace pt {

struct SphereCap {
    Vec3 axis;            // unit direction from the shading point to the centre
    float distance;       // from the shading point to the centre
    float oneMinusCosMax; // 1 - cos of the cap's half-angle; 2 when the point is inside
};

// 1 - cos(theta_max) with sin^2(theta_max) = r^2 / d^2, computed as sin^2 / (1 + cos) so that
// small or distant spheres do not round to an empty cone.
inline SphereCap sphereCap(const Vec3& p, const Vec3& center, float radius) {
    Vec3 d = center - p;
    float dist2 = glm::dot(d, d);
    float dist = std::sqrt(dist2);
    SphereCap cap{dist > 0.0f ? d / dist : Vec3(0, 0, 1), dist, 2.0f};
    float sin2Max = radius * radius / dist2;
    if (sin2Max < 1.0f) cap.oneMinusCosMax = sin2Max / (1.0f + std::sqrt(1.0f - sin2Max));
    return cap;
}

inline float sphereCapPdf(const SphereCap& cap) {
    return cap.oneMinusCosMax >= 2.0f ? uniformSpherePdf() : uniformConePdf(cap.oneMinusCosMax);
}

} // namespace pt
