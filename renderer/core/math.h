// Vector types and small helpers shared by the whole renderer.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace pt {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Spectrum = glm::vec3; // linear RGB radiance or reflectance

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInf = std::numeric_limits<float>::infinity();

inline float maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float average(const Vec3& v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }
inline float luminance(const Spectrum& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
inline bool isBlack(const Spectrum& c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }
inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline float sqr(float x) { return x * x; }
inline float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

// Length and direction of a vector whose squared length may overflow or underflow float: the
// cross product of two edges of a 1e10 triangle is 1e20, its square 1e40. Scaling by the largest
// component first keeps both exact to rounding for every finite vector.
inline float safeLength(const Vec3& v) {
    float m = maxComponent(glm::abs(v));
    if (!(m > 0.0f) || !std::isfinite(m)) return m;
    return m * glm::length(v * (1.0f / m));
}
// Unit vector along v, or (0, 0, 0) when v is zero or not finite.
inline Vec3 safeNormalize(const Vec3& v) {
    float m = maxComponent(glm::abs(v));
    if (!(m > 0.0f) || !std::isfinite(m)) return Vec3(0.0f);
    Vec3 s = v * (1.0f / m);
    return s * (1.0f / glm::length(s));
}

// dp/du and dp/dv of a triangle whose edges e1, e2 change uv by s1, s2. Returns twice the signed
// uv area (its sign is the handedness of the uv layout); where the layout is degenerate (an area
// of 0, or too small to divide by) it returns 0 and leaves dpdu and dpdv as they are.
inline float uvDerivatives(const Vec3& e1, const Vec3& e2, Vec2 s1, Vec2 s2, Vec3& dpdu, Vec3& dpdv) {
    float det = s1.x * s2.y - s1.y * s2.x;
    if (det == 0.0f || !std::isfinite(1.0f / det)) return 0.0f;
    dpdu = (s2.y * e1 - s1.y * e2) / det;
    dpdv = (s1.x * e2 - s2.x * e1) / det;
    return det;
}

// Orthonormal basis around a unit vector n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"): branchless and exact for every n, including n = (0, 0, -1).
struct Frame {
    Vec3 s, t, n;

    Frame() = default;
    explicit Frame(const Vec3& normal) : n(normal) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = Vec3(b, sign + n.y * n.y * a, -n.y);
    }
    Vec3 toLocal(const Vec3& v) const { return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)); }
    Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

} // namespace pt
