// The emitters of the light set, one small struct per kind, each sampling a point on itself as
// seen from a shading point and giving the density of that choice. They are what the light set
// holds; the scene's own description of them is scene/scene.h (LocalLight, DirectionalLight,
// the emissive materials) and environment/ (the map, the sky, the sun's disk). A kind is one
// alternative of the Emitter variant: LightSet::sample and ::pdf dispatch with one visit.
#pragma once

#include "core/math.h"
#include "environment/sun_disk.h"
#include "light/environment_light.h"
#include "light/light_tree.h"
#include "sampling/warp.h"

#include <variant>

namespace pt {

struct Scene;
struct PreethamSky;

// What an emitter is, for the code that handles its samples.
enum EmitterFlags : uint8_t {
    kEmitterDeltaPosition = 1,  // a point: no BSDF-sampled ray ever hits it
    kEmitterDeltaDirection = 2, // a single direction at infinity: likewise
    kEmitterInfinite = 4,       // at infinity: its shadow rays run without end
    kEmitterSurface = 8,        // a point on a triangle: the shadow ray ends at that point, offset
};

// A point on a light seen from a shading point, with what a shadow ray needs to reach it.
struct LightSample {
    Vec3 wi;               // unit direction from the shading point to the light
    float distance = 0.0f; // to the sampled point (for spheres: to the sphere's surface; at infinity: inf)
    Spectrum radiance;     // emitted radiance towards the shading point; for point lights I / d^2
    float pdf = 0.0f;      // solid-angle density, emitter choice excluded; 0 means no sample
    uint8_t flags = 0;     // the emitter's EmitterFlags
    int skipLight = -1;    // a sphere light the shadow ray may not stop at (the one it aims for)
    // kEmitterSurface: the point, its error bound and normal, to offset the shadow ray's end.
    Vec3 point, normal;
    float pointError = 0.0f;

    bool isDelta() const { return flags & (kEmitterDeltaPosition | kEmitterDeltaDirection); }
};

// A sphere of uniform radiance (the lab's light), sampled by the solid angle of its visible cap.
struct SphereEmitter {
    static constexpr uint8_t kFlags = 0;
    Vec3 center{0.0f};
    float radius = 0.0f;
    Spectrum radiance{0.0f}; // intensity / (pi r^2)
    uint32_t light = 0;      // into Scene::lights

    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3& p, const Vec3& wi, float distance) const;
    LightBounds bounds() const;
};

// A point light of radiant intensity I, with KHR_lights_punctual's spot cone and range.
struct PointEmitter {
    static constexpr uint8_t kFlags = kEmitterDeltaPosition;
    Vec3 position{0.0f};
    Spectrum intensity{0.0f};
    Vec3 spotDirection{0.0f, 0.0f, -1.0f};
    float cosInner = 1.0f, cosOuter = 1.0f; // 1, 1: no cone
    float range = 0.0f;                      // 0: infinite

    bool isSpot() const { return cosOuter < 1.0f; }
    // The spot's smooth falloff from the inner to the outer cone, and the window that ends the
    // light at its range (the extension's recommended (1 - (d / range)^4)^2); 1 for neither.
    float falloff(const Vec3& wi, float distance) const;
    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3&, const Vec3&, float) const { return 0.0f; }
    LightBounds bounds() const;
};

// An emissive triangle (both sides emit), sampled uniformly by area.
struct TriangleEmitter {
    static constexpr uint8_t kFlags = kEmitterSurface;
    uint32_t triangle = 0;
    Vec3 a{0.0f}, b{0.0f}, c{0.0f};
    Spectrum radiance{0.0f};       // the material's emission, before its texture
    const Scene* scene = nullptr; // for the emission texture

    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3& p, const Vec3& wi, float distance) const;
    LightBounds bounds() const;
};

// An environment map, or the Preetham sky through the map of it baked as its density.
struct EnvironmentEmitter {
    static constexpr uint8_t kFlags = kEmitterInfinite;
    const EnvironmentLight* light = nullptr;
    const PreethamSky* preetham = nullptr; // the sky's radiance comes from the model, not the map

    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3&, const Vec3& wi, float) const { return light->pdf(wi); }
};

// The sun's disk, sampled uniformly over its cone.
struct SunEmitter {
    static constexpr uint8_t kFlags = kEmitterInfinite;
    SunDisk disk;

    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3&, const Vec3& wi, float) const {
        return disk.covers(wi) ? uniformConePdf(disk.oneMinusCosRadius) : 0.0f;
    }
};

// A light at infinity in one direction (glTF's directional light).
struct DirectionalEmitter {
    static constexpr uint8_t kFlags = kEmitterInfinite | kEmitterDeltaDirection;
    Vec3 direction{0.0f, 1.0f, 0.0f}; // unit, towards the light
    Spectrum irradiance{0.0f};

    LightSample sample(const Vec3& p, Vec2 u) const;
    float pdf(const Vec3&, const Vec3&, float) const { return 0.0f; }
};

using Emitter = std::variant<SphereEmitter, PointEmitter, TriangleEmitter, EnvironmentEmitter, SunEmitter, DirectionalEmitter>;

inline uint8_t emitterFlags(const Emitter& e) {
    return std::visit([](const auto& x) { return x.kFlags; }, e);
}

} // namespace pt
