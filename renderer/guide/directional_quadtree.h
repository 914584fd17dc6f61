// Where light comes from at one region of a scene, as a distribution over directions: a quadtree
// over the square [0,1)^2 of the sphere's equal-area map (cos theta = 2x - 1, phi = 2 pi y), after
// Müller et al. 2017, "Practical Path Guiding". Each node holds the energy of its four quadrants;
// a quadrant is a leaf or a node of its own. Sampling descends by the energies, so the density on
// the square is the product of the chosen quadrants' shares times 4 per level; on the sphere it
// is that over 4 pi, the map being equal-area.
#pragma once

#include "core/math.h"

#include <cstdint>
#include <vector>

namespace pt {

// The equal-area map between the unit square and the unit sphere, both ways.
Vec3 directionOfSquare(Vec2 x);
Vec2 squareOfDirection(const Vec3& dir);

class DirectionalQuadtree {
public:
    static constexpr int kMaxDepth = 20; // levels below the root; a quadrant 2^-20 wide is ~1e-11 sr

    DirectionalQuadtree() : nodes_(1) {}

    // Where energy for a point of the square goes: node * 4 + quadrant, valid until the tree is
    // rebuilt. add() puts energy there; sumUp() then gives each inner quadrant its children's sum.
    uint32_t quadrantOf(Vec2 x) const;
    void add(uint32_t quadrant, float energy) { nodes_[quadrant >> 2].energy[quadrant & 3] += energy; }
    void sumUp();
    float energy() const;

    // A point of the square drawn by energy, with its density on the square; the tree must have
    // energy. pdf() is that density anywhere.
    Vec2 sample(Vec2 u, float& pdf) const;
    float pdf(Vec2 x) const;
    // The probability that sample() lands in the rectangle [lo, hi) of the square, exactly (the
    // density is constant on each leaf quadrant): for tests of sample() and pdf().
    double mass(Vec2 lo, Vec2 hi) const;

    // The structure for the next round of learning: a quadrant holding more than `fraction` of
    // the total energy is a node (split further down to kMaxDepth), any other a leaf. It keeps
    // this tree's energy (a new quadrant below an old leaf a quarter of it), so that the next
    // round adds to what was learnt rather than starting again: every round's estimate is
    // unbiased, and a training budget of a few samples per pixel is too small to throw any away.
    DirectionalQuadtree refined(float fraction) const;

    size_t nodeCount() const { return nodes_.size(); }
    static constexpr size_t kNodeBytes = 32; // four energies, four children
    int depth() const;

private:
    struct Node {
        float energy[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        uint32_t child[4] = {0, 0, 0, 0}; // 0: the quadrant is a leaf (node 0 is the root, no one's child)
    };
    double massIn(uint32_t node, Vec2 origin, double size, Vec2 lo, Vec2 hi) const;
    void refineInto(DirectionalQuadtree& out, uint32_t at, int old, const float (&energy)[4], float least, int depth) const;

    std::vector<Node> nodes_; // a node's children come after it
    static_assert(sizeof(Node) == kNodeBytes);
};

} // namespace pt
