// Every emitter of a scene in one list: sphere lights, point lights, emissive triangles, an
// environment map, the sun and directional lights. Next-event estimation chooses one by power,
// or, with many bounded emitters, the distant ones by power and the bounded ones through a light
// tree that weighs them as seen from the shading point. Built once per render.
#pragma once

#include "core/math.h"
#include "light/environment_light.h"
#include "light/light_tree.h"
#include "sampling/distribution1d.h"
#include "scene/scene.h"

#include <memory>
#include <vector>

namespace pt {

struct Emitter {
    enum class Kind : uint8_t { Sphere, Point, Triangle, Environment, Sun, Directional };
    Kind kind;
    uint32_t index;    // into Scene::lights, or a triangle index
    Vec3 center{0.0f}; // sphere and point lights; the sun and directional lights: their direction
    float radius = 0.0f; // sphere lights; the sun: 1 - cos of its angular radius
    Spectrum radiance{0.0f}; // sphere: I / (pi r^2); point: intensity I; triangle: Le; sun: its disk's;
                             // directional: irradiance; environment: unused
};

// A point on a light seen from a shading point, with what a shadow ray needs to reach it.
struct LightSample {
    Vec3 wi;              // unit direction from the shading point to the light
    float distance = 0.0f; // to the sampled point (for spheres: to the sphere's surface; environment, sun: inf)
    Spectrum radiance;    // emitted radiance towards the shading point; for point lights I / d^2
    float pdf = 0.0f;     // solid-angle density, emitter choice excluded; 0 means no sample
    bool delta = false;   // point and directional lights: cannot be hit by BSDF sampling
    // For triangles: the point, its error bound and normal, to offset the shadow ray's end.
    Vec3 point, normal;
    float pointError = 0.0f;
};

class LightSet {
public:
    explicit LightSet(const Scene& scene, LightChoice choice = LightChoice::Auto);

    bool empty() const { return emitters_.empty(); }
    size_t size() const { return emitters_.size(); }
    const Emitter& emitter(size_t i) const { return emitters_[i]; }

    // Picks an emitter for next-event estimation at p, whose shading normal is n (0: none).
    // Returns ~0u with pmf 0 when the tree finds no emitter that can light p.
    uint32_t choose(float u, const Vec3& p, const Vec3& n, float& pmf) const {
        if (emitters_.size() == 1) { // the common case of one lab light: no search
            pmf = 1.0f;
            return 0;
        }
        if (!usesTree()) return uint32_t(distribution_.sample(u, &pmf));
        return chooseFromTree(u, p, n, pmf);
    }
    // The probability that choose() at p picks emitter i.
    float pmf(size_t i, const Vec3& p, const Vec3& n) const {
        if (emitters_.size() == 1) return 1.0f;
        return usesTree() ? pmfFromTree(i, p, n) : distribution_.pmf(i);
    }
    bool usesTree() const { return !tree_.empty(); }

    // Emitter index of a sphere light or an emissive triangle, for MIS when a BSDF ray hits it.
    uint32_t emitterOfLight(uint32_t lightIndex) const { return lightEmitter_[lightIndex]; }
    uint32_t emitterOfTriangle(uint32_t prim) const { return triangleEmitter_[prim]; }
    // Emitter index of the environment map, or ~0u when the environment is the lab's two tones
    // (not a light: BSDF sampling alone reaches it, as in the lab).
    uint32_t environmentEmitter() const { return environmentEmitter_; }
    // Emitter index of the sun's disk, or ~0u without one.
    uint32_t sunEmitter() const { return sunEmitter_; }

    // Samples a point on emitter i as seen from p.
    LightSample sample(size_t i, const Vec3& p, Vec2 u) const;
    // Solid-angle density with which sample() picks direction wi from p towards emitter i, given
    // that it hits the emitter at distance `distance` (emitter choice excluded).
    float pdf(size_t i, const Vec3& p, const Vec3& wi, float distance) const;

    // The spot cone and range falloff of a point light (1 for the lab's lights).
    static float punctualFalloff(const SphereLight& l, const Vec3& wi, float distance);

private:
    uint32_t chooseFromTree(float u, const Vec3& p, const Vec3& n, float& pmf) const;
    float pmfFromTree(size_t i, const Vec3& p, const Vec3& n) const;
    LightBounds boundsOf(const Emitter& e, double power) const;

    const Scene& scene_;
    std::vector<Emitter> emitters_;
    Distribution1D distribution_; // all emitters by power
    // With a tree: the bounded emitters (indices below boundedCount_) are its leaves, and the
    // distant ones (from boundedCount_ on) compete with the tree as a whole at each point, by
    // an estimate of the irradiance each sends there (see chooseFromTree).
    struct DistantEstimate {
        Vec3 direction{0.0f}; // towards the light, for the receiver's cosine; 0: none (environment)
        float irradiance = 0.0f;
    };
    float distantWeight(size_t j, const Vec3& n) const;
    float treeWeight(const Vec3& p, const Vec3& n) const;
    // The weights at a point that chooseFromTree and pmfFromTree both divide up.
    struct TopChoice {
        float treeWeight = 0.0f, sum = 0.0f, items = 0.0f;
        float probability(float w) const { return sum > 0.0f ? 0.5f * w / sum + 0.5f / items : 1.0f / items; }
    };
    TopChoice topChoice(const Vec3& p, const Vec3& n) const;
    LightTree tree_;
    std::vector<DistantEstimate> distant_;
    uint32_t boundedCount_ = 0;
    std::vector<uint32_t> lightEmitter_;
    std::vector<uint32_t> triangleEmitter_; // empty unless the scene has emissive triangles
    std::unique_ptr<EnvironmentMap> skyDensity_; // the Preetham sky, baked: what samples it
    std::unique_ptr<EnvironmentLight> environment_;
    uint32_t environmentEmitter_ = ~0u;
    uint32_t sunEmitter_ = ~0u;
};

} // namespace pt
