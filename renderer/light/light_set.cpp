#include "light/light_set.h"

#include "environment/sky_environment.h"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

namespace pt {
namespace {

// Radius of a sphere about the bounds' centre that holds every triangle and sphere light.
double sceneBoundingRadius(const Scene& scene) {
    Vec3 lo(kInf), hi(-kInf);
    for (const Vec3& p : scene.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (const LocalLight& l : scene.lights) lo = glm::min(lo, l.center - l.radius), hi = glm::max(hi, l.center + l.radius);
    if (!(hi.x >= lo.x)) return 1.0;
    double r = 0.5 * double(glm::length(hi - lo));
    return r > 0.0 ? r : 1.0;
}

// What a distant emitter sends to a point facing it, for the tree's choice against them.
DistantEstimate distantEstimate(const Emitter& e, const EnvironmentLight* environment) {
    DistantEstimate d;
    if (std::holds_alternative<EnvironmentEmitter>(e)) {
        d.irradiance = float(0.25 * environment->radiantIntensityIntegral()); // pi L for a uniform L
    } else if (const SunEmitter* sun = std::get_if<SunEmitter>(&e)) {
        d.direction = sun->disk.direction;
        double radiance = average(sun->disk.radiance);
        d.irradiance = float(radiance * sun->disk.solidAngle());
    } else if (const DirectionalEmitter* light = std::get_if<DirectionalEmitter>(&e)) {
        d.direction = light->direction;
        double radiance = average(light->irradiance);
        d.irradiance = float(radiance);
    }
    return d;
}

// Where a bounded emitter is, where it faces and its power, for the light tree.
LightBounds boundsOf(const Emitter& e, double power) {
    LightBounds b = std::visit([](const auto& x) {
        if constexpr (requires { x.bounds(); }) return x.bounds();
        else return LightBounds{};
    }, e);
    b.phi = float(std::min(power, 1e30));
    return b;
}

} // namespace

LightSet::LightSet(const Scene& scene, LightChoice choice) {
    std::vector<double> power; // in double: 2 pi A Le can pass float's range
    lightEmitter_.resize(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LocalLight& l = scene.lights[i];
        lightEmitter_[i] = uint32_t(emitters_.size());
        if (l.isPoint())
            emitters_.push_back(PointEmitter{l.center, l.intensity, l.spotDirection, l.cosInner, l.cosOuter, l.range});
        else
            emitters_.push_back(SphereEmitter{l.center, l.radius, l.radiance(), uint32_t(i)});
        // 4 pi I for a sphere and a point; a spot sends its intensity into its cone only.
        double solidAngle = l.isSpot() ? 2.0 * kPi * (1.0 - 0.5 * (double(l.cosInner) + l.cosOuter)) : 4.0 * kPi;
        power.push_back(solidAngle * double(average(l.intensity)));
    }
    bool anyEmissive = false;
    for (const Material& m : scene.materials) anyEmissive |= m.isEmissive();
    if (anyEmissive) {
        triangleEmitter_.assign(scene.triangleCount(), ~0u);
        // A triangle given twice is one surface: sampled as two emitters it would send its light
        // twice (a shadow ray to either copy passes the other), so copies share one emitter.
        std::map<std::array<float, 9>, uint32_t> emitterOfCorners;
        // Each material's emission texture mean, once (a texture has millions of texels).
        std::vector<double> emissionMean(scene.materials.size(), -1.0);
        for (size_t t = 0; t < scene.triangleCount(); ++t) {
            const Material& m = scene.materials[scene.triMaterial[t]];
            if (!m.isEmissive()) continue;
            const glm::uvec3& tri = scene.triPositions[t];
            const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]], &c = scene.positions[tri[2]];
            float area = 0.5f * safeLength(glm::cross(b - a, c - a));
            if (!(area > 0.0f)) continue; // degenerate triangles emit nothing and are never hit
            std::array<Vec3, 3> corners = {a, b, c};
            std::sort(corners.begin(), corners.end(), [](const Vec3& p, const Vec3& q) {
                return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
            });
            std::array<float, 9> key;
            for (int k = 0; k < 9; ++k) key[k] = corners[k / 3][k % 3];
            auto [it, isNew] = emitterOfCorners.try_emplace(key, uint32_t(emitters_.size()));
            triangleEmitter_[t] = it->second;
            if (!isNew) continue;
            emitters_.push_back(TriangleEmitter{uint32_t(t), a, b, c, m.emission, &scene});
            // Both sides emit; a textured emitter by its texture's mean (a guess at this triangle's share).
            double& mean = emissionMean[scene.triMaterial[t]];
            if (mean < 0.0) mean = m.emissionMap.used() ? (*scene.textures)[m.emissionMap.texture].mean : 1.0;
            power.push_back(2.0 * kPi * double(area) * double(average(m.emission)) * mean);
        }
    }
    const uint32_t boundedCount = uint32_t(emitters_.size());
    // Distant lights are chosen by the power that crosses the scene's bounding disk, pi R^2 E.
    const double radius = sceneBoundingRadius(scene);
    // The sky's sampling density is baked here, once per render, not when a scene is loaded.
    if (scene.environment.preetham) skyDensity_ = std::make_unique<EnvironmentMap>(bakeSky(*scene.environment.preetham));
    if (const EnvironmentMap* density = skyDensity_ ? skyDensity_.get() : scene.environment.map.get()) {
        environment_ = std::make_unique<EnvironmentLight>(*density);
        // Its power: pi R^2 times the radiance integrated over the sphere.
        double p = kPi * radius * radius * environment_->radiantIntensityIntegral();
        if (p > 0.0) {
            environmentEmitter_ = uint32_t(emitters_.size());
            emitters_.push_back(EnvironmentEmitter{environment_.get(), scene.environment.preetham.get()});
            power.push_back(p);
        }
    }
    if (const auto& sun = scene.environment.sun; sun && !isBlack(sun->radiance)) {
        // As for the map: pi R^2 times the radiance integrated over the disk.
        sunEmitter_ = uint32_t(emitters_.size());
        emitters_.push_back(SunEmitter{*sun});
        power.push_back(kPi * radius * radius * double(sun->solidAngle()) * double(average(sun->radiance)));
    }
    for (const DirectionalLight& d : scene.directionalLights) {
        emitters_.push_back(DirectionalEmitter{d.direction, d.irradiance});
        power.push_back(kPi * radius * radius * double(average(d.irradiance)));
    }

    // The tree serves many bounded emitters, or bounded ones beside distant ones: choosing
    // between a spot and the sun by power alone weighs the sun by the whole scene's disk.
    size_t distantCount = emitters_.size() - boundedCount;
    bool tree = choice == LightChoice::Tree ? boundedCount >= 1
                                            : choice == LightChoice::Auto && boundedCount >= 1 &&
                                                  (boundedCount >= 2 || distantCount >= 1);
    std::vector<LightBounds> bounded;
    std::vector<DistantEstimate> distant;
    if (tree && emitters_.size() > 1) {
        for (uint32_t i = 0; i < boundedCount; ++i) bounded.push_back(boundsOf(emitters_[i], power[i]));
        for (size_t i = boundedCount; i < emitters_.size(); ++i) distant.push_back(distantEstimate(emitters_[i], environment_.get()));
    }
    chooser_ = LightChooser(power, bounded, std::move(distant));
}

} // namespace pt
