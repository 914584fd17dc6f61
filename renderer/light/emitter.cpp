#include "light/emitter.h"

#include "core/ray_offset.h"
#include "environment/preetham_sky.h"
#include "light/sphere_light_sampling.h"
#include "sampling/warp.h"
#include "scene/emission.h"

namespace pt {

LightSample SphereEmitter::sample(const Vec3& p, Vec2 u) const {
    LightSample s;
    s.flags = kFlags;
    s.skipLight = int(light);
    SphereCap cap = sphereCap(p, center, radius);
    // A direction in the cap, and the distance to where it meets the sphere, from the cone
    // angle: d cos(theta) -+ sqrt(r^2 - d^2 sin^2(theta)) (near root outside, far inside).
    bool inside = cap.oneMinusCosMax >= 2.0f;
    float oneMinusCos = inside ? 2.0f * u.x : u.x * cap.oneMinusCosMax;
    float cosTheta = 1.0f - oneMinusCos;
    float sin2Theta = oneMinusCos * (2.0f - oneMinusCos);
    float sinTheta = safeSqrt(sin2Theta);
    float phi = 2.0f * kPi * u.y;
    s.wi = Frame(cap.axis).toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
    float chord = safeSqrt(radius * radius - cap.distance * cap.distance * sin2Theta);
    s.distance = inside ? cap.distance * cosTheta + chord : cap.distance * cosTheta - chord;
    if (!(s.distance > 0.0f)) return s;
    s.radiance = radiance;
    s.pdf = sphereCapPdf(cap);
    return s;
}

float SphereEmitter::pdf(const Vec3& p, const Vec3&, float) const {
    return sphereCapPdf(sphereCap(p, center, radius));
}

LightBounds SphereEmitter::bounds() const {
    LightBounds b;
    b.lo = center - radius;
    b.hi = center + radius;
    return b;
}

float PointEmitter::falloff(const Vec3& wi, float distance) const {
    float f = 1.0f;
    if (isSpot()) {
        float cd = -glm::dot(spotDirection, wi);
        float t = std::clamp((cd - cosOuter) / std::max(1e-3f, cosInner - cosOuter), 0.0f, 1.0f);
        f = t * t;
    }
    if (range > 0.0f) f *= sqr(std::clamp(1.0f - sqr(sqr(distance / range)), 0.0f, 1.0f));
    return f;
}

LightSample PointEmitter::sample(const Vec3& p, Vec2) const {
    LightSample s;
    s.flags = kFlags;
    Vec3 d = position - p;
    float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return s;
    s.distance = std::sqrt(dist2);
    s.wi = d / s.distance;
    s.radiance = intensity * (falloff(s.wi, s.distance) / dist2);
    s.pdf = 1.0f;
    return s;
}

LightBounds PointEmitter::bounds() const {
    LightBounds b;
    b.lo = position - 0.0f;
    b.hi = position + 0.0f;
    if (isSpot()) {
        b.axis = spotDirection;
        b.cosThetaO = 1.0f;
        b.cosThetaE = cosOuter;
    }
    return b;
}

LightSample TriangleEmitter::sample(const Vec3& p, Vec2 u) const {
    LightSample s;
    s.flags = kFlags;
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
    const Material& m = scene->materials[scene->triMaterial[triangle]];
    s.radiance = m.emissionMap.used()
                     ? emittedRadiance(m, *scene->textures, scene->uvAt(triangle, bary.x, bary.y), Footprint{})
                     : radiance;
    s.pdf = dist2 / (cosLight * 0.5f * area2);
    return s;
}

float TriangleEmitter::pdf(const Vec3&, const Vec3& wi, float distance) const {
    Vec3 n = glm::cross(b - a, c - a);
    float area2 = safeLength(n);
    float cosLight = std::abs(glm::dot(safeNormalize(n), wi));
    if (cosLight == 0.0f) return 0.0f;
    return distance * distance / (cosLight * 0.5f * area2);
}

LightBounds TriangleEmitter::bounds() const {
    LightBounds bd;
    bd.lo = glm::min(a, glm::min(b, c));
    bd.hi = glm::max(a, glm::max(b, c));
    bd.axis = safeNormalize(glm::cross(b - a, c - a));
    bd.cosThetaO = 1.0f;
    bd.twoSided = true;
    return bd;
}

LightSample EnvironmentEmitter::sample(const Vec3&, Vec2 u) const {
    LightSample s;
    s.flags = kFlags;
    s.wi = light->sample(u, s.radiance, s.pdf);
    s.distance = kInf;
    // The sky's map is only its density: its radiance comes from the model, as for escaping rays.
    if (preetham) s.radiance = preetham->radiance(s.wi);
    return s;
}

LightSample SunEmitter::sample(const Vec3&, Vec2 u) const {
    LightSample s;
    s.flags = kFlags;
    s.wi = Frame(disk.direction).toWorld(squareToUniformCone(u, disk.oneMinusCosRadius));
    s.distance = kInf;
    s.pdf = uniformConePdf(disk.oneMinusCosRadius);
    // A setting sun's lower part is behind the ground: no light, as a BSDF ray there sees none.
    s.radiance = s.wi.y >= 0.0f ? disk.radiance : Spectrum(0.0f);
    return s;
}

LightSample DirectionalEmitter::sample(const Vec3&, Vec2) const {
    LightSample s;
    s.flags = kFlags;
    s.wi = direction;
    s.distance = kInf;
    s.radiance = irradiance;
    s.pdf = 1.0f;
    return s;
}

} // namespace pt
