// A material as its file gives it (factors and texture maps), the one table of its maps, and what
// those maps give at a hit.
#pragma once

#include "core/color.h"
#include "core/math.h"
#include "texture/texture.h"

#include <cstdint>
#include <string>

namespace pt {

// Which BSDF a material is: the lab's tree (OBJ + MTL), or glTF 2.0's metallic-roughness BRDF
// (material/metal_rough_bsdf.h), whose base colour is kd, alpha roughness, metallic and eta its
// ior, each texture multiplying its factor; ks and specular are KHR_materials_specular's colour
// and weight, transparency KHR_materials_transmission's factor.
enum class MaterialModel : uint8_t { Lab, MetalRough };

// A material as its file gives it; material/evaluate_material.h turns it into a BSDF at a hit.
// Parameters of the lab material tree (see material/lab_bsdf.h for how they combine):
//   f  = w * FresnelBlend(R0)[reflect: Spec(Ks), otherwise: B1] + (1 - w) * B1
//   B1 = T * Refr(eta) + (1 - T) * Diffuse(Kd)
struct Material {
    // The factors first, maps after: a hit on an untextured material reads the first cache lines only.
    MaterialModel model = MaterialModel::Lab;
    bool volume = false;          // glTF KHR_materials_volume: the mesh bounds a volume that refracting paths enter
    bool vertexColors = false;    // glTF COLOR_0 multiplies kd (Scene::vertexColors)
    bool unlit = false;           // glTF KHR_materials_unlit: camera rays see kd, nothing else sees it
    bool singleSided = false;     // glTF doubleSided false: cullsBackFaces() says what that does
    Spectrum kd{0.7f};            // Lambert reflectance (Kd, diffuseReflectance)
    Spectrum ks{1.0f};            // mirror colour (Ks, specularReflectance)
    Spectrum r0{0.0f};            // Fresnel reflectance at normal incidence (reflat0deg)
    float blend = 0.0f;           // w, weight of the Fresnel blend (reflat90deg)
    float transparency = 0.0f;    // T (transparency, Tr, 1 - d)
    float eta = 1.0f;             // index of refraction inside the surface (Ni)
    float roughnessAlpha = 0.001f; // GGX alpha, not perceptual roughness (specularroughness, or Pr^2); <= 0.001 is smooth
    float metallic = -1.0f;       // Pm in [0, 1], applied when the material is evaluated; < 0: not given
    float coverage = 1.0f;        // multiplies map_d's coverage (d, where map_d is given; glTF's base alpha)
    float alphaCutoff = -1.0f;    // >= 0: coverage is 1 at or above it and 0 below (glTF MASK)
    float specular = 1.0f;        // glTF KHR_materials_specular's specularFactor
    float clearcoat = 0.0f;       // glTF KHR_materials_clearcoat: the coat's weight (clearcoatFactor)
    float clearcoatAlpha = 0.0f;  // and its GGX alpha (clearcoatRoughnessFactor^2)
    Spectrum sheenColor{0.0f};    // glTF KHR_materials_sheen (black: no sheen)
    float sheenRoughness = 0.0f;  // and its roughness (the Charlie distribution's alpha)
    Spectrum attenuation{0.0f};   // the volume's absorption coefficient per unit length (0: clear)
    Spectrum emission{0.0f};      // emitted radiance, both sides (Ke, emittance)
    TextureMap kdMap;             // multiplies kd (map_Kd), with its -s, -o and -clamp options
    TextureMap ksMap;             // multiplies ks (map_Ks, glTF specularColorTexture)
    TextureMap roughnessMap;      // perceptual roughness: alpha = value^2 (map_Pr)
    TextureMap metallicMap;       // metallic, replacing Pm (map_Pm)
    TextureMap normalMap;         // tangent-space normal map (norm)
    TextureMap bumpMap;           // height map, height = -bm * value (bump, map_bump)
    TextureMap alphaMap;          // coverage = coverage * value (map_d); rays pass the rest
    TextureMap emissionMap;       // multiplies emission (glTF emissiveTexture)
    TextureMap clearcoatMap;          // R multiplies clearcoat
    TextureMap clearcoatRoughnessMap; // G multiplies the coat's roughness
    TextureMap clearcoatNormalMap;    // the coat's own tangent-space normal map
    TextureMap specularMap;       // A multiplies specular (glTF specularTexture; its colour is ksMap)
    TextureMap transmissionMap;   // R multiplies transparency (glTF transmissionTexture)
    TextureMap sheenColorMap;     // multiplies sheenColor
    TextureMap sheenRoughnessMap; // A multiplies sheenRoughness
    std::string name;

    bool isEmissive() const { return !isBlack(emission); }
    // A single-sided opaque surface is not seen from behind (the side its winding turns away,
    // glTF's back-face culling): camera rays pass its back. Every other ray sees both sides, so
    // that light transport stays that of a surface (docs/gltf.md says why). A transmitting one
    // keeps both sides for the camera too: refraction through a closed mesh leaves by its back.
    bool cullsBackFaces() const { return singleSided && transparency == 0.0f && !volume; }
    bool hasCutout() const { return alphaMap.used(); }
    bool perturbsNormal() const { return normalMap.used() || bumpMap.used(); }
    // Whether shading reads a map of it or vertex colours (and so needs texture coordinates).
    bool isTextured() const;
};

// What a material's maps give at one hit, before any model's rules. A value whose map the
// material does not have keeps its default: the model step (lab_bsdf.h, metal_rough_bsdf.h)
// reads the material's own factor there.
struct SurfaceInputs {
    Vec3 normal{0.0f, 0.0f, 1.0f}; // shading normal after the normal or bump map, on the geometric side of wo
    Spectrum kd{1.0f};              // map_Kd / baseColorTexture times vertex colours
    Spectrum ks{1.0f};              // map_Ks / specularColorTexture
    float specular = 1.0f;          // specularTexture A
    float transmission = 1.0f;      // transmissionTexture R
    Spectrum sheenColor{1.0f};      // sheenColorTexture
    float sheenRoughness = 1.0f;    // sheenRoughnessTexture A
    float roughness = 1.0f;         // map_Pr / metallicRoughness G, in [0, 1] (perceptual: alpha = value^2)
    float metallic = 1.0f;          // map_Pm / metallicRoughness B, in [0, 1]
    float clearcoat = 1.0f;         // clearcoatTexture R
    float clearcoatRoughness = 1.0f; // clearcoatRoughnessTexture G (perceptual)
    Vec3 clearcoatNormal{0.0f};     // the coat's normal (its own map, else the interpolated one); set where clearcoat > 0
};

// How the texture fetch (material/surface_inputs.h) reads a map: a colour or a value in [0, 1]
// into the SurfaceInputs field named, or by code of its own (normal and bump maps, the coat's
// maps, read only where the material has a coat; coverage, read by the cutout filter; emission).
enum class MapFetch : uint8_t { Color, Unit, Own };

struct MaterialMapEntry {
    TextureMap Material::*map;
    const char* what; // what messages call it
    MapFetch fetch;
    Spectrum SurfaceInputs::*color = nullptr; // MapFetch::Color
    float SurfaceInputs::*unit = nullptr;     // MapFetch::Unit
    bool shading = true;                      // read while shading (all but coverage)
};

// Every texture map a material can have, once: the loaders' checks, the fetch and isTextured
// all go through it. A new map: its field in Material, its line here, its loader keys.
inline constexpr MaterialMapEntry kMaterialMaps[] = {
    {&Material::kdMap, "diffuse or base colour", MapFetch::Color, &SurfaceInputs::kd},
    {&Material::ksMap, "specular colour", MapFetch::Color, &SurfaceInputs::ks},
    {&Material::roughnessMap, "roughness", MapFetch::Unit, nullptr, &SurfaceInputs::roughness},
    {&Material::metallicMap, "metallic", MapFetch::Unit, nullptr, &SurfaceInputs::metallic},
    {&Material::normalMap, "normal", MapFetch::Own},
    {&Material::bumpMap, "bump", MapFetch::Own},
    {&Material::alphaMap, "coverage", MapFetch::Own, nullptr, nullptr, false},
    {&Material::emissionMap, "emission", MapFetch::Own},
    {&Material::clearcoatMap, "clear coat", MapFetch::Own},
    {&Material::clearcoatRoughnessMap, "clear coat roughness", MapFetch::Own},
    {&Material::clearcoatNormalMap, "clear coat normal", MapFetch::Own},
    {&Material::specularMap, "specular", MapFetch::Unit, nullptr, &SurfaceInputs::specular},
    {&Material::transmissionMap, "transmission", MapFetch::Unit, nullptr, &SurfaceInputs::transmission},
    {&Material::sheenColorMap, "sheen colour", MapFetch::Color, &SurfaceInputs::sheenColor},
    {&Material::sheenRoughnessMap, "sheen roughness", MapFetch::Unit, nullptr, &SurfaceInputs::sheenRoughness},
};

inline bool Material::isTextured() const {
    if (vertexColors) return true;
    for (const MaterialMapEntry& e : kMaterialMaps)
        if (e.shading && (this->*e.map).used()) return true;
    return false;
}

} // namespace pt
