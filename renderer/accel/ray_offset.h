// The one place that decides where a ray leaving a surface starts. Offsets come from a bound on
// the floating-point error of the hit point (pbrt-v4, section 6.8), so they scale with the
// coordinates themselves and need no scene-size epsilon: a scene scaled by 1e-3 or 1e4, or moved
// far from the origin, is traced the same way.
#pragma once

#include "accel/accel.h"
#include "core/math.h"

namespace pt {

// Bound on the distance between a point interpolated from triangle vertices with barycentrics b
// and the plane that Embree intersects, as a scalar with two parts:
//  - representing p in float: a few ulps of the coordinates that produced it;
//  - Embree's own arithmetic (edge vectors, normal, origin-to-vertex differences), which is
//    relative to the triangle's size, not to its distance from the origin.
// It must be isotropic: Embree mixes all coordinates, so an axis-aligned plane at y = 0, whose
// interpolated y is exact, still needs an offset in y. Keeping the first term small matters
// far from the origin: a box at 1e4 then gets offsets of a few ulps, not a hundred.
// tests/ray_offset_test.cpp re-intersects slivers, huge, axis-aligned and distant triangles.
inline float interpolationError(const Vec3& b, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    constexpr float kRepresent = 4.0f * 0x1p-24f;  // 2x the smallest factor the test passes with
    constexpr float kArithmetic = 64.0f * 0x1p-24f; // likewise
    auto mag = [](const Vec3& p) { return maxComponent(glm::abs(p)); };
    float coords = std::abs(b.x) * mag(p0) + std::abs(b.y) * mag(p1) + std::abs(b.z) * mag(p2);
    float extent = std::max(mag(p1 - p0), std::max(mag(p2 - p0), mag(p2 - p1)));
    return kRepresent * coords + kArithmetic * extent;
}

// Moves p off the surface with unit normal n to the side of direction w by the error bound, then
// one more ulp away so rounding cannot bring it back.
inline Vec3 offsetRayOrigin(const Vec3& p, float pError, const Vec3& n, const Vec3& w) {
    Vec3 offset = pError * n;
    if (glm::dot(w, n) < 0.0f) offset = -offset;
    Vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = std::nextafter(po[i], kInf);
        else if (offset[i] < 0.0f) po[i] = std::nextafter(po[i], -kInf);
    }
    return po;
}

} // namespace pt
