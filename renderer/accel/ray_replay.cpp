// pt-bench's replay of recorded rays through bare Embree calls (Accel::traceBare): what the
// traversal alone costs, apart from the path loop around it.
#include "accel/embree_scene.h"

namespace pt {

size_t Accel::traceBare(const RayRecord* rays, size_t count, Replay mode) const {
    size_t hits = 0;
    std::vector<RTCRay> shadowStream;
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[kPacket];
    int lanes = 0;
    // A stream has one context, so its rays cannot each skip their light: a shadow ray aimed at a
    // sphere light may stop at it there (the study times the calls; it does not use the answers).
    QueryContext coherent;
    rtcInitIntersectContext(&coherent.embree);
    coherent.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    auto flushPacket = [&] {
        for (int i = lanes; i < kPacket; ++i) valid[i] = 0;
        rtcIntersect8(valid, impl_->scene, &coherent.embree, &packet);
        for (int i = 0; i < lanes; ++i) hits += packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        lanes = 0;
    };
    for (size_t i = 0; i < count; ++i) {
        const RayRecord& r = rays[i];
        QueryContext query;
        rtcInitIntersectContext(&query.embree);
        query.skipLight = r.skipLight;
        RTCIntersectContext& context = query.embree;
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
            fillPacketLane(packet, lanes, r.origin, r.dir, r.tfar);
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
        rtcOccluded1M(impl_->scene, &coherent.embree, shadowStream.data(), unsigned(shadowStream.size()), sizeof(RTCRay));
        for (const RTCRay& ray : shadowStream) hits += ray.tfar < 0.0f;
    }
    return hits;
}

} // namespace pt
