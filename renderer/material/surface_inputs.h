// Step 1 of evaluating a material at a hit (evaluate_material.h): the texture fetch. Every map
// the BSDF depends on is read here, so the model steps after it work on plain values: a batch of
// hits can fetch together, then shade together. (The emission map is read by scene/emission.h,
// the coverage map by accel.cpp's cutout filter: neither is the BSDF's.)
#pragma once

#include "scene/emission.h"
#include "scene/scene.h"
#include "scene/surface_point.h"
#include "texture/texture_cache.h"

namespace pt {


// The interpolated normal after a tangent-space normal map (y along increasing v), unnormalized.
inline Vec3 normalFromMap(const TextureMap& map, const TextureCache& textures, const SurfacePoint& sp) {
    const Vec3 n = sp.ns;
    Vec3 c = 2.0f * textures.vector(map, sp.uv, sp.footprint) - Vec3(1.0f);
    Vec3 t = sp.tangent;
    if (t == Vec3(0.0f)) t = safeNormalize(sp.dpdu - n * glm::dot(n, sp.dpdu));
    if (t == Vec3(0.0f)) t = Frame(n).s; // no uv direction at all: the map's x and y are arbitrary
    Vec3 b = sp.bitangentSign * glm::cross(n, t);
    Vec2 xy = map.bumpScale * normalMapToUv(map, Vec2(c.x, c.y));
    return xy.x * t + xy.y * b + c.z * n;
}

// A mapped normal made unit, or n where the map gives none.
inline Vec3 unitOr(const Vec3& mapped, const Vec3& n) {
    Vec3 u = safeNormalize(mapped);
    return u == Vec3(0.0f) || !isFinite(u) ? n : u;
}

// The shading normal after a normal map or a bump map (the surface displaced along n by
// -bm * height).
inline Vec3 perturbedNormal(const Material& m, const TextureCache& textures, const SurfacePoint& sp) {
    const Vec3 n = sp.ns;
    Vec3 mapped(0.0f);
    if (m.normalMap.used()) {
        mapped = normalFromMap(m.normalMap, textures, sp);
    } else if (m.bumpMap.used()) {
        if (sp.dpdu == Vec3(0.0f) || sp.dpdv == Vec3(0.0f)) return n;
        Vec2 dh;
        textures.scalar(m.bumpMap, sp.uv, sp.footprint, dh);
        dh *= m.bumpMap.bumpScale;
        Vec3 dpdu = sp.dpdu - n * (glm::dot(n, sp.dpdu) - dh.x);
        Vec3 dpdv = sp.dpdv - n * (glm::dot(n, sp.dpdv) - dh.y);
        mapped = glm::cross(dpdu, dpdv);
        if (glm::dot(mapped, n) < 0.0f) mapped = -mapped;
    } else {
        return n;
    }
    return unitOr(mapped, n);
}

// The clear coat's inputs and every map's value: out of line, so that the fetch of a plain
// material (most hits) stays small enough to be inlined into the shade stage.
[[gnu::noinline]] inline void fetchCoat(const Material& m, const TextureCache& textures, const SurfacePoint& sp,
                                        const Vec3& wo, SurfaceInputs& in) {
    // The extension: without its own normal map the coat takes no normal mapping at all.
    in.clearcoatNormal = m.clearcoatNormalMap.used() ? unitOr(normalFromMap(m.clearcoatNormalMap, textures, sp), sp.ns) : sp.ns;
    if (glm::dot(wo, in.clearcoatNormal) * glm::dot(wo, sp.ng) <= 0.0f) in.clearcoatNormal = sp.ng;
    if (m.clearcoatMap.used()) in.clearcoat = std::clamp(textures.scalar(m.clearcoatMap, sp.uv, sp.footprint), 0.0f, 1.0f);
    if (m.clearcoatRoughnessMap.used())
        in.clearcoatRoughness = std::clamp(textures.scalar(m.clearcoatRoughnessMap, sp.uv, sp.footprint), 0.0f, 1.0f);
}

[[gnu::noinline]] inline void fetchMaps(const Material& m, const TextureCache& textures, const SurfacePoint& sp,
                                        SurfaceInputs& in) {
    auto unit = [&](const TextureMap& map) { return std::clamp(textures.scalar(map, sp.uv, sp.footprint), 0.0f, 1.0f); };
    for (const MaterialMapEntry& e : kMaterialMaps) {
        const TextureMap& map = m.*e.map;
        if (!map.used()) continue;
        if (e.fetch == MapFetch::Color) in.*e.color = textures.color(map, sp.uv, sp.footprint);
        else if (e.fetch == MapFetch::Unit) in.*e.unit = unit(map);
    }
    if (m.vertexColors) in.kd *= sp.color;
}

// Reads every map of `m` at the hit. `wo` points back along the arriving ray. Textured materials
// need `sp`'s texture coordinates (addTextureCoordinates).
inline SurfaceInputs fetchSurfaceInputs(const Material& m, const TextureCache& textures, const SurfacePoint& sp,
                                        const Vec3& wo) {
    SurfaceInputs in;
    in.normal = m.perturbsNormal() ? perturbedNormal(m, textures, sp) : sp.ns;
    // Where interpolated or mapped normals put the viewer behind the surface that the geometry
    // shows (silhouettes of smooth meshes, steep bumps), trust the geometry.
    if (glm::dot(wo, in.normal) * glm::dot(wo, sp.ng) <= 0.0f) in.normal = sp.ng;
    if (m.clearcoat > 0.0f) fetchCoat(m, textures, sp, wo, in);
    if (m.isTextured()) fetchMaps(m, textures, sp, in);
    return in;
}

} // namespace pt
