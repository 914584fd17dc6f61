// What shading needs of each triangle, packed into one 64-byte cache line: after Embree reports
// a hit, one load gives the position, the offset bound, the material and the vertex normals
// (octahedral-encoded), instead of chasing indices through four scene arrays.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace pt {

struct alignas(64) ShadingTriangle {
    Vec3 p0, e1, e2;           // first vertex and the edges to the other two
    uint32_t materialAndFlags; // material index, and how the shading normal is stored
    float offsetError;         // bound for offsetting ray origins (core/ray_offset.h)
    union {
        uint32_t normals[3]; // kSmooth: unit vertex normals, octahedral-encoded (16 bits per axis)
        float flatNormal[3]; // kFlat: the one unit normal all three vertices share (walls, boxes)
    };

    static constexpr uint32_t kSmooth = 1u << 31;
    static constexpr uint32_t kFlat = 1u << 30;
    static constexpr uint32_t kFlags = kSmooth | kFlat;
    uint32_t material() const { return materialAndFlags & ~kFlags; }
};
static_assert(sizeof(ShadingTriangle) == 64);

std::vector<ShadingTriangle> buildShadingTriangles(const Scene& scene);

// Octahedral map of a unit vector to 2 x 16 bits (Meyer et al. 2010): 3e-5 rad worst-case error.
uint32_t encodeOctahedral(const Vec3& n);
inline Vec3 decodeOctahedral(uint32_t code) {
    float x = float(code & 0xffffu) * (2.0f / 65535.0f) - 1.0f;
    float y = float(code >> 16) * (2.0f / 65535.0f) - 1.0f;
    Vec3 v(x, y, 1.0f - std::abs(x) - std::abs(y));
    float t = std::max(-v.z, 0.0f);
    v.x += v.x >= 0.0f ? -t : t;
    v.y += v.y >= 0.0f ? -t : t;
    // Unit length again: interpolating the octahedron's points (lengths 1/sqrt(3) to 1) would
    // weight corners by their direction, not by the barycentrics.
    return glm::normalize(v);
}

} // namespace pt
