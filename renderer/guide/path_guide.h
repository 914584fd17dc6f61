// Path guiding: a spatial-directional tree (Müller et al. 2017, "Practical Path Guiding") that
// learns, during training passes, where light arrives from at each region of the scene, so that
// the path loop can sample directions from it beside the BSDF. The space is a binary tree over the
// scene's bounding cube, split at midpoints along x, y, z in turn; each leaf region holds two
// directional quadtrees, one learnt (sampled from) and one learning.
//
// Learning is deterministic: a pass's samples are gathered per image tile (GuideRecorder), reduced
// there in the tile's own order, and added to the tree tile by tile in tile order, so the learnt
// tree, and so the image, do not depend on which thread rendered which tile.
#pragma once

#include "core/math.h"
#include "guide/directional_quadtree.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace pt {

// The guide's shares of a guided vertex's draws that a region may learn to use (the first, none:
// the region is not guided), and the one training draws with, which the choice is learnt from.
inline constexpr float kGuideShares[] = {0.0f, 0.25f, 0.5f, 0.75f, 0.9f};
inline constexpr int kGuideShareCount = 5;
inline constexpr float kTrainingShare = 0.5f;

// How well each share would sample a region's light, from guided samples x = f cos L / p drawn
// with density p: their count, sum, and for each share the second moment its own density q would
// give, the sum of x^2 p / q (an unbiased estimate of the integral of (f cos L)^2 / q over p's
// samples).
struct ShareMoments {
    double count = 0.0, sum = 0.0;
    double second[kGuideShareCount] = {};
    void add(const ShareMoments& o);
    // The share whose variance times its cost is least; a guided vertex costs `guidedCost` times
    // an unguided one.
    float best(double guidedCost) const;
};

// One tile's share of a training pass: (where, energy) pairs as the paths leave them, reduced by
// reduce() to one energy and count per place, in the order they were recorded; and per region
// the samples that measure which share to guide with.
class GuideRecorder {
public:
    void record(uint64_t key, float energy) { records_.emplace_back(key, energy); }
    // A guided sample at `region`: x = f cos L over its density `pdf`, whose parts were the BSDF's
    // density `bsdfPdf` and the guide's `guidePdf` (scatter.h's ScatterParts).
    void recordShare(uint32_t region, float x, float pdf, float bsdfPdf, float guidePdf) {
        shareRecords_.push_back({region, x, pdf, bsdfPdf, guidePdf});
    }
    void reduce();
    void clear() { records_.clear(), sums_.clear(), shareRecords_.clear(), shareSums_.clear(); }

    struct Sum {
        uint64_t key;
        float energy;
        uint32_t count;
    };
    const std::vector<Sum>& sums() const { return sums_; }
    const std::vector<std::pair<uint32_t, ShareMoments>>& shareSums() const { return shareSums_; }

private:
    struct ShareRecord {
        uint32_t region;
        float x, pdf, bsdfPdf, guidePdf;
    };
    std::vector<std::pair<uint64_t, float>> records_;
    std::vector<Sum> sums_;
    std::vector<ShareRecord> shareRecords_;
    std::vector<std::pair<uint32_t, ShareMoments>> shareSums_;
};

class PathGuide {
public:
    // `lo`, `hi`: the scene's bounds; the tree covers the cube around them. Regions stop splitting
    // once the trees take more than `maxBytes`.
    PathGuide(const Vec3& lo, const Vec3& hi, size_t maxBytes = size_t(256) << 20);

    // The leaf region holding p on a surface facing `normal` (a point outside the cube goes to
    // the nearest region).
    uint32_t regionAt(const Vec3& p, const Vec3& normal) const;
    // Whether the region has learnt anything to sample from.
    bool trained(uint32_t region) const { return regions_[region].learnt.energy() > 0.0f; }
    // The guide's share of a draw at the region (0: not guided there): learnt in training, from
    // how well each of kGuideShares would have sampled the region's light, against its cost.
    float share(uint32_t region) const { return regions_[region].guidedShare(); }
    // A world direction drawn from the region's learnt distribution, with its solid-angle density.
    Vec3 sample(uint32_t region, Vec2 u, float& pdf) const;
    float pdf(uint32_t region, const Vec3& dir) const;
    // The region's learnt distribution on the equal-area square (directionOfSquare maps it to
    // directions), for tests.
    const DirectionalQuadtree& learnt(uint32_t region) const { return regions_[region].learnt; }
    // How many times the cube was halved to reach the region holding p.
    int depthAt(const Vec3& p, const Vec3& normal) const;

    // Learning. Where a sample of incident light along `dir` at `region` goes (recordKey), the
    // tiles' reduced records added in tile order (add), then endPass: the learning trees become
    // the learnt ones, crowded regions split, and new learning trees are refined from them.
    uint64_t recordKey(uint32_t region, const Vec3& dir) const;
    void add(const GuideRecorder& tile);
    // `samplesToSplit`: a region that received more samples in this pass is split in two.
    void endPass(uint64_t samplesToSplit);

    // Of the guidable vertices the last pass recorded, the fraction in regions that will be
    // guided now (share > 0).
    double guidedFraction() const { return guidedFraction_; }
    // Whether any region will be guided (share > 0).
    bool guidesAnywhere() const;

    size_t regionCount() const { return regions_.size(); }
    size_t directionalNodes() const;
    // The memory the guide takes, and whether it reached its bound (regions stopped splitting).
    size_t bytes() const;
    bool limited() const { return limited_; }

private:
    // Surfaces facing different ways see light from different halves of the sphere: six trees,
    // one per axis and sign that a surface's normal leans along most, so that a region's
    // distribution is not spread over directions half of its surfaces cannot take.
    static constexpr uint32_t kFacings = 6;
    static uint32_t facing(const Vec3& n);
    uint32_t leafAt(const Vec3& p, const Vec3& normal, int& depth) const;
    struct Node {
        uint32_t child = 0;  // children at child and child + 1; 0: a leaf
        uint32_t region = 0; // a leaf's region
    };
    struct Region {
        DirectionalQuadtree learnt, learning;
        uint64_t samples = 0;          // received this pass
        float share = 0.0f;            // the guide's share of a draw here: none until measured
        ShareMoments moments;          // this pass's measure of the shares
        // The share a draw takes here: none until the region has learnt something to sample.
        float guidedShare() const { return learnt.energy() > 0.0f ? share : 0.0f; }
    };
    void split(uint32_t node, int depth, uint64_t samples, uint64_t samplesToSplit, size_t& bytes);

    Vec3 lo_;
    float size_;
    size_t maxBytes_;
    bool limited_ = false;
    double guidedFraction_ = 1.0;
    std::vector<Node> nodes_;
    std::vector<Region> regions_;
};

} // namespace pt
