#include "light/light_set.h"

#include "accel/accel.h"
#include "accel/ray_offset.h"
#include "light/sphere_light_sampling.h"
#include "sampling/warp.h"

namespace pt {

LightSet::LightSet(const Scene& scene) : scene_(scene) {
    std::vector<float> power;
    lightEmitter_.resize(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const SphereLight& l = scene.lights[i];
        lightEmitter_[i] = uint32_t(emitters_.size());
        emitters_.push_back({l.isPoint() ? Emitter::Kind::Point : Emitter::Kind::Sphere, uint32_t(i)});
        power.push_back(4.0f * kPi * average(l.intensity)); // same for a sphere and a point
    }
    bool anyEmissive = false;
    for (const Material& m : scene.materials) anyEmissive |= m.isEmissive();
    if (anyEmissive) {
        triangleEmitter_.assign(scene.triangleCount(), ~0u);
        for (size_t t = 0; t < scene.triangleCount(); ++t) {
            const Material& m = scene.materials[scene.triMaterial[t]];
            if (!m.isEmissive()) continue;
            const glm::uvec3& tri = scene.triPositions[t];
            const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]], &c = scene.positions[tri[2]];
            float area = 0.5f * glm::length(glm::cross(b - a, c - a));
            if (!(area > 0.0f)) continue; // degenerate triangles emit nothing and are never hit
            triangleEmitter_[t] = uint32_t(emitters_.size());
            emitters_.push_back({Emitter::Kind::Triangle, uint32_t(t)});
            power.push_back(2.0f * kPi * area * average(m.emission)); // both sides emit
        }
    }
    distribution_ = Distribution1D(power);
}

LightSample LightSet::sample(size_t i, const Vec3& p, Vec2 u) const {
    const Emitter& e = emitters_[i];
    LightSample s;
    if (e.kind == Emitter::Kind::Point) {
        const SphereLight& l = scene_.lights[e.index];
        Vec3 d = l.center - p;
        float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return s;
        s.distance = std::sqrt(dist2);
        s.wi = d / s.distance;
        s.radiance = l.intensity / dist2;
        s.pdf = 1.0f;
        s.delta = true;
        return s;
    }
    if (e.kind == Emitter::Kind::Sphere) {
        const SphereLight& l = scene_.lights[e.index];
        SphereCap cap = sphereCap(p, l.center, l.radius);
        Vec3 local = cap.oneMinusCosMax >= 2.0f ? squareToUniformSphere(u) : squareToUniformCone(u, cap.oneMinusCosMax);
        s.wi = Frame(cap.axis).toWorld(local);
        s.distance = intersectSphere(p, s.wi, l.center, l.radius);
        if (!(s.distance < kInf)) return s; // grazing the rim in float: no sample
        s.radiance = l.radiance();
        s.pdf = sphereCapPdf(cap);
        return s;
    }
    // Emissive triangle: uniform by area, converted to solid angle.
    const glm::uvec3& tri = scene_.triPositions[e.index];
    const Vec3 &a = scene_.positions[tri[0]], &b = scene_.positions[tri[1]], &c = scene_.positions[tri[2]];
    Vec2 bary = squareToUniformTriangle(u);
    Vec3 bw(1.0f - bary.x - bary.y, bary.x, bary.y);
    s.point = bw.x * a + bw.y * b + bw.z * c;
    s.pointError = interpolationError(bw, a, b, c);
    Vec3 n = glm::cross(b - a, c - a);
    float area2 = glm::length(n);
    s.normal = n / area2;
    Vec3 d = s.point - p;
    float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return s;
    s.distance = std::sqrt(dist2);
    s.wi = d / s.distance;
    float cosLight = std::abs(glm::dot(s.normal, s.wi));
    if (cosLight == 0.0f) return s;
    s.radiance = scene_.materials[scene_.triMaterial[e.index]].emission;
    s.pdf = dist2 / (cosLight * 0.5f * area2);
    return s;
}

float LightSet::pdf(size_t i, const Vec3& p, const Vec3& wi, float distance) const {
    const Emitter& e = emitters_[i];
    if (e.kind == Emitter::Kind::Point) return 0.0f;
    if (e.kind == Emitter::Kind::Sphere) {
        const SphereLight& l = scene_.lights[e.index];
        return sphereCapPdf(sphereCap(p, l.center, l.radius));
    }
    const glm::uvec3& tri = scene_.triPositions[e.index];
    const Vec3 &a = scene_.positions[tri[0]], &b = scene_.positions[tri[1]], &c = scene_.positions[tri[2]];
    Vec3 n = glm::cross(b - a, c - a);
    float area2 = glm::length(n);
    float cosLight = std::abs(glm::dot(n, wi)) / area2;
    if (cosLight == 0.0f) return 0.0f;
    return distance * distance / (cosLight * 0.5f * area2);
}

} // namespace pt
