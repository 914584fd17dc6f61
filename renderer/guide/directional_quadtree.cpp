#include "guide/directional_quadtree.h"

#include <algorithm>
#include <cmath>

namespace pt {
namespace {

constexpr float kBelowOne = 0x1.fffffep-1f;

// Picks the lower half (0) or the upper (1) of a split whose lower half has share `p`, and
// stretches u over the chosen half, so that one uniform value serves every level.
inline int chooseHalf(float p, float& u) {
    if (u < p) {
        u = std::min(u / p, kBelowOne);
        return 0;
    }
    u = std::min((u - p) / (1.0f - p), kBelowOne);
    return 1;
}

} // namespace

Vec3 directionOfSquare(Vec2 x) {
    const float z = 2.0f * x.x - 1.0f;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * x.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

Vec2 squareOfDirection(const Vec3& dir) {
    float phi = std::atan2(dir.y, dir.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return Vec2(std::clamp(0.5f * (dir.z + 1.0f), 0.0f, kBelowOne), std::clamp(phi * (0.5f / kPi), 0.0f, kBelowOne));
}

uint32_t DirectionalQuadtree::quadrantOf(Vec2 x) const {
    uint32_t n = 0;
    for (;;) {
        const int qx = x.x >= 0.5f, qy = x.y >= 0.5f;
        const int q = qx + 2 * qy;
        const uint32_t c = nodes_[n].child[q];
        if (c == 0) return n * 4 + uint32_t(q);
        x = Vec2(2.0f * x.x - float(qx), 2.0f * x.y - float(qy));
        n = c;
    }
}

void DirectionalQuadtree::sumUp() {
    for (size_t i = nodes_.size(); i-- > 0;) { // children after parents: bottom-up
        Node& node = nodes_[i];
        for (int q = 0; q < 4; ++q)
            if (uint32_t c = node.child[q]) {
                const Node& child = nodes_[c];
                node.energy[q] = child.energy[0] + child.energy[1] + child.energy[2] + child.energy[3];
            }
    }
}

float DirectionalQuadtree::energy() const {
    const Node& root = nodes_[0];
    return root.energy[0] + root.energy[1] + root.energy[2] + root.energy[3];
}

Vec2 DirectionalQuadtree::sample(Vec2 u, float& pdf) const {
    uint32_t n = 0;
    Vec2 origin(0.0f);
    float size = 1.0f, density = 1.0f;
    for (;;) {
        const Node& node = nodes_[n];
        const float* e = node.energy;
        const float total = e[0] + e[1] + e[2] + e[3];
        // The column (x) first, then the quadrant within it (y).
        const int qx = chooseHalf((e[0] + e[2]) / total, u.x);
        const int qy = chooseHalf(e[qx] / (e[qx] + e[qx + 2]), u.y);
        const int q = qx + 2 * qy;
        density *= 4.0f * e[q] / total;
        size *= 0.5f;
        origin += size * Vec2(float(qx), float(qy));
        if (node.child[q] == 0) {
            pdf = density;
            return origin + size * u;
        }
        n = node.child[q];
    }
}

float DirectionalQuadtree::pdf(Vec2 x) const {
    uint32_t n = 0;
    float density = 1.0f;
    for (;;) {
        const Node& node = nodes_[n];
        const float* e = node.energy;
        const float total = e[0] + e[1] + e[2] + e[3];
        if (!(total > 0.0f)) return 0.0f;
        const int qx = x.x >= 0.5f, qy = x.y >= 0.5f;
        const int q = qx + 2 * qy;
        density *= 4.0f * e[q] / total;
        if (node.child[q] == 0 || density == 0.0f) return density;
        x = Vec2(2.0f * x.x - float(qx), 2.0f * x.y - float(qy));
        n = node.child[q];
    }
}

double DirectionalQuadtree::mass(Vec2 lo, Vec2 hi) const {
    return energy() > 0.0f ? massIn(0, Vec2(0.0f), 1.0, lo, hi) : 0.0;
}

// The share of node `n`'s probability (its cell at `origin`, `size` wide) inside [lo, hi).
double DirectionalQuadtree::massIn(uint32_t n, Vec2 origin, double size, Vec2 lo, Vec2 hi) const {
    const Node& node = nodes_[n];
    const float* e = node.energy;
    const double total = double(e[0]) + e[1] + e[2] + e[3], half = 0.5 * size;
    double sum = 0.0;
    for (int q = 0; q < 4; ++q) {
        const double x0 = origin.x + half * (q & 1), y0 = origin.y + half * (q >> 1);
        const double w = std::min<double>(hi.x, x0 + half) - std::max<double>(lo.x, x0);
        const double h = std::min<double>(hi.y, y0 + half) - std::max<double>(lo.y, y0);
        if (w <= 0.0 || h <= 0.0 || e[q] <= 0.0f) continue;
        const double share = e[q] / total;
        sum += node.child[q] == 0 ? share * (w * h) / (half * half)
                                  : share * massIn(node.child[q], Vec2(float(x0), float(y0)), half, lo, hi);
    }
    return sum;
}

DirectionalQuadtree DirectionalQuadtree::refined(float fraction) const {
    DirectionalQuadtree out;
    const float total = energy();
    if (total > 0.0f) refineInto(out, 0, 0, nodes_[0].energy, fraction * total, 1);
    return out;
}

// Node `at` of `out` stands where node `old` of this tree stood (-1: below this tree's leaves,
// its quadrants' energy shared out evenly from the leaf above), with quadrant energies `energy`.
void DirectionalQuadtree::refineInto(DirectionalQuadtree& out, uint32_t at, int old, const float (&energy)[4], float least,
                                     int depth) const {
    for (int q = 0; q < 4; ++q) out.nodes_[at].energy[q] = energy[q]; // leaves keep it; sumUp() redoes the rest
    if (depth >= kMaxDepth) return;
    for (int q = 0; q < 4; ++q) {
        if (!(energy[q] > least)) continue;
        const uint32_t child = uint32_t(out.nodes_.size());
        out.nodes_.emplace_back();
        out.nodes_[at].child[q] = child;
        const int oldChild = old >= 0 && nodes_[size_t(old)].child[q] != 0 ? int(nodes_[size_t(old)].child[q]) : -1;
        float childEnergy[4];
        for (int k = 0; k < 4; ++k) childEnergy[k] = oldChild >= 0 ? nodes_[size_t(oldChild)].energy[k] : 0.25f * energy[q];
        refineInto(out, child, oldChild, childEnergy, least, depth + 1);
    }
}

int DirectionalQuadtree::depth() const {
    std::vector<int> level(nodes_.size(), 1);
    int deepest = 1;
    for (size_t i = 0; i < nodes_.size(); ++i)
        for (uint32_t c : nodes_[i].child)
            if (c) deepest = std::max(deepest, level[c] = level[i] + 1);
    return deepest;
}

} // namespace pt
