// The one place that decides where a ray leaving a surface starts. Offsets come from a bound on
// the floating-point error of the hit point (pbrt-v4, section 6.8), so they scale with the
// coordinates themselves and need no scene-size epsilon: a scene scaled by 1e-3 or 1e4, or moved
// far from the origin, is traced the same way.
#pragma once

#include "core/math.h"

namespace pt {

// Bound on the distance between a point interpolated on a triangle and the plane that Embree
// intersects, as a scalar with two parts:
//  - representing p in float: a few ulps of the largest coordinate of the triangle;
//  - Embree's own arithmetic (edge vectors, normal, origin-to-vertex differences), which is
//    relative to the triangle's size, not to its distance from the origin.
// It must be isotropic: Embree mixes all coordinates, so an axis-aligned plane at y = 0, whose
// interpolated y is exact, still needs an offset in y. Keeping the first term small matters
// far from the origin: a box at 1e4 then gets offsets of a few ulps, not a hundred.
// tests/ray_offset_test.cpp re-intersects slivers, huge, axis-aligned and distant triangles.
inline float triangleOffsetError(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    constexpr float kRepresent = 6.0f * 0x1p-24f;  // 2x the smallest factor (3) the test passes with
    constexpr float kArithmetic = 64.0f * 0x1p-24f; // 2x the smallest (32)
    auto mag = [](const Vec3& p) { return maxComponent(glm::abs(p)); };
    float coords = std::max(mag(p0), std::max(mag(p1), mag(p2)));
    float extent = std::max(mag(p1 - p0), std::max(mag(p2 - p0), mag(p2 - p1)));
    return kRepresent * coords + kArithmetic * extent;
}

// Moves p off the surface with unit normal n to the side of direction w by the error bound.
// Rounding p + offset can take back at most half an ulp per coordinate, well inside the bound's
// margin (twice the factors the re-intersection test needs without any round-away step),
// so no extra round-away step is needed.
inline Vec3 offsetRayOrigin(const Vec3& p, float pError, const Vec3& n, const Vec3& w) {
    return p + (glm::dot(w, n) < 0.0f ? -pError : pError) * n;
}

} // namespace pt
