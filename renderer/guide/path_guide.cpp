#include "guide/path_guide.h"

#include <algorithm>
#include <cmath>

namespace pt {
namespace {

// A quadrant holding more than this share of a region's light is split when the next learning
// tree is made (Müller et al.'s rho).
constexpr float kSplitShare = 0.01f;
// The spatial tree's deepest level: 2^-8 of the scene along each axis.
constexpr int kMaxSpatialDepth = 24;
// A region chooses its share from at least this many guided samples; with fewer it keeps the
// share it had, none at first: a guide learnt from one or two passes is not trusted unmeasured.
constexpr double kShareSamples = 256.0;
// What a guided vertex costs against an unguided one (the guide's density looked up for the
// sampled direction and the light sample's, and a draw from it): a share must cut the variance
// by more than this to be worth guiding with. Measured at equal time (glass, cornellbottle2,
// cornell_textured; 20 s, 2 seeds), 3 beat 2 and 1.25 on each: the variance a region's few
// hundred training samples predict for a share is optimistic, and guiding where it cuts less
// than this lost time.
constexpr double kGuidedCost = 3.0;

} // namespace

void ShareMoments::add(const ShareMoments& o) {
    count += o.count;
    sum += o.sum;
    for (int k = 0; k < kGuideShareCount; ++k) second[k] += o.second[k];
}

float ShareMoments::best(double guidedCost) const {
    const double mean = sum / count;
    int best = 0;
    double bestCost = 0.0;
    for (int k = 0; k < kGuideShareCount; ++k) {
        const double variance = std::max(0.0, second[k] / count - mean * mean);
        const double cost = variance * (kGuideShares[k] > 0.0f ? guidedCost : 1.0);
        if (k == 0 || cost < bestCost) best = k, bestCost = cost;
    }
    return kGuideShares[best];
}

void GuideRecorder::reduce() {
    // Stable: records of one place keep the order the paths left them, so their sum is the same
    // on every run.
    std::stable_sort(records_.begin(), records_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    sums_.clear();
    for (const auto& [key, energy] : records_) {
        if (sums_.empty() || sums_.back().key != key) sums_.push_back({key, 0.0f, 0});
        sums_.back().energy += energy;
        ++sums_.back().count;
    }
    records_.clear();
    std::stable_sort(shareRecords_.begin(), shareRecords_.end(), [](const auto& a, const auto& b) { return a.region < b.region; });
    shareSums_.clear();
    for (const ShareRecord& r : shareRecords_) {
        if (shareSums_.empty() || shareSums_.back().first != r.region) shareSums_.push_back({r.region, ShareMoments{}});
        ShareMoments& m = shareSums_.back().second;
        m.count += 1.0;
        m.sum += r.x;
        const double x2p = double(r.x) * r.x * r.pdf;
        for (int k = 0; k < kGuideShareCount; ++k) {
            const double q = (1.0 - kGuideShares[k]) * r.bsdfPdf + kGuideShares[k] * double(r.guidePdf);
            // A share that could not have drawn a direction that carried light misses it: its
            // estimate is biased there, never to be chosen.
            m.second[k] += q > 0.0 ? x2p / q : r.x > 0.0f ? HUGE_VAL : 0.0;
        }
    }
    shareRecords_.clear();
}

PathGuide::PathGuide(const Vec3& lo, const Vec3& hi, size_t maxBytes)
    : maxBytes_(maxBytes), nodes_(kFacings), regions_(kFacings) {
    for (uint32_t f = 0; f < kFacings; ++f) nodes_[f].region = f;
    const Vec3 extent = hi - lo;
    size_ = std::max({extent.x, extent.y, extent.z, 1e-6f}) * 1.0001f;
    lo_ = 0.5f * (lo + hi) - Vec3(0.5f * size_);
}

// The root of the tree for surfaces facing n: along which axis n leans most, and which way.
uint32_t PathGuide::facing(const Vec3& n) {
    const Vec3 a = glm::abs(n);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return uint32_t(2 * axis + (n[axis] < 0.0f));
}

// The leaf node holding p on a surface facing `normal`, and how many halvings led to it.
uint32_t PathGuide::leafAt(const Vec3& p, const Vec3& normal, int& depth) const {
    Vec3 x = (p - lo_) / size_; // in the unit cube
    uint32_t n = facing(normal);
    depth = 0;
    for (int axis = 0; nodes_[n].child != 0; axis = axis == 2 ? 0 : axis + 1, ++depth) {
        const int upper = x[axis] >= 0.5f;
        x[axis] = 2.0f * x[axis] - float(upper);
        n = nodes_[n].child + uint32_t(upper);
    }
    return n;
}

uint32_t PathGuide::regionAt(const Vec3& p, const Vec3& normal) const {
    int depth;
    return nodes_[leafAt(p, normal, depth)].region;
}

int PathGuide::depthAt(const Vec3& p, const Vec3& normal) const {
    int depth;
    leafAt(p, normal, depth);
    return depth;
}

Vec3 PathGuide::sample(uint32_t region, Vec2 u, float& pdf) const {
    Vec2 x = regions_[region].learnt.sample(u, pdf);
    pdf *= 1.0f / (4.0f * kPi);
    return directionOfSquare(x);
}

float PathGuide::pdf(uint32_t region, const Vec3& dir) const {
    return regions_[region].learnt.pdf(squareOfDirection(dir)) * (1.0f / (4.0f * kPi));
}

uint64_t PathGuide::recordKey(uint32_t region, const Vec3& dir) const {
    return uint64_t(region) << 32 | regions_[region].learning.quadrantOf(squareOfDirection(dir));
}

void PathGuide::add(const GuideRecorder& tile) {
    for (const GuideRecorder::Sum& s : tile.sums()) {
        Region& r = regions_[size_t(s.key >> 32)];
        r.learning.add(uint32_t(s.key), s.energy);
        r.samples += s.count;
    }
    for (const auto& [region, moments] : tile.shareSums()) regions_[region].moments.add(moments);
}

void PathGuide::endPass(uint64_t samplesToSplit) {
    uint64_t samples = 0, guidedSamples = 0;
    for (Region& r : regions_) {
        if (r.moments.count >= kShareSamples) r.share = r.moments.best(kGuidedCost);
        r.moments = ShareMoments{};
        r.learning.sumUp();
        // A region that learnt nothing this pass keeps what it knew.
        if (r.learning.energy() > 0.0f) r.learnt = std::move(r.learning);
        r.learning = r.learnt.refined(kSplitShare);
        samples += r.samples;
        if (r.guidedShare() > 0.0f) guidedSamples += r.samples;
    }
    guidedFraction_ = samples > 0 ? double(guidedSamples) / double(samples) : 0.0;
    // Past the bound, regions stop splitting and the trees coarsen (a quadrant must hold twice
    // the share to be split, again until they fit), keeping the energy they learnt.
    for (float share = 2.0f * kSplitShare; bytes() > maxBytes_ && share <= 1.0f; share *= 2.0f) {
        limited_ = true;
        for (Region& r : regions_) {
            r.learnt = r.learnt.refined(share);
            r.learnt.sumUp();
            r.learning = r.learnt.refined(share);
        }
    }
    size_t bytesAfter = bytes(); // what the guide will take, as split() adds to it
    // Depth-first over the leaves as they are now; split() appends nodes and regions.
    const size_t leaves = nodes_.size();
    std::vector<int> depth(leaves, 0);
    for (size_t n = 0; n < leaves && !limited_; ++n) {
        if (nodes_[n].child) {
            depth[nodes_[n].child] = depth[n] + 1;
            depth[nodes_[n].child + 1] = depth[n] + 1;
            continue;
        }
        split(uint32_t(n), depth[n], regions_[nodes_[n].region].samples, samplesToSplit, bytesAfter);
    }
    for (Region& r : regions_) r.samples = 0;
}

// A leaf with more samples than `samplesToSplit` becomes two, each with a copy of what it learnt
// and, as far as anyone knows, half its samples; again until none has too many. Past the memory
// bound no region is made.
void PathGuide::split(uint32_t node, int depth, uint64_t samples, uint64_t samplesToSplit, size_t& bytes) {
    if (samples <= samplesToSplit || depth >= kMaxSpatialDepth || limited_) return;
    const uint32_t region = nodes_[node].region, child = uint32_t(nodes_.size());
    const Region& r = regions_[region];
    const size_t cost =
        (r.learnt.nodeCount() + r.learning.nodeCount()) * DirectionalQuadtree::kNodeBytes + sizeof(Region) + 2 * sizeof(Node);
    if (bytes + cost > maxBytes_) {
        limited_ = true;
        return;
    }
    bytes += cost;
    nodes_.resize(nodes_.size() + 2);
    nodes_[node].child = child;
    nodes_[child].region = region;
    nodes_[child + 1].region = uint32_t(regions_.size());
    regions_.push_back(Region{regions_[region].learnt, regions_[region].learning, 0, regions_[region].share, {}});
    split(child, depth + 1, samples / 2, samplesToSplit, bytes);
    split(child + 1, depth + 1, samples / 2, samplesToSplit, bytes);
}

bool PathGuide::guidesAnywhere() const {
    for (const Region& r : regions_)
        if (r.guidedShare() > 0.0f) return true;
    return false;
}

size_t PathGuide::bytes() const {
    size_t quadtreeNodes = 0;
    for (const Region& r : regions_) quadtreeNodes += r.learnt.nodeCount() + r.learning.nodeCount();
    return quadtreeNodes * DirectionalQuadtree::kNodeBytes + nodes_.size() * sizeof(Node) + regions_.size() * sizeof(Region);
}

size_t PathGuide::directionalNodes() const {
    size_t n = 0;
    for (const Region& r : regions_) n += r.learnt.nodeCount();
    return n;
}

} // namespace pt
