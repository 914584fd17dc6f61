// Per-pixel sums of radiance samples and of their squares, from which the mean image and the
// variance of that mean are derived. Each pixel is written by one task at a time, so no locks.
// Counts are per pixel, so a render stopped part-way through a pass still gives a correct mean.
#pragma once

#include "core/math.h"

#include <glm/gtc/type_precision.hpp>

#include <vector>

namespace pt {

class Film {
public:
    Film(int width, int height)
        : width_(width), height_(height), count_(size_t(width) * height, 0),
          sum_(size_t(width) * height, glm::dvec3(0.0)), sumSq_(size_t(width) * height, glm::dvec3(0.0)) {}

    int width() const { return width_; }
    int height() const { return height_; }
    // Fewest and most samples any pixel holds, and their mean, in one pass over the counts.
    struct SampleCounts {
        uint32_t fewest = 0, most = 0;
        double mean = 0.0;
    };
    SampleCounts sampleCounts() const;

    void add(size_t pixel, const glm::dvec3& sum, const glm::dvec3& sumSq, uint32_t n) {
        count_[pixel] += n;
        sum_[pixel] += sum;
        sumSq_[pixel] += sumSq;
    }

    // First-hit layers (albedo, shading normal, distance), allocated only when asked for.
    void enableFirstHitLayers();
    bool hasFirstHitLayers() const { return !albedo_.empty(); }
    void addFirstHit(size_t pixel, const glm::dvec3& albedo, const glm::dvec3& normal, double depth, uint32_t hits) {
        albedo_[pixel] += albedo;
        normal_[pixel] += normal;
        depth_[pixel] += depth;
        hits_[pixel] += hits;
    }
    std::vector<float> albedo() const; // mean over samples, RGB
    std::vector<float> normal() const; // mean over samples, renormalized; 0 where nothing was hit
    std::vector<float> depth() const;  // mean distance over samples that hit; +inf where none did

    // The raw sums of one pixel, for parts (render/film_part.h) and merging them.
    uint32_t count(size_t pixel) const { return count_[pixel]; }
    const glm::dvec3& sum(size_t pixel) const { return sum_[pixel]; }
    const glm::dvec3& sumSq(size_t pixel) const { return sumSq_[pixel]; }
    const glm::dvec3& albedoSum(size_t pixel) const { return albedo_[pixel]; }
    const glm::dvec3& normalSum(size_t pixel) const { return normal_[pixel]; }
    double depthSum(size_t pixel) const { return depth_[pixel]; }
    uint32_t hits(size_t pixel) const { return hits_[pixel]; }
    // Adds everything pixel `from` of `other` holds to pixel `to` of this film.
    void addPixel(size_t to, const Film& other, size_t from) {
        add(to, other.sum_[from], other.sumSq_[from], other.count_[from]);
        if (hasFirstHitLayers() && other.hasFirstHitLayers())
            addFirstHit(to, other.albedo_[from], other.normal_[from], other.depth_[from], other.hits_[from]);
    }

    // Interleaved RGB float images of the mean and of its variance (sample variance / n).
    std::vector<float> mean() const;
    std::vector<float> varianceOfMean() const; // +inf where a pixel holds fewer than 2 samples
    std::vector<float> samples() const; // each pixel's count, as float (exact below 2^24)

    // Adaptive sampling (render/convergence.h): which pixels have stopped, and the sample count
    // of the pass boundary at which that was last decided (a resumed render decides from there
    // on, so that it stops the pixels an uninterrupted one would). Empty unless enabled.
    void enableConvergence() { converged_.assign(count_.size(), 0); }
    bool hasConvergence() const { return !converged_.empty(); }
    bool converged(size_t pixel) const { return !converged_.empty() && converged_[pixel] != 0; }
    void setConverged(size_t pixel) { converged_[pixel] = 1; }
    size_t convergedCount() const;
    uint32_t decidedAt = 0;

private:
    // Each pixel's sum divided by its sample count (0 where it has none), as RGB floats.
    std::vector<float> perSample(const std::vector<glm::dvec3>& sums) const;

    int width_, height_;
    std::vector<uint32_t> count_;
    std::vector<glm::dvec3> sum_, sumSq_;
    std::vector<glm::dvec3> albedo_, normal_;
    std::vector<double> depth_;
    std::vector<uint32_t> hits_;
    std::vector<uint8_t> converged_;
};

} // namespace pt
