#include "light/light_tree.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <numeric>

namespace pt {
namespace {

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of two angles in [0, pi].
inline float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
inline float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

// v rotated by `angle` about the unit axis k (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& k, float angle) {
    float c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0f - c));
}

// The smallest cone (axis, cos of half-angle) holding two cones; pbrt-v4's DirectionCone::Union.
void unionCones(Vec3 wa, float cosA, Vec3 wb, float cosB, Vec3& w, float& cosOut) {
    float thetaA = std::acos(std::clamp(cosA, -1.0f, 1.0f)), thetaB = std::acos(std::clamp(cosB, -1.0f, 1.0f));
    float thetaD = std::acos(std::clamp(glm::dot(wa, wb), -1.0f, 1.0f));
    if (std::min(thetaD + thetaB, kPi) <= thetaA) { w = wa, cosOut = cosA; return; }
    if (std::min(thetaD + thetaA, kPi) <= thetaB) { w = wb, cosOut = cosB; return; }
    float thetaO = 0.5f * (thetaA + thetaD + thetaB);
    Vec3 k = glm::cross(wa, wb);
    if (thetaO >= kPi || glm::dot(k, k) < 1e-12f) { w = wa, cosOut = -1.0f; return; }
    w = glm::normalize(rotate(wa, glm::normalize(k), thetaO - thetaA));
    cosOut = std::cos(thetaO);
}

// pbrt-v4's surface area orientation heuristic: power times the solid angle the node's emission
// spans times its box's area, stretched when split along a short axis.
float splitCost(const LightBounds& b, int axis) {
    if (!(b.phi > 0.0f)) return 0.0f;
    float thetaO = std::acos(std::clamp(b.cosThetaO, -1.0f, 1.0f));
    float thetaE = std::acos(std::clamp(b.cosThetaE, -1.0f, 1.0f));
    float thetaW = std::min(thetaO + thetaE, kPi);
    float sinO = safeSqrt(1.0f - b.cosThetaO * b.cosThetaO);
    float mOmega = 2.0f * kPi * (1.0f - b.cosThetaO) +
                   0.5f * kPi * (2.0f * thetaW * sinO - std::cos(thetaO - 2.0f * thetaW) - 2.0f * thetaO * sinO + b.cosThetaO);
    Vec3 d = b.hi - b.lo;
    float area = 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    float kr = d[axis] > 0.0f ? std::max({d.x, d.y, d.z}) / d[axis] : 1.0f;
    return b.phi * mOmega * kr * std::max(area, 1e-20f);
}

} // namespace

LightBounds unionBounds(const LightBounds& a, const LightBounds& b) {
    if (!(a.phi > 0.0f)) return b;
    if (!(b.phi > 0.0f)) return a;
    LightBounds u;
    u.lo = glm::min(a.lo, b.lo);
    u.hi = glm::max(a.hi, b.hi);
    u.phi = a.phi + b.phi;
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    // Bounding lines: a one-sided cone is within the lines of its two-sided self, and b's axis
    // may be flipped to the side nearer a's.
    Vec3 wb = b.axis;
    if (u.twoSided && glm::dot(a.axis, wb) < 0.0f) wb = -wb;
    unionCones(a.axis, a.cosThetaO, wb, b.cosThetaO, u.axis, u.cosThetaO);
    // Lines more than 90 degrees from an axis are the lines on the other side of it.
    if (u.twoSided && u.cosThetaO < 0.0f) u.cosThetaO = -1.0f;
    return u;
}

LightCone::LightCone(const LightBounds& b)
    : center(0.5f * (b.lo + b.hi)), radius2(0.25f * glm::dot(b.hi - b.lo, b.hi - b.lo)), axis(b.axis),
      cosThetaO(b.cosThetaO), sinThetaO(safeSqrt(1.0f - b.cosThetaO * b.cosThetaO)), cosThetaE(b.cosThetaE),
      phi(b.phi), twoSided(b.twoSided) {}

float LightCone::importance(const Vec3& p, const Vec3& n) const {
    if (!(phi > 0.0f)) return 0.0f;
    const float r2 = radius2;
    Vec3 toP = p - center;
    float d2 = glm::dot(toP, toP);
    // Directions from p to the box span at most theta_b about its centre; inside, any.
    float cosB = -1.0f, sinB = 0.0f;
    if (d2 > r2) {
        float sin2 = r2 / d2;
        cosB = safeSqrt(1.0f - sin2), sinB = std::sqrt(sin2);
    }
    Vec3 wi = d2 > 0.0f ? toP / std::sqrt(d2) : Vec3(0.0f, 0.0f, 1.0f);
    // The smallest angle between an emitter's normal and the direction to p, less theta_b.
    float cosW = glm::dot(axis, wi);
    if (twoSided) cosW = std::abs(cosW);
    float sinW = safeSqrt(1.0f - cosW * cosW);
    float cosX = cosSubClamped(sinW, cosW, sinThetaO, cosThetaO);
    float sinX = sinSubClamped(sinW, cosW, sinThetaO, cosThetaO);
    float cosP = cosSubClamped(sinX, cosX, sinB, cosB);
    if (cosP <= cosThetaE) return 0.0f;
    float result = phi * cosP / std::max({d2, r2, 1e-20f});
    if (n != Vec3(0.0f)) { // the receiver's cosine, either side: transmission counts too
        float cosI = std::abs(glm::dot(wi, n));
        float sinI = safeSqrt(1.0f - cosI * cosI);
        result *= cosSubClamped(sinI, cosI, sinB, cosB);
    }
    return std::min(result, FLT_MAX);
}

LightTree::LightTree(const std::vector<LightBounds>& emitters) {
    if (emitters.empty()) return;
    std::vector<uint32_t> order(emitters.size());
    std::iota(order.begin(), order.end(), 0u);
    trail_.assign(emitters.size(), 0);
    nodes_.reserve(2 * emitters.size());
    build(emitters, order, 0, order.size(), 0, 0);
}

uint32_t LightTree::build(const std::vector<LightBounds>& emitters, std::vector<uint32_t>& order, size_t begin,
                          size_t end, uint64_t trail, int depth) {
    uint32_t index = uint32_t(nodes_.size());
    nodes_.emplace_back();
    if (end - begin == 1) {
        nodes_[index] = Node{LightCone(emitters[order[begin]]), order[begin], true};
        trail_[order[begin]] = trail;
        return index;
    }
    LightBounds all;
    Vec3 clo(kInf), chi(-kInf);
    for (size_t i = begin; i < end; ++i) {
        const LightBounds& b = emitters[order[i]];
        all = unionBounds(all, b);
        Vec3 c = 0.5f * (b.lo + b.hi);
        clo = glm::min(clo, c), chi = glm::max(chi, c);
    }
    // Split into 12 buckets along each axis and keep the cheapest plane. Deep in a tree of
    // many coincident emitters (or past 48 levels, so a trail fits 64 bits) split by count.
    constexpr int kBuckets = 12;
    float bestCost = kInf;
    int bestAxis = -1, bestBucket = -1;
    auto bucketOf = [&](uint32_t e, int axis) {
        const LightBounds& b = emitters[e];
        float c = 0.5f * (b.lo[axis] + b.hi[axis]);
        int k = int(kBuckets * (c - clo[axis]) / (chi[axis] - clo[axis]));
        return std::clamp(k, 0, kBuckets - 1);
    };
    for (int axis = 0; axis < 3 && depth < 48; ++axis) {
        if (!(chi[axis] > clo[axis])) continue;
        std::array<LightBounds, kBuckets> buckets;
        for (size_t i = begin; i < end; ++i) {
            int k = bucketOf(order[i], axis);
            buckets[k] = unionBounds(buckets[k], emitters[order[i]]);
        }
        for (int split = 0; split < kBuckets - 1; ++split) {
            LightBounds below, above;
            for (int k = 0; k <= split; ++k) below = unionBounds(below, buckets[k]);
            for (int k = split + 1; k < kBuckets; ++k) above = unionBounds(above, buckets[k]);
            float cost = splitCost(below, axis) + splitCost(above, axis);
            if (cost < bestCost && below.phi > 0.0f && above.phi > 0.0f) bestCost = cost, bestAxis = axis, bestBucket = split;
        }
    }
    size_t mid = begin + (end - begin) / 2;
    bool byCount = bestAxis < 0;
    if (!byCount) {
        auto it = std::partition(order.begin() + begin, order.begin() + end,
                                 [&](uint32_t e) { return bucketOf(e, bestAxis) <= bestBucket; });
        size_t m = size_t(it - order.begin());
        if (m == begin || m == end) byCount = true;
        else mid = m;
    }
    if (byCount) {
        int axis = 0;
        Vec3 extent = chi - clo;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](uint32_t a, uint32_t b) {
            return emitters[a].lo[axis] + emitters[a].hi[axis] < emitters[b].lo[axis] + emitters[b].hi[axis];
        });
    }
    build(emitters, order, begin, mid, trail, depth + 1);
    uint32_t second = build(emitters, order, mid, end, trail | (uint64_t(1) << depth), depth + 1);
    nodes_[index].bounds = LightCone(all);
    nodes_[index].child = second;
    nodes_[index].leaf = false;
    return index;
}

uint32_t LightTree::sample(const Vec3& p, const Vec3& n, float u, float& pmf) const {
    pmf = 0.0f;
    if (nodes_.empty() || !(nodes_[0].bounds.importance(p, n) > 0.0f)) return ~0u;
    float prob = 1.0f;
    uint32_t i = 0;
    while (!nodes_[i].leaf) {
        float a = nodes_[i + 1].bounds.importance(p, n);
        float b = nodes_[nodes_[i].child].bounds.importance(p, n);
        if (!(a + b > 0.0f)) return ~0u;
        // The same quotients as pmf() computes, so the two agree to the bit.
        float pa = a / (a + b), pb = b / (a + b);
        if (u < pa) {
            u = std::min(u / pa, 0x1.fffffep-1f);
            prob *= pa;
            i = i + 1;
        } else {
            u = std::min((u - pa) / pb, 0x1.fffffep-1f);
            prob *= pb;
            i = nodes_[i].child;
        }
    }
    pmf = prob;
    return nodes_[i].child;
}

float LightTree::pmf(const Vec3& p, const Vec3& n, uint32_t emitter) const {
    if (emitter >= trail_.size() || !(nodes_[0].bounds.importance(p, n) > 0.0f)) return 0.0f;
    uint64_t trail = trail_[emitter];
    float prob = 1.0f;
    uint32_t i = 0;
    while (!nodes_[i].leaf) {
        float a = nodes_[i + 1].bounds.importance(p, n);
        float b = nodes_[nodes_[i].child].bounds.importance(p, n);
        if (!(a + b > 0.0f)) return 0.0f;
        bool second = trail & 1;
        prob *= (second ? b : a) / (a + b);
        i = second ? nodes_[i].child : i + 1;
        trail >>= 1;
    }
    return prob;
}

} // namespace pt
