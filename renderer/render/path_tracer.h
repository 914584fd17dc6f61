// The per-sample path loop: next-event estimation, BSDF sampling and multiple importance
// sampling (power heuristic) between them, Russian roulette. Orchestration (tiles, threads,
// film) lives in render/renderer.h.
#pragma once

#include "accel/accel.h"
#include "light/light_set.h"
#include "render/render_settings.h"
#include "render/shading_triangles.h"
#include "render/vertex_tangents.h"
#include "sampling/sampler.h"
#include "sampling/sobol_sampler.h"
#include "scene/scene.h"

namespace pt {

// What the camera ray hit first, for the albedo, normal and depth layers.
struct FirstHit {
    Spectrum albedo{0.0f}; // the BSDF's total reflectance towards the camera (all lobes)
    Vec3 normal{0.0f};     // shading normal, turned to face the camera
    float depth = kInf;    // distance along the camera ray
};

class PathTracer {
public:
    // `pixelSpread` is the angle a camera ray's cone opens per unit distance (texture footprints).
    PathTracer(const Scene& scene, const std::vector<ShadingTriangle>& triangles,
               const std::vector<CornerTangent>& tangents, const Accel& accel, const LightSet& lights,
               const RenderSettings& settings, float pixelSpread)
        : scene_(scene), triangles_(triangles), tangents_(tangents), accel_(accel), lights_(lights),
          settings_(settings), pixelSpread_(pixelSpread) {}

    // Radiance arriving at the camera along `cameraRay`, whose closest hit the caller traced
    // (camera rays go to Embree in packets). Sampler is IndependentSampler or SobolSampler; the
    // choice is made once per render, not per ray.
    template <typename Sampler>
    Spectrum trace(const Ray& cameraRay, const Hit& cameraHit, const Sampler& sampler, RayCounts& counts,
                   FirstHit* first = nullptr) const;

private:
    const Scene& scene_;
    const std::vector<ShadingTriangle>& triangles_;
    const std::vector<CornerTangent>& tangents_;
    const Accel& accel_;
    const LightSet& lights_;
    const RenderSettings& settings_;
    float pixelSpread_;
};

} // namespace pt
