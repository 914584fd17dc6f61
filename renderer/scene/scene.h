// The scene as flat arrays: what loaders produce and what the renderer reads. No scene graph:
// one triangle soup with per-triangle material, a list of cameras, lights and materials.
#pragma once

#include "core/math.h"
#include "environment/environment.h"
#include "texture/texture_cache.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pt {

// A camera looking from position at target: a pinhole whose vertical field of view is fovY
// degrees, or, with orthoHalfHeight > 0, orthographic (glTF's orthographic cameras).
struct Camera {
    std::string name;
    Vec3 position{0.0f, 0.0f, 0.0f};
    Vec3 target{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = 45.0f;
    float aspect = 0.0f;          // width / height the file asks for (glTF); 0: none, --res decides
    float orthoHalfHeight = 0.0f; // > 0: orthographic, seeing this far above and below the axis (glTF ymag)
};

// A light at a place in the scene: the lab's sphere of radius r emitting uniform radiance
// intensity / (pi r^2), so a facing point at distance d from the centre receives irradiance
// intensity / d^2; or, with radius 0, a point light of radiant intensity `intensity` (W/sr),
// which glTF may make a spot and give a range. The light set makes each a SphereEmitter or a
// PointEmitter (light/emitter.h).
struct LocalLight {
    std::string name;
    Vec3 center{0.0f};
    float radius = 0.0f;
    Spectrum intensity{1.0f}; // lightintensity * lightcolor
    std::string source;       // "file:line: " of its lightintensity (or newlight), for messages
    std::string radiusSource; // same for lightradius
    const char* intensityKeyword = "lightintensity"; // what the file calls its intensity, for messages
    // glTF's KHR_lights_punctual on a point light: a spot cone (cosOuter < 1) with the
    // extension's smooth falloff from cosInner to cosOuter, and a range beyond which it is dark.
    Vec3 spotDirection{0.0f, 0.0f, -1.0f};
    float cosInner = 1.0f, cosOuter = 1.0f; // 1, 1: no cone
    float range = 0.0f;                      // 0: infinite

    bool isPoint() const { return radius <= 0.0f; }
    bool isSpot() const { return cosOuter < 1.0f; }
    Spectrum radiance() const { return intensity / (kPi * radius * radius); }
};

// Which BSDF a material is: the lab's tree (OBJ + MTL), or glTF 2.0's metallic-roughness BRDF
// (material/metal_rough_bsdf.h), whose base colour is kd, alpha roughness, metallic and eta its
// ior, each texture multiplying its factor; ks and specular are KHR_materials_specular's colour
// and weight, transparency KHR_materials_transmission's factor.
enum class MaterialModel : uint8_t { Lab, MetalRough };

// A light at infinity in one direction (glTF's directional light): irradiance on a surface facing it.
struct DirectionalLight {
    std::string name;
    Vec3 direction{0.0f, 1.0f, 0.0f}; // unit, towards the light
    Spectrum irradiance{1.0f};        // W/m^2
};

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
    bool hasCutout() const { return alphaMap.used(); }
    bool perturbsNormal() const { return normalMap.used() || bumpMap.used(); }
    bool isTextured() const {
        return kdMap.used() || ksMap.used() || roughnessMap.used() || metallicMap.used() || perturbsNormal() ||
               emissionMap.used() || vertexColors || clearcoatMap.used() || clearcoatRoughnessMap.used() ||
               clearcoatNormalMap.used() || specularMap.used() || transmissionMap.used() ||
               sheenColorMap.used() || sheenRoughnessMap.used();
    }
};

// A file a scene was made from, with the hash of the bytes pt read from it (io/input_file.h):
// taken when they were read, so a file renamed over while pt loads cannot give a part the
// identity of content it did not use.
struct SourceFile {
    std::string path;
    uint64_t hash = 0;
};

struct Scene {
    std::string path; // file it was loaded from, for messages and metadata
    std::vector<SourceFile> sources; // every file read: the scene, its MTLs, buffers, textures and maps

    // Geometry. Each triangle corner has its own position, normal and uv index, as in OBJ.
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<glm::uvec3> triPositions;
    std::vector<glm::ivec3> triNormals; // -1 where the face has no normals; empty if none has
    std::vector<glm::ivec3> triUvs;     // -1 where the face has no uvs; empty if none has
    std::vector<glm::vec4> vertexTangents; // glTF TANGENT per position (xyz unit, w the bitangent's sign; 0: none); empty if none has
    std::vector<Spectrum> vertexColors; // glTF COLOR_0, per position (white where a mesh has none); empty if none has
    std::vector<uint32_t> triMaterial;

    std::vector<Material> materials;
    std::shared_ptr<TextureCache> textures = std::make_shared<TextureCache>(); // shared by copies
    std::vector<LocalLight> lights;
    std::vector<DirectionalLight> directionalLights;
    std::vector<Camera> cameras;
    Environment environment;

    size_t triangleCount() const { return triPositions.size(); }
    // Texture coordinates at barycentrics (b1, b2) of triangle t; (0, 0) where it has none.
    Vec2 uvAt(size_t t, float b1, float b2) const {
        if (triUvs.empty() || triUvs[t].x < 0) return Vec2(0.0f);
        const glm::ivec3& ti = triUvs[t];
        return (1.0f - b1 - b2) * uvs[ti.x] + b1 * uvs[ti.y] + b2 * uvs[ti.z];
    }
};

} // namespace pt
