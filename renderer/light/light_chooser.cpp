#include "light/light_chooser.h"

#include <algorithm>

namespace pt {

LightChooser::LightChooser(const std::vector<double>& power, const std::vector<LightBounds>& bounded,
                           std::vector<DistantEstimate> distant)
    : count_(power.size()), distribution_(power), distant_(std::move(distant)), boundedCount_(uint32_t(bounded.size())) {
    if (!bounded.empty()) tree_ = LightTree(bounded);
}

// Each item's weight at a point: the tree's is its root's importance, which for a point light of
// intensity I is 4 pi I / d^2 (4 pi times its irradiance); a distant light's is its irradiance
// on a surface facing it, times the receiver's cosine.
float LightChooser::treeWeight(const Vec3& p, const Vec3& n) const { return tree_.rootImportance(p, n) * (0.25f * kInvPi); }

float LightChooser::distantWeight(size_t j, const Vec3& n) const {
    const DistantEstimate& d = distant_[j];
    if (d.direction == Vec3(0.0f) || n == Vec3(0.0f)) return d.irradiance;
    return d.irradiance * std::abs(glm::dot(d.direction, n));
}

// Between the tree (item 0) and the distant emitters: half of the probability by the weights,
// half evenly, so that an estimate that is off (the weights are rough) can cost at most half of
// the samples and never starve a light. A tree that can light nothing at p gets nothing.
LightChooser::TopChoice LightChooser::topChoice(const Vec3& p, const Vec3& n) const {
    TopChoice t;
    t.treeWeight = treeWeight(p, n);
    t.sum = t.treeWeight;
    for (size_t j = 0; j < distant_.size(); ++j) t.sum += distantWeight(j, n);
    t.items = float(distant_.size() + (t.treeWeight > 0.0f ? 1 : 0));
    return t;
}

uint32_t LightChooser::chooseFromTree(float u, const Vec3& p, const Vec3& n, float& pmf) const {
    const TopChoice top = topChoice(p, n);
    float cdf = 0.0f;
    if (top.treeWeight > 0.0f) {
        float pTree = top.probability(top.treeWeight);
        if (u < pTree || distant_.empty()) {
            float pLeaf;
            uint32_t e = tree_.sample(p, n, std::min(u / pTree, 0x1.fffffep-1f), pLeaf);
            pmf = pTree * pLeaf;
            return e;
        }
        cdf = pTree;
    }
    for (size_t j = 0; j < distant_.size(); ++j) {
        float pj = top.probability(distantWeight(j, n));
        cdf += pj;
        if (u < cdf || j + 1 == distant_.size()) {
            pmf = pj;
            return boundedCount_ + uint32_t(j);
        }
    }
    pmf = 0.0f;
    return ~0u;
}

float LightChooser::pmfFromTree(size_t i, const Vec3& p, const Vec3& n) const {
    const TopChoice top = topChoice(p, n);
    if (i >= boundedCount_) return top.probability(distantWeight(i - boundedCount_, n));
    if (!(top.treeWeight > 0.0f)) return 0.0f;
    return top.probability(top.treeWeight) * tree_.pmf(p, n, uint32_t(i));
}

} // namespace pt
