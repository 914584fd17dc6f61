// The path loop: next-event estimation, BSDF sampling and multiple importance sampling (power
// heuristic) between them, Russian roulette; run in stages over a batch of paths: shade every
// path's hit (emission, material, a light sample whose shadow ray is queued, the next direction),
// trace the queued shadow rays, intersect the continuing paths' rays, again until none is left.
// Each stage is a loop over flat arrays with one kind of work, so that it can run several paths
// per instruction; each path's arithmetic is the same as one path traced alone, in the same order,
// so the image does not depend on how paths are batched. Orchestration (tiles, threads, film,
// camera rays) lives in render/renderer.h.
#pragma once

#include "accel/accel.h"
#include "light/light_set.h"
#include "material/evaluate_material.h"
#include "render/path_state.h"
#include "render/scatter.h"
#include "render/render_settings.h"
#include "render/shading_triangles.h"
#include "render/vertex_tangents.h"
#include "sampling/sampler.h"
#include "sampling/sobol_sampler.h"
#include "scene/scene.h"

#include <type_traits>
#include <vector>

namespace pt {

// The paths of one batch and the arrays the stages share, kept by a thread from batch to batch
// so that the loop allocates nothing once they have grown.
template <typename Sampler>
struct PathBatch {
    std::vector<PathState<Sampler>> paths;
    std::vector<Hit> hits;            // each path's closest hit along its ray
    std::vector<uint32_t> active;     // slots of paths still going
    std::vector<ShadowQuery> shadows; // this round's shadow rays
    std::vector<VertexDraws> draws;   // this round's sample values, by position in `active`
    std::vector<float> drawX, drawY;  // drawDimension's values, by position in the chosen slots
    std::vector<GuidePath> guidePaths; // a training pass's records, by slot

    void clear() {
        paths.clear();
        hits.clear();
    }

    // Sample values of many paths, one dimension at a time: chooseForDraws(slots, n) picks
    // paths[slots[k]], k < n (`slots` must outlive the draws), then each drawDimension writes
    // one dimension of theirs to drawX[k] (and drawY[k] for a 2D draw). Sobol samplers draw
    // together, in SIMD lanes (SobolSampler::drawMany); others one by one. The camera stage and
    // the loop's draw stage both draw through here.
    void chooseForDraws(const uint32_t* slots, size_t n) {
        drawSlots_ = slots;
        drawCount_ = n;
        drawX.resize(n);
        drawY.resize(n);
        if constexpr (std::is_same_v<Sampler, SobolSampler>) {
            pixelSeeds_.resize(n);
            sampleIndices_.resize(n);
            for (size_t k = 0; k < n; ++k) {
                const SobolSampler& s = paths[slots[k]].sampler;
                pixelSeeds_[k] = s.pixelSeed();
                sampleIndices_[k] = s.sampleIndex();
            }
        }
    }
    void drawDimension(uint32_t dimension, bool pair) {
        if constexpr (std::is_same_v<Sampler, SobolSampler>) {
            SobolSampler::drawMany(pixelSeeds_.data(), sampleIndices_.data(), drawCount_, dimension, drawX.data(),
                                   pair ? drawY.data() : nullptr);
        } else {
            for (size_t k = 0; k < drawCount_; ++k) {
                const Sampler& s = paths[drawSlots_[k]].sampler;
                if (pair) {
                    const Vec2 v = s.get2D(dimension);
                    drawX[k] = v.x;
                    drawY[k] = v.y;
                } else {
                    drawX[k] = s.get1D(dimension);
                }
            }
        }
    }

private:
    const uint32_t* drawSlots_ = nullptr;
    size_t drawCount_ = 0;
    std::vector<uint32_t> pixelSeeds_, sampleIndices_; // SobolSampler::drawMany's inputs
};

class PathTracer {
public:
    // `pixelSpread` is the angle a camera ray's cone opens per unit distance (texture footprints).
    PathTracer(const Scene& scene, const std::vector<ShadingTriangle>& triangles,
               const std::vector<CornerTangent>& tangents, const Accel& accel, const LightSet& lights,
               const RenderSettings& settings, float pixelSpread)
        : scene_(scene), triangles_(triangles), tangents_(tangents), accel_(accel), lights_(lights),
          settings_(settings), pixelSpread_(pixelSpread) {}

    // Traces every path of `batch` to its end. Each path's camera ray and its closest hit are set
    // by the caller (camera rays go to Embree in packets); on return each path's L is its
    // radiance sample (0 for a discarded NaN, negative or infinite one; clamped if asked), and
    // `first` is filled when `firstHits` is set. Sampler is IndependentSampler or SobolSampler:
    // the choice is made once per render, not per ray.
    // `recorder` (a training pass of --guide): each path's guidable vertices and the light that
    // came back along their directions are recorded there.
    template <typename Sampler>
    void trace(PathBatch<Sampler>& batch, bool firstHits, RayCounts& counts, GuideRecorder* recorder = nullptr) const;

    // The path guide directions are drawn from (and, in training, recorded into); none: BSDF only.
    void setGuide(const PathGuide* guide) { guide_ = guide; }

private:
    // Shade stage for one path at its hit, with its vertex's sample values: returns whether it
    // goes on (its ray set to the next).
    template <typename Sampler>
    bool shade(PathState<Sampler>& path, const Hit& hit, const VertexDraws& u, uint32_t slot, bool firstHits,
               std::vector<ShadowQuery>& shadows, RayCounts& counts) const;
    // Its steps (path_tracer.cpp): a ray that left the scene, a sphere light hit, next-event
    // estimation at a surface, and the BSDF-sampled continuation.
    template <typename Sampler>
    void escape(PathState<Sampler>& path, bool firstHits) const;
    template <typename Sampler>
    void hitSphereLight(PathState<Sampler>& path, const Hit& hit, bool firstHits) const;
    template <typename Sampler>
    void sampleLight(const PathState<Sampler>& path, const SurfacePoint& sp, const Material& m,
                     const ShadingPoint& shading, const ScatterGuide& guide, const Vec3& ng, const VertexDraws& u,
                     uint32_t slot, std::vector<ShadowQuery>& shadows, RayCounts& counts) const;
    template <typename Sampler>
    bool continuePath(PathState<Sampler>& path, const SurfacePoint& sp, const Material& m, const ShadingPoint& shading,
                      const ScatterGuide& guide, const Vec3& ng, const VertexDraws& u, bool firstHits,
                      RayCounts& counts) const;
    // Weight of emission found by BSDF sampling (or by the camera) at a hit `distance` along the path's ray.
    template <typename Sampler>
    float hitWeight(const PathState<Sampler>& path, uint32_t emitter, float distance) const;
    // Whether next-event estimation could have sampled the emitter the path just found.
    template <typename Sampler>
    bool neeCovers(const PathState<Sampler>& path, uint32_t emitter) const;

    const Scene& scene_;
    const std::vector<ShadingTriangle>& triangles_;
    const std::vector<CornerTangent>& tangents_;
    const Accel& accel_;
    const LightSet& lights_;
    const RenderSettings& settings_;
    const PathGuide* guide_ = nullptr;
    float pixelSpread_;
};

} // namespace pt
