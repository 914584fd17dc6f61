// The one place that decides where a ray leaving a surface starts. Offsets come from a bound on
// the floating-point error of the hit point (pbrt-v4, section 6.8), so they scale with the
// coordinates themselves and need no scene-size epsilon: a scene scaled by 1e-3 or 1e4, or moved
// far from the origin, is traced the same way.
#pragma once

#include "accel/accel.h"
#include "core/math.h"

namespace pt {

// Conservative bound on the absolute error of a point interpolated from triangle vertices with
// barycentrics b: a few ulps of the largest contributing coordinates. The factor is larger than
// pbrt's gamma(7) because Embree's intersector, not ours, must agree the origin is off the
// surface; tests/ray_offset_test.cpp re-intersects random triangles at many scales to check it.
inline Vec3 interpolationError(const Vec3& b, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    constexpr float kGamma = 32.0f * 0x1p-24f;
    return kGamma * (glm::abs(b.x * p0) + glm::abs(b.y * p1) + glm::abs(b.z * p2));
}

// Moves p off the surface with normal n to the side of direction w, by the error bound projected
// on n, then one more ulp away so rounding cannot bring it back.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& n, const Vec3& w) {
    float d = glm::dot(glm::abs(n), pError);
    Vec3 offset = d * n;
    if (glm::dot(w, n) < 0.0f) offset = -offset;
    Vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = std::nextafter(po[i], kInf);
        else if (offset[i] < 0.0f) po[i] = std::nextafter(po[i], -kInf);
    }
    return po;
}

} // namespace pt
