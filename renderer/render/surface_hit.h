// A triangle hit made into a SurfacePoint: position with its error bound, normals and material,
// recomputed from the hit's barycentrics (more accurate than origin + t * dir); its texture
// coordinates and footprint; and the rays that leave it.
#pragma once

#include "accel/accel.h"
#include "core/ray_offset.h"
#include "scene/surface_point.h"
#include "render/shading_triangles.h"
#include "render/vertex_tangents.h"

namespace pt {

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

// Texture coordinates of a hit and the footprint of a ray cone of width `coneWidth` arriving
// along `dir`: on the surface an ellipse with axes coneWidth across the plane of incidence and
// coneWidth / |cos theta| along it, mapped into uv through the triangle's own uv layout.
inline void addTextureCoordinates(SurfacePoint& sp, const ShadingTriangle& tri, const Scene& scene,
                                  const std::vector<CornerTangent>& tangents, const Hit& hit, const Vec3& dir,
                                  float coneWidth) {
    if (!scene.vertexColors.empty()) {
        const glm::uvec3& t = scene.triPositions[hit.prim];
        // Clamped: at an edge u + v can pass 1 by a rounding, and a colour of -1e-7 is a negative sample.
        sp.color = glm::max(Spectrum(0.0f), (1.0f - hit.u - hit.v) * scene.vertexColors[t.x] +
                                                hit.u * scene.vertexColors[t.y] + hit.v * scene.vertexColors[t.z]);
    }
    if (scene.triUvs.empty() || scene.triUvs[hit.prim].x < 0) return;
    const glm::ivec3& ti = scene.triUvs[hit.prim];
    const Vec2 uv0 = scene.uvs[ti.x];
    const Vec2 s1 = scene.uvs[ti.y] - uv0, s2 = scene.uvs[ti.z] - uv0;
    const float b0 = 1.0f - hit.u - hit.v;
    sp.uv = uv0 + hit.u * s1 + hit.v * s2;

    uvDerivatives(tri.e1, tri.e2, s1, s2, sp.dpdu, sp.dpdv);
    if (!tangents.empty()) {
        const CornerTangent* c = &tangents[3 * size_t(hit.prim)];
        sp.tangent = b0 * c[0].tangent + hit.u * c[1].tangent + hit.v * c[2].tangent;
        sp.bitangentSign = c[0].sign;
    }

    if (!(coneWidth > 0.0f)) return;
    Vec3 across = safeNormalize(glm::cross(sp.ng, dir));
    if (across == Vec3(0.0f)) across = Frame(sp.ng).s; // head-on: the ellipse is a circle
    Vec3 along = glm::cross(across, sp.ng);
    float cosTheta = std::max(std::abs(glm::dot(dir, sp.ng)), 1e-3f);
    // A surface vector a = alpha e1 + beta e2 moves uv by alpha s1 + beta s2.
    // In double: the Gram determinant is a fourth power of the scene's size.
    const glm::dvec3 e1(tri.e1), e2(tri.e2);
    double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    double gram = g11 * g22 - g12 * g12;
    if (!(gram > 0.0)) return;
    auto toUv = [&](const Vec3& a) {
        double r1 = glm::dot(glm::dvec3(a), e1), r2 = glm::dot(glm::dvec3(a), e2);
        float alpha = float((g22 * r1 - g12 * r2) / gram), beta = float((g11 * r2 - g12 * r1) / gram);
        return alpha * s1 + beta * s2;
    };
    sp.footprint.dx = toUv(coneWidth * across);
    sp.footprint.dy = toUv((coneWidth / cosTheta) * along);
}

// A ray leaving the surface in direction w, starting just off the surface on w's side.
inline Ray spawnRay(const SurfacePoint& sp, const Vec3& w) {
    return Ray{offsetRayOrigin(sp.p, sp.pError, sp.ng, w), w};
}

} // namespace pt
