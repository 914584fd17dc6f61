// How next-event estimation picks one emitter of the light set: by power, or, with many bounded
// emitters, the distant ones by an estimate of their irradiance at the shading point and the
// bounded ones through a light tree that weighs them as seen from there. Knows the emitters only
// by their power, bounds and estimates: light_set.cpp gives those.
#pragma once

#include "core/math.h"
#include "light/light_tree.h"
#include "sampling/distribution1d.h"

#include <vector>

namespace pt {

// What a distant emitter (environment, sun, directional light) sends to a point, for the choice.
struct DistantEstimate {
    Vec3 direction{0.0f}; // towards the light, for the receiver's cosine; 0: none (environment)
    float irradiance = 0.0f;
};

class LightChooser {
public:
    LightChooser() = default;
    // `power`: every emitter's, the bounded ones first. With `bounded` not empty, a tree is
    // built over them (bounded.size() of them) and `distant` gives the rest, in order.
    LightChooser(const std::vector<double>& power, const std::vector<LightBounds>& bounded,
                 std::vector<DistantEstimate> distant);

    // Picks an emitter at p, whose shading normal is n (0: none). Returns ~0u with pmf 0 when
    // the tree finds no emitter that can light p.
    uint32_t choose(float u, const Vec3& p, const Vec3& n, float& pmf) const {
        if (count_ == 1) { // the common case of one lab light: no search
            pmf = 1.0f;
            return 0;
        }
        if (!usesTree()) return uint32_t(distribution_.sample(u, &pmf));
        return chooseFromTree(u, p, n, pmf);
    }
    // The probability that choose() at p picks emitter i.
    float pmf(size_t i, const Vec3& p, const Vec3& n) const {
        if (count_ == 1) return 1.0f;
        return usesTree() ? pmfFromTree(i, p, n) : distribution_.pmf(i);
    }
    bool usesTree() const { return !tree_.empty(); }

private:
    uint32_t chooseFromTree(float u, const Vec3& p, const Vec3& n, float& pmf) const;
    float pmfFromTree(size_t i, const Vec3& p, const Vec3& n) const;
    float distantWeight(size_t j, const Vec3& n) const;
    float treeWeight(const Vec3& p, const Vec3& n) const;
    // The weights at a point that chooseFromTree and pmfFromTree both divide up.
    struct TopChoice {
        float treeWeight = 0.0f, sum = 0.0f, items = 0.0f;
        float probability(float w) const { return sum > 0.0f ? 0.5f * w / sum + 0.5f / items : 1.0f / items; }
    };
    TopChoice topChoice(const Vec3& p, const Vec3& n) const;

    size_t count_ = 0;
    Distribution1D distribution_; // all emitters by power
    // With a tree: the bounded emitters (indices below boundedCount_) are its leaves, and the
    // distant ones (from boundedCount_ on) compete with the tree as a whole at each point, by
    // an estimate of the irradiance each sends there (see chooseFromTree).
    LightTree tree_;
    std::vector<DistantEstimate> distant_;
    uint32_t boundedCount_ = 0;
};

} // namespace pt
