#include "accel/accel.h"

#include "accel/embree_scene.h"
#include "io/load_error.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <string>

namespace pt {

namespace {

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
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const uint8_t flags = cut->flags[prim];
        if ((flags & Cutouts::kUnlit) && !(RTCRayN_mask(args->ray, args->N, i) & kCameraRay)) {
            args->valid[i] = 0;
            continue;
        }
        // Embree's Ng points out of the face whose corners run counter-clockwise: the front.
        if ((flags & Cutouts::kCullBack) && (RTCRayN_mask(args->ray, args->N, i) & kCameraRay) &&
            RTCHitN_Ng_x(args->hit, args->N, i) * RTCRayN_dir_x(args->ray, args->N, i) +
                    RTCHitN_Ng_y(args->hit, args->N, i) * RTCRayN_dir_y(args->ray, args->N, i) +
                    RTCHitN_Ng_z(args->hit, args->N, i) * RTCRayN_dir_z(args->ray, args->N, i) > 0.0f) {
            args->valid[i] = 0;
            continue;
        }
        if (!(flags & Cutouts::kCutout)) continue;
        uint32_t tri = cut->triangle[prim];
        float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const Material& m = scene.materials[scene.triMaterial[tri]];
        float coverage = m.coverage * scene.textures->scalar(m.alphaMap, scene.uvAt(tri, u, v), Footprint{});
        if (m.alphaCutoff >= 0.0f) coverage = coverage >= m.alphaCutoff ? 1.0f : 0.0f;
        if (coverage >= 1.0f) continue;
        float coin = coverageCoin(tri, u, v, RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                                  RTCRayN_dir_z(args->ray, args->N, i));
        if (!(coin < coverage)) args->valid[i] = 0; // not there: the ray goes on
    }
}



void sphereBounds(const RTCBoundsFunctionArguments* args) {
    const glm::vec4& s = static_cast<const Spheres*>(args->geometryUserPtr)->centerRadius[args->primID];
    RTCBounds* b = args->bounds_o;
    b->lower_x = s.x - s.w, b->lower_y = s.y - s.w, b->lower_z = s.z - s.w;
    b->upper_x = s.x + s.w, b->upper_y = s.y + s.w, b->upper_z = s.z + s.w;
}

float sphereHit(const Spheres& spheres, unsigned prim, RTCRayN* ray, unsigned n, unsigned i) {
    const glm::vec4& s = spheres.centerRadius[prim];
    Vec3 o(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    Vec3 d(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    float t = intersectSphere(o, d, Vec3(s), s.w);
    return t > RTCRayN_tnear(ray, n, i) && t < RTCRayN_tfar(ray, n, i) ? t : kInf;
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto& spheres = *static_cast<const Spheres*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        float t = sphereHit(spheres, args->primID, ray, args->N, i);
        if (t == kInf) continue;
        RTCRayN_tfar(ray, args->N, i) = t;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_u(hit, args->N, i) = 0.0f;
        RTCHitN_v(hit, args->N, i) = 0.0f;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto& spheres = *static_cast<const Spheres*>(args->geometryUserPtr);
    // Every query that reaches here was started with a QueryContext (Accel's own calls).
    const auto* context = reinterpret_cast<const QueryContext*>(args->context);
    if (int(spheres.light[args->primID]) == context->skipLight) return;
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1 && sphereHit(spheres, args->primID, args->ray, args->N, i) != kInf)
            RTCRayN_tfar(args->ray, args->N, i) = -kInf;
}

} // namespace


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
    auto flagsOf = [](const Material& m) {
        return uint8_t((m.hasCutout() ? Cutouts::kCutout : 0) | (m.unlit ? Cutouts::kUnlit : 0) |
                       (m.cullsBackFaces() ? Cutouts::kCullBack : 0));
    };
    for (const Material& m : scene.materials) anyCutout |= flagsOf(m) != 0;
    if (anyCutout)
        for (size_t t = 0; t < scene.triangleCount(); ++t) {
            const uint8_t flags = flagsOf(scene.materials[scene.triMaterial[t]]);
            if (flags == 0) {
                impl_->opaqueTriangle.push_back(uint32_t(t));
                continue;
            }
            impl_->cutouts.triangle.push_back(uint32_t(t));
            impl_->cutouts.flags.push_back(flags);
        }
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
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LocalLight& l = scene.lights[i];
        if (l.isPoint()) continue;
        impl_->spheres.centerRadius.emplace_back(l.center, l.radius);
        impl_->spheres.light.push_back(uint32_t(i));
    }
    impl_->spheres.inBvh = impl_->spheres.light.size() > kSpheresLooped;
    if (impl_->spheres.inBvh) {
        RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geom, unsigned(impl_->spheres.light.size()));
        rtcSetGeometryUserData(geom, &impl_->spheres);
        rtcSetGeometryBoundsFunction(geom, sphereBounds, nullptr);
        rtcSetGeometryIntersectFunction(geom, sphereIntersect);
        rtcSetGeometryOccludedFunction(geom, sphereOccluded);
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(impl_->scene, geom, kSphereGeometry);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(impl_->scene);
    if (!impl_->error.empty()) throw LoadError(scene.path + ": building the BVH failed: " + impl_->error);
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


Hit Accel::hitOf(unsigned geomID, unsigned primID, float t, float u, float v) const {
    Hit hit;
    if (geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.t = t;
    if (geomID == kSphereGeometry) {
        hit.prim = impl_->spheres.light[primID];
        hit.onSphere = true;
        return hit;
    }
    hit.prim = geomID == kCutoutGeometry      ? impl_->cutouts.triangle[primID]
               : impl_->opaqueTriangle.empty() ? primID
                                               : impl_->opaqueTriangle[primID];
    hit.u = u;
    hit.v = v;
    return hit;
}

void Accel::addLoopedSphereHits(const Ray& ray, float tfar, Hit& hit) const {
    const Spheres& spheres = impl_->spheres;
    if (spheres.inBvh) return;
    for (size_t i = 0; i < spheres.light.size(); ++i) {
        const glm::vec4& s = spheres.centerRadius[i];
        float t = intersectSphere(ray.origin, ray.dir, Vec3(s), s.w);
        if (t < hit.t && t < tfar) {
            hit.t = t;
            hit.prim = spheres.light[i];
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
    Hit hit = hitOf(rh.hit.geomID, rh.hit.primID, rh.ray.tfar, rh.hit.u, rh.hit.v);
    addLoopedSphereHits(ray, tfar, hit);
    return hit;
}

void Accel::intersectCameraRays(const Ray* rays, const bool* active, int count, Hit* hits) const {
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[kPacket];
    for (int i = 0; i < kPacket; ++i) {
        valid[i] = i < count && active[i] ? -1 : 0;
        // Inactive lanes still get finite values: Embree may compute on them before masking.
        const Ray& r = valid[i] ? rays[i] : rays[0];
        fillPacketLane(packet, i, r.origin, r.dir, kInf);
        if (valid[i] && log_) log_->push_back({r.origin, kInf, r.dir, RayRecord::Kind::Camera});
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, impl_->scene, &context, &packet);
    for (int i = 0; i < count; ++i) {
        if (!valid[i]) continue;
        hits[i] = hitOf(packet.hit.geomID[i], packet.hit.primID[i], packet.ray.tfar[i], packet.hit.u[i], packet.hit.v[i]);
        addLoopedSphereHits(rays[i], kInf, hits[i]);
    }
}

bool Accel::occluded(const Ray& ray, float tfar, int skipLight) const {
    if (log_) log_->push_back({ray.origin, tfar, ray.dir, RayRecord::Kind::Shadow, skipLight});
    const Spheres& spheres = impl_->spheres;
    if (!spheres.inBvh)
        for (size_t i = 0; i < spheres.light.size(); ++i) {
            if (int(spheres.light[i]) == skipLight) continue;
            const glm::vec4& s = spheres.centerRadius[i];
            if (intersectSphere(ray.origin, ray.dir, Vec3(s), s.w) < tfar) return true;
        }
    QueryContext context;
    rtcInitIntersectContext(&context.embree);
    context.skipLight = skipLight;
    RTCRay r;
    fillRay(r, ray, tfar);
    rtcOccluded1(impl_->scene, &context.embree, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf when it finds an occluder
}


} // namespace pt
