// Ray queries against the scene: Embree 3 for the triangles, and an exact analytic test for the
// sphere lights, inside the BVH as a user geometry when there are many. This is the only module
// that includes Embree's headers.
#pragma once

#include "scene/scene.h"

#include <memory>
#include <vector>

namespace pt {

// Rays always start at tnear = 0: surface origins are offset by spawnRay (render/surface_hit.h,
// by the error bound of core/ray_offset.h) instead of relying on an epsilon here. `dir` must be unit length.
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
    int skipLight = -1; // shadow rays: the sphere light they are aimed at
};

// How Embree builds the BVH. The defaults are chosen by pt-bench's comparison of all of them on
// the rays of a cornellbottle2 frame (see docs/performance.md).
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

    // Closest hit with t in (0, tfar), for incoherent rays (a path's continuation).
    Hit intersect(const Ray& ray, float tfar = kInf) const;
    // Closest hits of up to kPacket camera rays of neighbouring pixels, as one coherent packet:
    // Embree traces those 2.7 times as fast as one by one (pt-bench --batching). Lanes whose
    // `active` is false are left alone.
    static constexpr int kPacket = 8;
    void intersectCameraRays(const Ray* rays, const bool* active, int count, Hit* hits) const;
    // True if anything lies on the ray with t in (0, tfar), ignoring sphere light `skipLight`
    // (the light being sampled; -1 for none).
    bool occluded(const Ray& ray, float tfar, int skipLight = -1) const;

    // Bench support: while a log is set, every query appends its ray (single-threaded use only).
    void setRayLog(std::vector<RayRecord>* log) { log_ = log; }
    // Traces recorded rays through Embree and nothing around them, returning the number of hits
    // so the work cannot be optimised away. Camera rays go as the path tracer sends them, in
    // coherent packets of kPacket (or one by one: OneByOne); continuation rays one by one
    // (rtcIntersect1); shadow rays one by one (rtcOccluded1) or, with ShadowStreams, as one
    // coherent stream (rtcOccluded1M), to measure what streams would gain the staged loop's shadow
    // stage. In accel/ray_replay.cpp.
    enum class Replay { AsTraced, OneByOne, ShadowStreams };
    size_t traceBare(const RayRecord* rays, size_t count, Replay mode = Replay::AsTraced) const;

private:
    // The Hit of Embree's answer: scene triangle or sphere light.
    Hit hitOf(unsigned geomID, unsigned primID, float t, float u, float v) const;
    // Sphere lights not in the BVH (a few of them) are tested after Embree's query.
    void addLoopedSphereHits(const Ray& ray, float tfar, Hit& hit) const;

    std::vector<RayRecord>* log_ = nullptr;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Closest intersection t > 0 of a ray with a sphere, or kInf. Uses the formulation of Haines et
// al. (Ray Tracing Gems, ch. 7) that avoids cancellation when the sphere is small or far.
float intersectSphere(const Vec3& origin, const Vec3& dir, const Vec3& center, float radius);

} // namespace pt
