// Ray queries against the scene: Embree 3 for the triangles, an exact analytic test for the few
// sphere lights. This is the only module that includes Embree's headers.
#pragma once

#include "scene/scene.h"

#include <memory>
#include <vector>

namespace pt {

// Rays always start at tnear = 0: surface origins are offset by spawnRay (accel/ray_offset.h)
// instead of relying on an epsilon here. `dir` must be unit length.
struct Ray {
    Vec3 origin;
    Vec3 dir;
};

struct Hit {
    static constexpr uint32_t kNone = ~0u;
    float t = kInf;
    uint32_t prim = kNone; // triangle index, or index into Scene::lights when onSphere
    float u = 0.0f, v = 0.0f; // barycentric weights of triangle vertices 1 and 2
    bool onSphere = false;

    bool found() const { return prim != kNone; }
};

// One traced ray, as the bench records it to replay through bare Embree calls.
struct RayRecord {
    enum class Kind : uint8_t { Camera, Continuation, Shadow };
    Vec3 origin;
    float tfar;
    Vec3 dir;
    Kind kind;
};

// How Embree builds the BVH. The defaults are chosen by pt-bench's comparison of all of them on
// the rays of a cornellbottle2 frame (see the README's Performance section).
struct AccelOptions {
    enum class Quality : uint8_t { Low, Medium, High };
    Quality quality = Quality::High;
    bool robust = true;   // watertight triangle tests: no rays slipping between adjacent triangles
    bool compact = false; // smaller BVH, usually slower
};

class Accel {
public:
    // Builds the BVH. `threads` bounds Embree's build threads (0: all).
    Accel(const Scene& scene, int threads, const AccelOptions& options = {});
    ~Accel();
    Accel(const Accel&) = delete;
    Accel& operator=(const Accel&) = delete;

    // Closest hit with t in (0, tfar). `coherent` marks camera rays.
    Hit intersect(const Ray& ray, bool coherent, float tfar = kInf) const;
    // True if anything lies on the ray with t in (0, tfar), ignoring sphere light `skipLight`
    // (the light being sampled; -1 for none).
    bool occluded(const Ray& ray, float tfar, int skipLight = -1) const;

    // Bench support: while a log is set, every query appends its ray (single-threaded use only).
    void setRayLog(std::vector<RayRecord>* log) { log_ = log; }
    // Traces recorded rays with plain rtcIntersect1 / rtcOccluded1 and nothing around them.
    // Returns the number of hits, so the work cannot be optimised away.
    size_t traceBare(const RayRecord* rays, size_t count) const;

private:
    std::vector<RayRecord>* log_ = nullptr;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Closest intersection t > 0 of a ray with a sphere, or kInf. Uses the formulation of Haines et
// al. (Ray Tracing Gems, ch. 7) that avoids cancellation when the sphere is small or far.
float intersectSphere(const Vec3& origin, const Vec3& dir, const Vec3& center, float radius);

} // namespace pt
