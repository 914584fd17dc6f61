#include "accel/accel.h"

#include "scene/load_error.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <string>

namespace pt {

namespace {

constexpr unsigned kOpaqueGeometry = 0, kCutoutGeometry = 1;

// Triangles of materials with a cutout (map_d) sit in a geometry of their own whose filter
// function drops hits where the surface is not there; the opaque rest has no filter and pays
// nothing. Coverage between 0 and 1 is a coin flip keyed on the hit and the ray, so an image does
// not depend on which thread traced what.
struct Cutouts {
    const Scene* scene = nullptr;
    std::vector<uint32_t> triangle; // primitive of the cutout geometry -> scene triangle
};

uint32_t floatBits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// A uniform number in [0, 1) from the hit and the ray (SplitMix64's finaliser).
float coverageCoin(uint32_t triangle, float u, float v, float dx, float dy, float dz) {
    uint64_t h = (uint64_t(triangle) << 32) ^ floatBits(u);
    h = h * 0x9E3779B97F4A7C15ull ^ (uint64_t(floatBits(v)) << 32 | floatBits(dx));
    h = h * 0xBF58476D1CE4E5B9ull ^ (uint64_t(floatBits(dy)) << 32 | floatBits(dz));
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return float(h >> 40) * 0x1p-24f;
}

void cutoutFilter(const RTCFilterFunctionNArguments* args) {
    const auto* cut = static_cast<const Cutouts*>(args->geometryUserPtr);
    const Scene& scene = *cut->scene;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        uint32_t tri = cut->triangle[RTCHitN_primID(args->hit, args->N, i)];
        float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const Material& m = scene.materials[scene.triMaterial[tri]];
        float coverage = m.alpha * scene.textures->scalar(m.alphaMap, scene.uvAt(tri, u, v), Footprint{});
        if (m.alphaCutoff >= 0.0f) coverage = coverage >= m.alphaCutoff ? 1.0f : 0.0f;
        if (coverage >= 1.0f) continue;
        float coin = coverageCoin(tri, u, v, RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                                  RTCRayN_dir_z(args->ray, args->N, i));
        if (!(coin < coverage)) args->valid[i] = 0; // not there: the ray goes on
    }
}

} // namespace

struct Accel::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;
    // Scene triangle of each primitive, per geometry; empty: the identity (no cutouts).
    std::vector<uint32_t> opaqueTriangle;
    Cutouts cutouts;
    // Sphere lights (radius > 0) as (centre, radius), with their index in Scene::lights.
    std::vector<glm::vec4> spheres;
    std::vector<uint32_t> sphereLight;
};

static void onEmbreeError(void* user, RTCError code, const char* message) {
    auto* error = static_cast<std::string*>(user);
    if (error->empty()) *error = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

Accel::Accel(const Scene& scene, int threads, const AccelOptions& options) : impl_(std::make_unique<Impl>()) {
    std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
    impl_->device = rtcNewDevice(config.c_str());
    if (!impl_->device) throw LoadError("cannot create the Embree device (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(impl_->device, onEmbreeError, &impl_->error);

    impl_->scene = rtcNewScene(impl_->device);
    int flags = (options.robust ? RTC_SCENE_FLAG_ROBUST : 0) | (options.compact ? RTC_SCENE_FLAG_COMPACT : 0);
    RTCBuildQuality quality = options.quality == AccelOptions::Quality::High     ? RTC_BUILD_QUALITY_HIGH
                              : options.quality == AccelOptions::Quality::Medium ? RTC_BUILD_QUALITY_MEDIUM
                                                                                 : RTC_BUILD_QUALITY_LOW;
    rtcSetSceneFlags(impl_->scene, RTCSceneFlags(flags));
    rtcSetSceneBuildQuality(impl_->scene, quality);

    // Which triangles have a cutout: they go into a geometry of their own.
    impl_->cutouts.scene = &scene;
    bool anyCutout = false;
    for (const Material& m : scene.materials) anyCutout |= m.hasCutout();
    if (anyCutout)
        for (size_t t = 0; t < scene.triangleCount(); ++t)
            (scene.materials[scene.triMaterial[t]].hasCutout() ? impl_->cutouts.triangle : impl_->opaqueTriangle)
                .push_back(uint32_t(t));
    auto addGeometry = [&](const std::vector<uint32_t>* subset, unsigned id) {
        size_t count = subset ? subset->size() : scene.triangleCount();
        if (count == 0) return;
        RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geom, quality);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), scene.positions.size()));
        auto* indices = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), count));
        if (!vertices || !indices) throw LoadError("Embree could not allocate the mesh buffers: " + impl_->error);
        for (size_t i = 0; i < scene.positions.size(); ++i)
            for (int k = 0; k < 3; ++k) vertices[3 * i + k] = scene.positions[i][k];
        for (size_t i = 0; i < count; ++i)
            for (int k = 0; k < 3; ++k) indices[3 * i + k] = scene.triPositions[subset ? (*subset)[i] : i][k];
        if (id == kCutoutGeometry) {
            rtcSetGeometryUserData(geom, &impl_->cutouts);
            rtcSetGeometryIntersectFilterFunction(geom, cutoutFilter);
            rtcSetGeometryOccludedFilterFunction(geom, cutoutFilter);
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(impl_->scene, geom, id);
        rtcReleaseGeometry(geom);
    };
    if (anyCutout) {
        addGeometry(&impl_->opaqueTriangle, kOpaqueGeometry);
        addGeometry(&impl_->cutouts.triangle, kCutoutGeometry);
    } else {
        addGeometry(nullptr, kOpaqueGeometry);
    }
    rtcCommitScene(impl_->scene);
    if (!impl_->error.empty()) throw LoadError(scene.path + ": building the BVH failed: " + impl_->error);

    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const SphereLight& l = scene.lights[i];
        if (l.isPoint()) continue;
        impl_->spheres.emplace_back(l.center, l.radius);
        impl_->sphereLight.push_back(uint32_t(i));
    }
}

Accel::~Accel() {
    if (impl_->scene) rtcReleaseScene(impl_->scene);
    if (impl_->device) rtcReleaseDevice(impl_->device);
}

float intersectSphere(const Vec3& origin, const Vec3& dir, const Vec3& center, float radius) {
    Vec3 f = origin - center;
    float b = glm::dot(f, dir);
    float c = glm::dot(f, f) - radius * radius;
    if (c > 0.0f && b > 0.0f) return kInf; // outside and moving away: most rays, decided early
    Vec3 perp = f - b * dir; // distance from centre to the line, computed without cancellation
    float disc = radius * radius - glm::dot(perp, perp);
    if (disc < 0.0f) return kInf;
    float q = -b - std::copysign(std::sqrt(disc), b);
    float t0 = c / q, t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0f) return t0;
    if (t1 > 0.0f) return t1;
    return kInf;
}

static void fillRay(RTCRay& r, const Ray& ray, float tfar) {
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.dir.x;
    r.dir_y = ray.dir.y;
    r.dir_z = ray.dir.z;
    r.tnear = 0.0f;
    r.tfar = tfar;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu; // Debian's Embree is built with ray masks
    r.id = 0;
    r.flags = 0;
}

uint32_t Accel::sceneTriangle(unsigned geomID, unsigned primID) const {
    return geomID == kCutoutGeometry      ? impl_->cutouts.triangle[primID]
           : impl_->opaqueTriangle.empty() ? primID
                                           : impl_->opaqueTriangle[primID];
}

void Accel::addSphereHits(const Ray& ray, float tfar, Hit& hit) const {
    for (size_t i = 0; i < impl_->spheres.size(); ++i) {
        const glm::vec4& s = impl_->spheres[i];
        float t = intersectSphere(ray.origin, ray.dir, Vec3(s), s.w);
        if (t < hit.t && t < tfar) {
            hit.t = t;
            hit.prim = impl_->sphereLight[i];
            hit.onSphere = true;
        }
    }
}

Hit Accel::intersect(const Ray& ray, float tfar) const {
    if (log_) log_->push_back({ray.origin, tfar, ray.dir, RayRecord::Kind::Continuation});
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRayHit rh;
    fillRay(rh.ray, ray, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rh);

    Hit hit;
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        hit.t = rh.ray.tfar;
        hit.prim = sceneTriangle(rh.hit.geomID, rh.hit.primID);
        hit.u = rh.hit.u;
        hit.v = rh.hit.v;
    }
    addSphereHits(ray, tfar, hit);
    return hit;
}

void Accel::intersectCameraRays(const Ray* rays, const bool* active, int count, Hit* hits) const {
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[kPacket];
    for (int i = 0; i < kPacket; ++i) {
        valid[i] = i < count && active[i] ? -1 : 0;
        // Inactive lanes still get finite values: Embree may compute on them before masking.
        const Ray& r = valid[i] ? rays[i] : rays[0];
        RTCRay8& p = packet.ray;
        p.org_x[i] = r.origin.x, p.org_y[i] = r.origin.y, p.org_z[i] = r.origin.z;
        p.dir_x[i] = r.dir.x, p.dir_y[i] = r.dir.y, p.dir_z[i] = r.dir.z;
        p.tnear[i] = 0.0f, p.tfar[i] = kInf, p.time[i] = 0.0f;
        p.mask[i] = 0xFFFFFFFFu, p.id[i] = 0, p.flags[i] = 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
        if (valid[i] && log_) log_->push_back({r.origin, kInf, r.dir, RayRecord::Kind::Camera});
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, impl_->scene, &context, &packet);
    for (int i = 0; i < count; ++i) {
        if (!valid[i]) continue;
        Hit& hit = hits[i];
        hit = Hit{};
        if (packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID) {
            hit.t = packet.ray.tfar[i];
            hit.prim = sceneTriangle(packet.hit.geomID[i], packet.hit.primID[i]);
            hit.u = packet.hit.u[i];
            hit.v = packet.hit.v[i];
        }
        addSphereHits(rays[i], kInf, hit);
    }
}

bool Accel::occluded(const Ray& ray, float tfar, int skipLight) const {
    if (log_) log_->push_back({ray.origin, tfar, ray.dir, RayRecord::Kind::Shadow});
    for (size_t i = 0; i < impl_->spheres.size(); ++i) {
        if (int(impl_->sphereLight[i]) == skipLight) continue;
        const glm::vec4& s = impl_->spheres[i];
        if (intersectSphere(ray.origin, ray.dir, Vec3(s), s.w) < tfar) return true;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    fillRay(r, ray, tfar);
    rtcOccluded1(impl_->scene, &context, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf when it finds an occluder
}

size_t Accel::traceBare(const RayRecord* rays, size_t count, Replay mode) const {
    size_t hits = 0;
    std::vector<RTCRay> shadowStream;
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[kPacket];
    int lanes = 0;
    RTCIntersectContext coherent;
    rtcInitIntersectContext(&coherent);
    coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    auto flushPacket = [&] {
        for (int i = lanes; i < kPacket; ++i) valid[i] = 0;
        rtcIntersect8(valid, impl_->scene, &coherent, &packet);
        for (int i = 0; i < lanes; ++i) hits += packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        lanes = 0;
    };
    for (size_t i = 0; i < count; ++i) {
        const RayRecord& r = rays[i];
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        if (r.kind == RayRecord::Kind::Shadow) {
            RTCRay ray;
            fillRay(ray, Ray{r.origin, r.dir}, r.tfar);
            if (mode == Replay::ShadowStreams) {
                shadowStream.push_back(ray);
                continue;
            }
            rtcOccluded1(impl_->scene, &context, &ray);
            hits += ray.tfar < 0.0f;
        } else if (r.kind == RayRecord::Kind::Camera && mode != Replay::OneByOne) {
            RTCRay8& p = packet.ray;
            p.org_x[lanes] = r.origin.x, p.org_y[lanes] = r.origin.y, p.org_z[lanes] = r.origin.z;
            p.dir_x[lanes] = r.dir.x, p.dir_y[lanes] = r.dir.y, p.dir_z[lanes] = r.dir.z;
            p.tnear[lanes] = 0.0f, p.tfar[lanes] = r.tfar, p.time[lanes] = 0.0f;
            p.mask[lanes] = 0xFFFFFFFFu, p.id[lanes] = 0, p.flags[lanes] = 0;
            packet.hit.geomID[lanes] = RTC_INVALID_GEOMETRY_ID;
            valid[lanes++] = -1;
            if (lanes == kPacket) flushPacket();
        } else {
            if (r.kind == RayRecord::Kind::Camera) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            RTCRayHit rh;
            fillRay(rh.ray, Ray{r.origin, r.dir}, r.tfar);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(impl_->scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    if (lanes > 0) flushPacket();
    if (!shadowStream.empty()) {
        rtcOccluded1M(impl_->scene, &coherent, shadowStream.data(), unsigned(shadowStream.size()), sizeof(RTCRay));
        for (const RTCRay& ray : shadowStream) hits += ray.tfar < 0.0f;
    }
    return hits;
}

} // namespace pt
