// A bounding-volume hierarchy over a scene's bounded emitters (sphere, point and spot lights,
// emissive triangles) that picks one for next-event estimation in proportion to an estimate of
// what it sends to the shading point: power, distance, the emitters' orientation and the
// receiver's normal (Conty Estevez and Kulla 2018, in pbrt-v4's form). With thousands of small
// emitters most are far or facing away from any one point; choosing by power alone wastes
// nearly every shadow ray on them.
#pragma once

#include "core/math.h"

#include <cstdint>
#include <vector>

namespace pt {

// How a LightSet picks an emitter for next-event estimation: by power alone, or by the tree's
// estimate at the shading point. Auto takes the tree when there are 2 or more bounded emitters,
// or bounded emitters beside distant ones (environment, sun, directional lights).
enum class LightChoice : uint8_t { Auto, Power, Tree };

// What a node knows of the emitters below it: where they are, where their surfaces face, and
// how much light they send. Normals lie within theta_o of `axis`; each emits within theta_e of
// its normal. Two-sided emitters (our triangles emit from both faces) bound lines, not
// directions: axis and -axis are the same, which keeps a flat panel's cone narrow.
struct LightBounds {
    Vec3 lo{kInf}, hi{-kInf};
    Vec3 axis{0.0f, 0.0f, 1.0f};
    float cosThetaO = -1.0f; // -1: normals in every direction (spheres, points)
    float cosThetaE = 0.0f;  // 0: emits over the hemisphere of its normal (area lights)
    float phi = 0.0f;        // power
    bool twoSided = false;
};

LightBounds unionBounds(const LightBounds& a, const LightBounds& b);

// A node's bounds as the importance estimate reads them: the box as its bounding sphere, and
// the sines it would otherwise recompute per query.
struct LightCone {
    Vec3 center;
    float radius2;
    Vec3 axis;
    float cosThetaO, sinThetaO, cosThetaE;
    float phi;
    bool twoSided;

    explicit LightCone(const LightBounds& b);
    LightCone() = default;
    // An estimate of the light that reaches p (with shading normal n, or n = 0 for none) from
    // these emitters; never 0 where one of them can light p.
    float importance(const Vec3& p, const Vec3& n) const;
};

class LightTree {
public:
    LightTree() = default;
    // One bounds per emitter; emitter i is the caller's index i.
    explicit LightTree(const std::vector<LightBounds>& emitters);

    bool empty() const { return nodes_.empty(); }
    // The whole tree's importance at p (0: no emitter of it can light p).
    float rootImportance(const Vec3& p, const Vec3& n) const { return nodes_.empty() ? 0.0f : nodes_[0].bounds.importance(p, n); }
    // Picks an emitter for a shading point; ~0u when none can light it.
    uint32_t sample(const Vec3& p, const Vec3& n, float u, float& pmf) const;
    // The probability that sample() picks `emitter` at p.
    float pmf(const Vec3& p, const Vec3& n, uint32_t emitter) const;
    size_t nodeCount() const { return nodes_.size(); }

private:
    struct Node {
        LightCone bounds;
        uint32_t child = 0; // interior: index of the second child (the first follows the node); leaf: the emitter
        bool leaf = false;
    };
    uint32_t build(const std::vector<LightBounds>& emitters, std::vector<uint32_t>& order, size_t begin,
                   size_t end, uint64_t trail, int depth);

    std::vector<Node> nodes_;
    // Per emitter, the path from the root to its leaf: bit k set = second child at depth k.
    std::vector<uint64_t> trail_;
};

} // namespace pt
