// The one step from a material at a hit to its BSDF: the shading normal after normal or bump
// maps, the shading frame, texture lookups, then the material's model: the lab tree (after the
// Pm rule) collapsed for the outgoing direction, or glTF's metallic-roughness BRDF. Everything a
// material's value depends on at a hit goes through here, so new maps and lobes have one place
// to go; so does its emission, for hits and light samples alike.
#pragma once

#include "material/bsdf.h"
#include "render/surface_point.h"
#include "texture/texture_cache.h"

namespace pt {

// A material evaluated at a hit: the BSDF in the local frame of the shading normal.
struct ShadingPoint {
    Frame frame;
    Vec3 wo;   // outgoing direction in the frame
    Bsdf bsdf;
};

// Radiance a material emits at texture coordinates uv: Ke, times its emission texture (glTF).
inline Spectrum emittedRadiance(const Material& m, const TextureCache& textures, Vec2 uv, const Footprint& footprint) {
    if (!m.emissionMap.used()) return m.emission;
    return m.emission * textures.color(m.emissionMap, uv, footprint);
}

// The shading normal after a normal map (tangent space, y along increasing v) or a bump map
// (the surface displaced along n by -bm * height).
inline Vec3 perturbedNormal(const Material& m, const TextureCache& textures, const SurfacePoint& sp) {
    const Vec3 n = sp.ns;
    Vec3 mapped(0.0f);
    if (m.normalMap.used()) {
        Vec3 c = 2.0f * textures.vector(m.normalMap, sp.uv, sp.footprint) - Vec3(1.0f);
        Vec3 t = sp.tangent;
        if (t == Vec3(0.0f)) t = safeNormalize(sp.dpdu - n * glm::dot(n, sp.dpdu));
        if (t == Vec3(0.0f)) t = Frame(n).s; // no uv direction at all: the map's x and y are arbitrary
        Vec3 b = sp.bitangentSign * glm::cross(n, t);
        Vec2 xy = m.normalMap.bumpScale * normalMapToUv(m.normalMap, Vec2(c.x, c.y));
        mapped = xy.x * t + xy.y * b + c.z * n;
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
    mapped = safeNormalize(mapped);
    return mapped == Vec3(0.0f) || !isFinite(mapped) ? n : mapped;
}

// `wo` points back along the arriving ray. For textured materials `sp` must carry its texture
// coordinates (addTextureCoordinates).
inline ShadingPoint evaluateMaterial(const Material& m, const TextureCache& textures, const SurfacePoint& sp,
                                     const Vec3& wo, HemisphereSampling hemisphere) {
    Vec3 n = m.perturbsNormal() ? perturbedNormal(m, textures, sp) : sp.ns;
    // Where interpolated or mapped normals put the viewer behind the surface that the geometry
    // shows (silhouettes of smooth meshes, steep bumps), trust the geometry.
    if (glm::dot(wo, n) * glm::dot(wo, sp.ng) <= 0.0f) n = sp.ng;
    ShadingPoint s;
    if (m.model == MaterialModel::MetalRough) {
        Spectrum base = m.kd;
        float alpha = m.roughness, metallic = std::max(0.0f, m.metallic);
        if (m.isTextured()) {
            // glTF's textures multiply its factors: roughness = factor * G, so alpha = factor^2 G^2.
            if (m.kdMap.used()) base *= textures.color(m.kdMap, sp.uv, sp.footprint);
            if (m.vertexColors) base *= sp.color;
            if (m.roughnessMap.used()) alpha *= sqr(std::clamp(textures.scalar(m.roughnessMap, sp.uv, sp.footprint), 0.0f, 1.0f));
            if (m.metallicMap.used()) metallic *= std::clamp(textures.scalar(m.metallicMap, sp.uv, sp.footprint), 0.0f, 1.0f);
        }
        if (m.transparency > 0.0f) {
            // KHR_materials_transmission: the lab tree's FresnelBlend over refraction (with the
            // ior) and Lambert, its refraction tinted by the base colour; metal does not transmit.
            // The frame keeps the outside, which refraction needs.
            s.frame = Frame(n);
            s.wo = s.frame.toLocal(wo);
            LabParameters p = labParameters(m, base, base, alpha, metallic);
            p.transparency *= 1.0f - metallic;
            p.refractTint = base;
            s.bsdf = LabBsdf::make(p, s.wo.z, hemisphere);
            return s;
        }
        // Opaque and two-sided: the frame turns to the side wo arrives from.
        if (glm::dot(wo, n) < 0.0f) n = -n;
        s.frame = Frame(n);
        s.wo = s.frame.toLocal(wo);
        s.bsdf = MetalRoughBsdf::make(base, metallic, alpha, m.eta, s.wo.z, m.ks, m.specular);
        return s;
    }
    s.frame = Frame(n);
    s.wo = s.frame.toLocal(wo);
    if (!m.isTextured()) {
        s.bsdf = LabBsdf::make(labParameters(m, m.kd), s.wo.z, hemisphere);
        return s;
    }
    Spectrum kd = m.kd, ks = m.ks;
    float alpha = m.roughness, metallic = m.metallic;
    if (m.kdMap.used()) kd *= textures.color(m.kdMap, sp.uv, sp.footprint);
    if (m.ksMap.used()) ks *= textures.color(m.ksMap, sp.uv, sp.footprint);
    if (m.roughnessMap.used()) alpha = sqr(std::clamp(textures.scalar(m.roughnessMap, sp.uv, sp.footprint), 0.0f, 1.0f));
    if (m.metallicMap.used()) metallic = std::clamp(textures.scalar(m.metallicMap, sp.uv, sp.footprint), 0.0f, 1.0f);
    s.bsdf = LabBsdf::make(labParameters(m, kd, ks, alpha, metallic), s.wo.z, hemisphere);
    return s;
}

} // namespace pt
