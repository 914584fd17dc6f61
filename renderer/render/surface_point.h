// What the path loop knows about a triangle hit: position with its error bound, normals and
// material, recomputed from the hit's barycentrics (more accurate than origin + t * dir).
#pragma once

#include "accel/accel.h"
#include "accel/ray_offset.h"
#include "render/shading_triangles.h"

namespace pt {

struct SurfacePoint {
    Vec3 p;
    float pError; // bound on |p - true surface point|, see accel/ray_offset.h
    Vec3 ng;      // unit geometric normal, on the outside as the vertex normals define it
    Vec3 ns;      // unit shading normal, same hemisphere as ng
    uint32_t material;
};

inline SurfacePoint makeSurfacePoint(const ShadingTriangle& tri, const Hit& hit) {
    SurfacePoint sp;
    sp.p = tri.p0 + hit.u * tri.e1 + hit.v * tri.e2;
    sp.pError = tri.offsetError;
    sp.material = tri.material();
    sp.ng = safeNormalize(glm::cross(tri.e1, tri.e2)); // a plain length overflows beyond 4e9
    if (sp.ng == Vec3(0.0f)) sp.ng = Vec3(0.0f, 0.0f, 1.0f);
    sp.ns = sp.ng;
    if (tri.materialAndFlags & ShadingTriangle::kFlat) {
        sp.ns = Vec3(tri.flatNormal[0], tri.flatNormal[1], tri.flatNormal[2]);
    } else if (tri.materialAndFlags & ShadingTriangle::kSmooth) {
        float b0 = 1.0f - hit.u - hit.v;
        Vec3 n = b0 * decodeOctahedral(tri.normals[0]) + hit.u * decodeOctahedral(tri.normals[1]) +
                 hit.v * decodeOctahedral(tri.normals[2]);
        float nlen = glm::length(n);
        if (nlen > 0.0f) sp.ns = n / nlen;
    }
    // Vertex normals say which side is outside (what refraction needs); the winding order of
    // exported meshes is less reliable.
    if (glm::dot(sp.ng, sp.ns) < 0.0f) sp.ng = -sp.ng;
    return sp;
}

// Texture coordinates of a hit; only textured materials need them.
inline Vec2 hitUv(const Scene& scene, const Hit& hit) {
    if (scene.triUvs.empty() || scene.triUvs[hit.prim].x < 0) return Vec2(0.0f);
    const glm::ivec3& ti = scene.triUvs[hit.prim];
    return (1.0f - hit.u - hit.v) * scene.uvs[ti.x] + hit.u * scene.uvs[ti.y] + hit.v * scene.uvs[ti.z];
}

// A ray leaving the surface in direction w, starting just off the surface on w's side.
inline Ray spawnRay(const SurfacePoint& sp, const Vec3& w) {
    return Ray{offsetRayOrigin(sp.p, sp.pError, sp.ng, w), w};
}

} // namespace pt
