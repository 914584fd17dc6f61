// What the path loop knows about a triangle hit: position with its error bound, normals, uv and
// material, all recomputed from the hit's barycentrics (more accurate than origin + t * dir).
#pragma once

#include "accel/accel.h"
#include "accel/ray_offset.h"
#include "scene/scene.h"

namespace pt {

struct SurfacePoint {
    Vec3 p;
    float pError; // bound on |p - true surface point|, see accel/ray_offset.h
    Vec3 ng; // unit geometric normal, on the outside as the vertex normals define it
    Vec3 ns; // unit shading normal, same hemisphere as ng
    Vec2 uv;
    uint32_t material;
};

inline SurfacePoint makeSurfacePoint(const Scene& scene, const Hit& hit) {
    SurfacePoint sp;
    const uint32_t t = hit.prim;
    const glm::uvec3& tri = scene.triPositions[t];
    const Vec3 &p0 = scene.positions[tri[0]], &p1 = scene.positions[tri[1]], &p2 = scene.positions[tri[2]];
    Vec3 b(1.0f - hit.u - hit.v, hit.u, hit.v);
    sp.p = b.x * p0 + b.y * p1 + b.z * p2;
    sp.pError = interpolationError(b, p0, p1, p2);
    sp.material = scene.triMaterial[t];

    Vec3 ng = glm::cross(p1 - p0, p2 - p0);
    float len = glm::length(ng);
    sp.ng = len > 0.0f ? ng / len : Vec3(0.0f, 0.0f, 1.0f);
    sp.ns = sp.ng;
    if (!scene.triNormals.empty() && scene.triNormals[t].x >= 0) {
        const glm::ivec3& ni = scene.triNormals[t];
        Vec3 n = b.x * scene.normals[ni.x] + b.y * scene.normals[ni.y] + b.z * scene.normals[ni.z];
        float nlen = glm::length(n);
        if (nlen > 0.0f && std::isfinite(nlen)) {
            sp.ns = n / nlen;
            // Vertex normals say which side is outside (what refraction needs); the winding
            // order of exported meshes is less reliable.
            if (glm::dot(sp.ng, sp.ns) < 0.0f) sp.ng = -sp.ng;
        }
    }
    sp.uv = Vec2(0.0f);
    if (!scene.triUvs.empty() && scene.triUvs[t].x >= 0) {
        const glm::ivec3& ti = scene.triUvs[t];
        sp.uv = b.x * scene.uvs[ti.x] + b.y * scene.uvs[ti.y] + b.z * scene.uvs[ti.z];
    }
    return sp;
}

// A ray leaving the surface in direction w, starting just off the surface on w's side.
inline Ray spawnRay(const SurfacePoint& sp, const Vec3& w) {
    return Ray{offsetRayOrigin(sp.p, sp.pError, sp.ng, w), w};
}

} // namespace pt
