// Every emitter of a scene in one list (light/emitter.h): sphere lights, point and spot lights,
// emissive triangles, an environment map or sky, the sun and directional lights, with the
// chooser that next-event estimation picks one by (light/light_chooser.h). Built once per render.
#pragma once

#include "core/math.h"
#include "light/emitter.h"
#include "light/environment_light.h"
#include "light/light_chooser.h"
#include "scene/scene.h"

#include <memory>
#include <vector>

namespace pt {

class LightSet {
public:
    explicit LightSet(const Scene& scene, LightChoice choice = LightChoice::Auto);

    bool empty() const { return emitters_.empty(); }
    size_t size() const { return emitters_.size(); }
    const Emitter& emitter(size_t i) const { return emitters_[i]; }

    // Picks an emitter for next-event estimation at p, whose shading normal is n (0: none).
    // Returns ~0u with pmf 0 when the tree finds no emitter that can light p.
    uint32_t choose(float u, const Vec3& p, const Vec3& n, float& pmf) const { return chooser_.choose(u, p, n, pmf); }
    // The probability that choose() at p picks emitter i.
    float pmf(size_t i, const Vec3& p, const Vec3& n) const { return chooser_.pmf(i, p, n); }
    bool usesTree() const { return chooser_.usesTree(); }

    // Emitter index of a sphere light or an emissive triangle, for MIS when a BSDF ray hits it.
    uint32_t emitterOfLight(uint32_t lightIndex) const { return lightEmitter_[lightIndex]; }
    uint32_t emitterOfTriangle(uint32_t prim) const { return triangleEmitter_[prim]; }
    // Emitter index of the environment map, or ~0u when the environment is the lab's two tones
    // (not a light: BSDF sampling alone reaches it, as in the lab).
    uint32_t environmentEmitter() const { return environmentEmitter_; }
    // Emitter index of the sun's disk, or ~0u without one.
    uint32_t sunEmitter() const { return sunEmitter_; }

    // Samples a point on emitter i as seen from p.
    LightSample sample(size_t i, const Vec3& p, Vec2 u) const {
        return std::visit([&](const auto& e) { return e.sample(p, u); }, emitters_[i]);
    }
    // Solid-angle density with which sample() picks direction wi from p towards emitter i, given
    // that it hits the emitter at distance `distance` (emitter choice excluded).
    float pdf(size_t i, const Vec3& p, const Vec3& wi, float distance) const {
        return std::visit([&](const auto& e) { return e.pdf(p, wi, distance); }, emitters_[i]);
    }

private:
    std::vector<Emitter> emitters_; // the bounded ones (spheres, points, triangles) first
    LightChooser chooser_;
    std::vector<uint32_t> lightEmitter_;
    std::vector<uint32_t> triangleEmitter_; // empty unless the scene has emissive triangles
    std::unique_ptr<EnvironmentMap> skyDensity_; // the Preetham sky, baked: what samples it
    std::unique_ptr<EnvironmentLight> environment_;
    uint32_t environmentEmitter_ = ~0u;
    uint32_t sunEmitter_ = ~0u;
};

} // namespace pt
