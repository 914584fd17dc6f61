// The scene as flat arrays: what loaders produce and what the renderer reads. No scene graph:
// one triangle soup with per-triangle material, a list of cameras, lights and materials.
#pragma once

#include "core/math.h"
#include "environment/environment.h"
#include "scene/material.h"
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

// A light at infinity in one direction (glTF's directional light): irradiance on a surface facing it.
struct DirectionalLight {
    std::string name;
    Vec3 direction{0.0f, 1.0f, 0.0f}; // unit, towards the light
    Spectrum irradiance{1.0f};        // W/m^2
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
