// What accel.cpp and ray_replay.cpp share inside accel/: the Embree scene behind Accel, its
// geometries and ray masks, and the helpers that fill Embree's ray structs. Not for use outside
// accel/, the only code that includes Embree's headers.
#pragma once

#include "accel/accel.h"

#include <embree3/rtcore.h>

#include <string>
#include <vector>

namespace pt {

constexpr unsigned kOpaqueGeometry = 0, kCutoutGeometry = 1, kSphereGeometry = 2;
constexpr unsigned kCameraRay = 1u << 1, kAnyRay = 0xFFFFFFFFu & ~kCameraRay;

// Triangles of materials with a cutout (map_d) sit in a geometry of their own whose filter
// function drops hits where the surface is not there; the opaque rest has no filter and pays
// nothing. Coverage between 0 and 1 is a coin flip keyed on the hit and the ray, so an image does
// not depend on which thread traced what. Unlit materials (glTF KHR_materials_unlit) sit there
// too: only camera rays see them, as Blender's importer has it; every other ray passes.
// Camera rays carry kCameraRay in their mask (every geometry's mask is all ones, so masks
// select nothing else).
// Single-sided opaque surfaces (glTF doubleSided false, Material::cullsBackFaces) sit there as
// well: a camera ray's hit on a back face, by the triangle's winding, is dropped.
struct Cutouts {
    enum Flag : uint8_t { kCutout = 1, kUnlit = 2, kCullBack = 4 };
    const Scene* scene = nullptr;
    std::vector<uint32_t> triangle; // primitive of the cutout geometry -> scene triangle
    std::vector<uint8_t> flags;     // and its Flags
};

// Sphere lights (radius > 0), tested exactly by intersectSphere. A few are tested one by one after
// each Embree query; more go into the BVH as an Embree user geometry, which culls them like
// triangles. Both are needed: the loop costs every ray time in proportion to the number of lights
// (five times slower with 257 of them), while a user geometry moves Embree to its slower
// mixed-geometry traversal for every ray (+1,300 instructions per path on cornellbottle2).
constexpr size_t kSpheresLooped = 8;

struct Spheres {
    std::vector<glm::vec4> centerRadius;
    std::vector<uint32_t> light; // primitive -> index in Scene::lights
    bool inBvh = false;
};

// The context of a shadow query: Embree's, and the sphere light the ray is aimed at (not a blocker).
struct QueryContext {
    RTCIntersectContext embree;
    int skipLight = -1;
};

struct Accel::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;
    // Scene triangle of each primitive, per geometry; empty: the identity (no cutouts).
    std::vector<uint32_t> opaqueTriangle;
    Cutouts cutouts;
    Spheres spheres;
};

inline void fillRay(RTCRay& r, const Ray& ray, float tfar) {
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.dir.x;
    r.dir_y = ray.dir.y;
    r.dir_z = ray.dir.z;
    r.tnear = 0.0f;
    r.tfar = tfar;
    r.time = 0.0f;
    r.mask = kAnyRay; // Debian's Embree is built with ray masks
    r.id = 0;
    r.flags = 0;
}

// Lane `i` of a packet of 8 rays, with no hit yet.
inline void fillPacketLane(RTCRayHit8& packet, int i, const Vec3& origin, const Vec3& dir, float tfar) {
    RTCRay8& p = packet.ray;
    p.org_x[i] = origin.x, p.org_y[i] = origin.y, p.org_z[i] = origin.z;
    p.dir_x[i] = dir.x, p.dir_y[i] = dir.y, p.dir_z[i] = dir.z;
    p.tnear[i] = 0.0f, p.tfar[i] = tfar, p.time[i] = 0.0f;
    p.mask[i] = kAnyRay | kCameraRay, p.id[i] = 0, p.flags[i] = 0; // packets carry camera rays
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
}

} // namespace pt
