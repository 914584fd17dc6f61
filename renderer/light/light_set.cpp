#include "light/light_set.h"

#include "core/ray_offset.h"
#include "environment/sky_environment.h"
#include "light/sphere_light_sampling.h"
#include "scene/emission.h"
#include "sampling/warp.h"

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
    for (const SphereLight& l : scene.lights) lo = glm::min(lo, l.center - l.radius), hi = glm::max(hi, l.center + l.radius);
    if (!(hi.x >= lo.x)) return 1.0;
    double r = 0.5 * double(glm::length(hi - lo));
    return r > 0.0 ? r : 1.0;
}

} // namespace

// KHR_lights_punctual's falloffs: the spot's, smooth from the inner to the outer cone, and the
// window that ends a light at its range (the extension's recommended (1 - (d / range)^4)^2).
float LightSet::punctualFalloff(const SphereLight& l, const Vec3& wi, float distance) {
    float f = 1.0f;
    if (l.isSpot()) {
        float cd = -glm::dot(l.spotDirection, wi);
        float t = std::clamp((cd - l.cosOuter) / std::max(1e-3f, l.cosInner - l.cosOuter), 0.0f, 1.0f);
        f = t * t;
    }
    if (l.range > 0.0f) f *= sqr(std::clamp(1.0f - sqr(sqr(distance / l.range)), 0.0f, 1.0f));
    return f;
}

LightSet::LightSet(const Scene& scene, LightChoice choice) : scene_(scene) {
    std::vector<double> power; // in double: 2 pi A Le can pass float's range
    lightEmitter_.resize(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const SphereLight& l = scene.lights[i];
        lightEmitter_[i] = uint32_t(emitters_.size());
        Emitter e{l.isPoint() ? Emitter::Kind::Point : Emitter::Kind::Sphere, uint32_t(i)};
        e.center = l.center;
        e.radius = l.radius;
        e.radiance = l.isPoint() ? l.intensity : l.radiance();
        emitters_.push_back(e);
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
            Emitter e{Emitter::Kind::Triangle, uint32_t(t)};
            e.radiance = m.emission;
            emitters_.push_back(e);
            // Both sides emit; a textured emitter by its texture's mean (a guess at this triangle's share).
            double& mean = emissionMean[scene.triMaterial[t]];
            if (mean < 0.0) mean = m.emissionMap.used() ? (*scene.textures)[m.emissionMap.texture].mean : 1.0;
            power.push_back(2.0 * kPi * double(area) * double(average(m.emission)) * mean);
        }
    }
    boundedCount_ = uint32_t(emitters_.size());
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
            emitters_.push_back(Emitter{Emitter::Kind::Environment, 0});
            power.push_back(p);
        }
    }
    if (const auto& sun = scene.environment.sun; sun && !isBlack(sun->radiance)) {
        // As for the map: pi R^2 times the radiance integrated over the disk.
        sunEmitter_ = uint32_t(emitters_.size());
        Emitter e{Emitter::Kind::Sun, 0};
        e.center = sun->direction;
        e.radius = sun->oneMinusCosRadius;
        e.radiance = sun->radiance;
        emitters_.push_back(e);
        power.push_back(kPi * radius * radius * double(sun->solidAngle()) * double(average(sun->radiance)));
    }
    for (const DirectionalLight& d : scene.directionalLights) {
        Emitter e{Emitter::Kind::Directional, 0};
        e.center = d.direction;
        e.radiance = d.irradiance;
        emitters_.push_back(e);
        power.push_back(kPi * radius * radius * double(average(d.irradiance)));
    }
    distribution_ = Distribution1D(power);

    // The tree serves many bounded emitters, or bounded ones beside distant ones: choosing
    // between a spot and the sun by power alone weighs the sun by the whole scene's disk.
    size_t distantCount = emitters_.size() - boundedCount_;
    bool tree = choice == LightChoice::Tree ? boundedCount_ >= 1
                                            : choice == LightChoice::Auto && boundedCount_ >= 1 &&
                                                  (boundedCount_ >= 2 || distantCount >= 1);
    if (tree && emitters_.size() > 1) {
        std::vector<LightBounds> bounds;
        for (uint32_t i = 0; i < boundedCount_; ++i) bounds.push_back(boundsOf(emitters_[i], power[i]));
        tree_ = LightTree(bounds);
        for (size_t i = boundedCount_; i < emitters_.size(); ++i) {
            const Emitter& e = emitters_[i];
            DistantEstimate d;
            if (e.kind == Emitter::Kind::Environment) {
                d.irradiance = float(0.25 * environment_->radiantIntensityIntegral()); // pi L for a uniform L
            } else {
                d.direction = e.center;
                double radiance = average(e.radiance);
                d.irradiance = float(e.kind == Emitter::Kind::Sun ? radiance * scene.environment.sun->solidAngle() : radiance);
            }
            distant_.push_back(d);
        }
    }
}

// Where a bounded emitter is, where it faces and its power, for the light tree.
LightBounds LightSet::boundsOf(const Emitter& e, double power) const {
    LightBounds b;
    b.phi = float(std::min(power, 1e30));
    if (e.kind == Emitter::Kind::Triangle) {
        const glm::uvec3& tri = scene_.triPositions[e.index];
        const Vec3 &p0 = scene_.positions[tri[0]], &p1 = scene_.positions[tri[1]], &p2 = scene_.positions[tri[2]];
        b.lo = glm::min(p0, glm::min(p1, p2));
        b.hi = glm::max(p0, glm::max(p1, p2));
        b.axis = safeNormalize(glm::cross(p1 - p0, p2 - p0));
        b.cosThetaO = 1.0f;
        b.twoSided = true;
        return b;
    }
    b.lo = e.center - e.radius;
    b.hi = e.center + e.radius;
    if (const SphereLight& l = scene_.lights[e.index]; l.isSpot()) {
        b.axis = l.spotDirection;
        b.cosThetaO = 1.0f;
        b.cosThetaE = l.cosOuter;
    }
    return b;
}

// Each item's weight at a point: the tree's is its root's importance, which for a point light of
// intensity I is 4 pi I / d^2 (4 pi times its irradiance); a distant light's is its irradiance
// on a surface facing it, times the receiver's cosine.
float LightSet::treeWeight(const Vec3& p, const Vec3& n) const { return tree_.rootImportance(p, n) * (0.25f * kInvPi); }

float LightSet::distantWeight(size_t j, const Vec3& n) const {
    const DistantEstimate& d = distant_[j];
    if (d.direction == Vec3(0.0f) || n == Vec3(0.0f)) return d.irradiance;
    return d.irradiance * std::abs(glm::dot(d.direction, n));
}

// Between the tree (item 0) and the distant emitters: half of the probability by the weights,
// half evenly, so that an estimate that is off (the weights are rough) can cost at most half of
// the samples and never starve a light. A tree that can light nothing at p gets nothing.
LightSet::TopChoice LightSet::topChoice(const Vec3& p, const Vec3& n) const {
    TopChoice t;
    t.treeWeight = treeWeight(p, n);
    t.sum = t.treeWeight;
    for (size_t j = 0; j < distant_.size(); ++j) t.sum += distantWeight(j, n);
    t.items = float(distant_.size() + (t.treeWeight > 0.0f ? 1 : 0));
    return t;
}

uint32_t LightSet::chooseFromTree(float u, const Vec3& p, const Vec3& n, float& pmf) const {
    const TopChoice top = topChoice(p, n);
    float cdf = 0.0f;
    if (top.treeWeight > 0.0f) {
        float pTree = top.probability(top.treeWeight);
        if (u < pTree || distant_.empty()) {
            float pLeaf;
            uint32_t e = tree_.sample(p, n, std::min(u / pTree, 0x1.fffffep-1f), pLeaf);
            pmf = pTree * pLeaf;
            return e;
        }
        cdf = pTree;
    }
    for (size_t j = 0; j < distant_.size(); ++j) {
        float pj = top.probability(distantWeight(j, n));
        cdf += pj;
        if (u < cdf || j + 1 == distant_.size()) {
            pmf = pj;
            return boundedCount_ + uint32_t(j);
        }
    }
    pmf = 0.0f;
    return ~0u;
}

float LightSet::pmfFromTree(size_t i, const Vec3& p, const Vec3& n) const {
    const TopChoice top = topChoice(p, n);
    if (i >= boundedCount_) return top.probability(distantWeight(i - boundedCount_, n));
    if (!(top.treeWeight > 0.0f)) return 0.0f;
    return top.probability(top.treeWeight) * tree_.pmf(p, n, uint32_t(i));
}

LightSample LightSet::sample(size_t i, const Vec3& p, Vec2 u) const {
    const Emitter& e = emitters_[i];
    LightSample s;
    if (e.kind == Emitter::Kind::Point) {
        Vec3 d = e.center - p;
        float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return s;
        s.distance = std::sqrt(dist2);
        s.wi = d / s.distance;
        s.radiance = e.radiance * (punctualFalloff(scene_.lights[e.index], s.wi, s.distance) / dist2);
        s.pdf = 1.0f;
        s.delta = true;
        return s;
    }
    if (e.kind == Emitter::Kind::Directional) {
        s.wi = e.center;
        s.distance = kInf;
        s.radiance = e.radiance;
        s.pdf = 1.0f;
        s.delta = true;
        return s;
    }
    if (e.kind == Emitter::Kind::Sphere) {
        SphereCap cap = sphereCap(p, e.center, e.radius);
        // A direction in the cap, and the distance to where it meets the sphere, from the cone
        // angle: d cos(theta) -+ sqrt(r^2 - d^2 sin^2(theta)) (near root outside, far inside).
        bool inside = cap.oneMinusCosMax >= 2.0f;
        float oneMinusCos = inside ? 2.0f * u.x : u.x * cap.oneMinusCosMax;
        float cosTheta = 1.0f - oneMinusCos;
        float sin2Theta = oneMinusCos * (2.0f - oneMinusCos);
        float sinTheta = safeSqrt(sin2Theta);
        float phi = 2.0f * kPi * u.y;
        s.wi = Frame(cap.axis).toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
        float chord = safeSqrt(e.radius * e.radius - cap.distance * cap.distance * sin2Theta);
        s.distance = inside ? cap.distance * cosTheta + chord : cap.distance * cosTheta - chord;
        if (!(s.distance > 0.0f)) return s;
        s.radiance = e.radiance;
        s.pdf = sphereCapPdf(cap);
        return s;
    }
    if (e.kind == Emitter::Kind::Environment) {
        s.wi = environment_->sample(u, s.radiance, s.pdf);
        s.distance = kInf;
        // The sky's map is only its density: its radiance comes from the model, as for escaping rays.
        if (scene_.environment.preetham) s.radiance = scene_.environment.preetham->radiance(s.wi);
        return s;
    }
    if (e.kind == Emitter::Kind::Sun) {
        s.wi = Frame(e.center).toWorld(squareToUniformCone(u, e.radius));
        s.distance = kInf;
        s.pdf = uniformConePdf(e.radius);
        // A setting sun's lower part is behind the ground: no light, as a BSDF ray there sees none.
        s.radiance = s.wi.y >= 0.0f ? e.radiance : Spectrum(0.0f);
        return s;
    }
    // Emissive triangle: uniform by area, converted to solid angle.
    const glm::uvec3& tri = scene_.triPositions[e.index];
    const Vec3 &a = scene_.positions[tri[0]], &b = scene_.positions[tri[1]], &c = scene_.positions[tri[2]];
    Vec2 bary = squareToUniformTriangle(u);
    Vec3 bw(1.0f - bary.x - bary.y, bary.x, bary.y);
    s.point = bw.x * a + bw.y * b + bw.z * c;
    s.pointError = triangleOffsetError(a, b, c);
    Vec3 n = glm::cross(b - a, c - a);
    float area2 = safeLength(n);
    s.normal = safeNormalize(n);
    Vec3 d = s.point - p;
    float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return s;
    s.distance = std::sqrt(dist2);
    s.wi = d / s.distance;
    float cosLight = std::abs(glm::dot(s.normal, s.wi));
    if (cosLight == 0.0f) return s;
    const Material& m = scene_.materials[scene_.triMaterial[e.index]];
    s.radiance = m.emissionMap.used() ? emittedRadiance(m, *scene_.textures, scene_.uvAt(e.index, bary.x, bary.y), Footprint{})
                                      : e.radiance;
    s.pdf = dist2 / (cosLight * 0.5f * area2);
    return s;
}

float LightSet::pdf(size_t i, const Vec3& p, const Vec3& wi, float distance) const {
    const Emitter& e = emitters_[i];
    if (e.kind == Emitter::Kind::Point || e.kind == Emitter::Kind::Directional) return 0.0f;
    if (e.kind == Emitter::Kind::Sphere) return sphereCapPdf(sphereCap(p, e.center, e.radius));
    if (e.kind == Emitter::Kind::Environment) return environment_->pdf(wi);
    if (e.kind == Emitter::Kind::Sun) return scene_.environment.sun->covers(wi) ? uniformConePdf(e.radius) : 0.0f;
    const glm::uvec3& tri = scene_.triPositions[e.index];
    const Vec3 &a = scene_.positions[tri[0]], &b = scene_.positions[tri[1]], &c = scene_.positions[tri[2]];
    Vec3 n = glm::cross(b - a, c - a);
    float area2 = safeLength(n);
    float cosLight = std::abs(glm::dot(safeNormalize(n), wi));
    if (cosLight == 0.0f) return 0.0f;
    return distance * distance / (cosLight * 0.5f * area2);
}

} // namespace pt
