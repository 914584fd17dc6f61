// The one step from a material at a hit to its BSDF, in three: the texture fetch
// (surface_inputs.h: shading normal and every map), the model's parameters from the material and
// those inputs (the lab tree after the Pm rule, or glTF's metallic-roughness), then the BSDF made
// from the parameters for the outgoing direction (lab_bsdf.h, metal_rough_bsdf.h), which
// evaluates, samples and gives densities. New maps go into the fetch, new lobes into a model's
// parameters. The BSDF is read nowhere else; a material's other properties are, where they are
// not the BSDF's: its emission (scene/emission.h: the path loop and the light set), its coverage
// (accel.cpp's cutout filter), unlit and volume (the path loop).
#pragma once

#include "material/bsdf.h"
#include "material/surface_inputs.h"

namespace pt {

// A material evaluated at a hit: the BSDF in the local frame of the shading normal.
struct ShadingPoint {
    Frame frame;
    Vec3 wo;   // outgoing direction in the frame
    Bsdf bsdf;
    // The frame's normal was turned to the side of wo, away from the surface's outside (an opaque
    // glTF surface seen from behind): the side tests of the path loop must turn the geometric
    // normal with it.
    bool turned = false;
};

// Step 2, lab model: the material's factors, replaced (Pr, Pm) or multiplied (Kd, Ks) by its maps.
inline LabParameters labParameters(const Material& m, const SurfaceInputs& in) {
    return labParameters(m, m.kd * in.kd, m.ks * in.ks, m.roughnessMap.used() ? sqr(in.roughness) : m.roughnessAlpha,
                         m.metallicMap.used() ? in.metallic : m.metallic);
}

// Step 2, glTF model: textures multiply factors; roughness = factor * G, so alpha = factor^2 G^2
// (the sheen's roughness is its alpha as it is).
inline MetalRoughParameters metalRoughParameters(const Material& m, const SurfaceInputs& in) {
    MetalRoughParameters p{m.kd * in.kd,  std::max(0.0f, m.metallic) * in.metallic, m.roughnessAlpha * sqr(in.roughness),
                           m.eta,         m.ks * in.ks,
                           m.specular * in.specular, m.clearcoat * in.clearcoat,
                           m.clearcoatAlpha * sqr(in.clearcoatRoughness)};
    p.sheenColor = m.sheenColor * in.sheenColor;
    p.sheenRoughness = m.sheenRoughness * in.sheenRoughness;
    return p;
}

// KHR_materials_transmission: the specification's mix, by metallic, of a metal (mirror with the
// base colour's Fresnel) and a dielectric whose Fresnel lies over transmission T (refraction
// with the ior, or straight through a thin wall where the material bounds no volume, tinted by
// the base colour) and (1 - T) Lambert. As the lab tree: the mirror's weight is Schlick of the
// mixed F0 (Schlick is linear in F0: the mix of the two Fresnels); refraction and Lambert share
// the dielectric's part that its own Fresnel does not reflect, (1 - metallic)(1 - F). Metal
// transmits nothing and has no diffuse lobe: a glass of metallic 0.5 is half mirror, half glass.
inline LabParameters transmissionParameters(const Material& m, const MetalRoughParameters& p, const SurfaceInputs& in) {
    LabParameters lab = labParameters(m, p.baseColor, p.baseColor, p.alpha, p.metallic);
    lab.transparency *= in.transmission;
    lab.kd = p.baseColor;
    lab.metalShare = p.metallic;
    lab.dielectricR0 = sqr((m.eta - 1.0f) / (m.eta + 1.0f));
    lab.refractTint = p.baseColor;
    lab.thin = !m.volume; // the specification: without a volume the surface is a thin wall
    return lab;
}

// `wo` points back along the arriving ray. For textured materials `sp` must carry its texture
// coordinates (addTextureCoordinates).
inline ShadingPoint evaluateMaterial(const Material& m, const TextureCache& textures, const SurfacePoint& sp,
                                     const Vec3& wo, HemisphereSampling hemisphere) {
    const SurfaceInputs in = fetchSurfaceInputs(m, textures, sp, wo);
    Vec3 n = in.normal;
    ShadingPoint s;
    if (m.model == MaterialModel::MetalRough) {
        MetalRoughParameters p = metalRoughParameters(m, in);
        // Opaque surfaces are two-sided: the frame turns to the side wo arrives from. A
        // transmitting one keeps the outside, which refraction needs.
        const bool transmits = m.transparency > 0.0f;
        const bool flip = !transmits && glm::dot(wo, n) < 0.0f;
        if (flip) n = -n;
        s.turned = flip;
        s.frame = Frame(n);
        s.wo = s.frame.toLocal(wo);
        if (p.clearcoat > 0.0f) { // the coat's normal in the frame, turned with it
            p.clearcoatNormal = s.frame.toLocal(flip ? -in.clearcoatNormal : in.clearcoatNormal);
            if (!(p.clearcoatNormal.z > 0.0f)) p.clearcoatNormal = Vec3(0.0f, 0.0f, 1.0f);
        }
        if (transmits) s.bsdf.initLab(transmissionParameters(m, p, in), s.wo.z, hemisphere);
        else s.bsdf.initMetalRough(p, s.wo);
        return s;
    }
    s.frame = Frame(n);
    s.wo = s.frame.toLocal(wo);
    s.bsdf.initLab(labParameters(m, in), s.wo.z, hemisphere);
    return s;
}

} // namespace pt
