#include "render/convergence.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace pt {
namespace {

// A pixel's sample variance and mean, averaged over its channels; variance -1 below 2 samples.
struct PixelStats {
    double variance = -1.0, mean = 0.0;
};

PixelStats statsOf(const Film& film, size_t p) {
    PixelStats s;
    const double n = film.count(p);
    if (n < 1.0) return s;
    const glm::dvec3 m = film.sum(p) / n;
    s.mean = (m.x + m.y + m.z) / 3.0;
    if (n < 2.0) return s;
    const glm::dvec3 var = glm::max(glm::dvec3(0.0), (film.sumSq(p) - n * m * m) / (n - 1.0));
    s.variance = (var.x + var.y + var.z) / 3.0;
    return s;
}

} // namespace

double relativeError(const Film& film, int x, int y, float darkFloor) {
    const int w = film.width(), h = film.height();
    const size_t p = size_t(y) * size_t(w) + size_t(x);
    const PixelStats own = statsOf(film, p);
    if (own.variance < 0.0) return std::numeric_limits<double>::infinity();
    double pooled = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            const PixelStats s = statsOf(film, size_t(ny) * size_t(w) + size_t(nx));
            if (s.variance < 0.0) continue;
            pooled = std::max(pooled, s.variance);
        }
    return std::sqrt(pooled / double(film.count(p))) / (own.mean + double(darkFloor));
}

size_t markConverged(Film& film, const SampleBudget& budget, uint32_t samples) {
    // Each pixel's answer reads only sums, which marking leaves alone: rows in any order give the same marks.
    const int w = film.width();
    std::atomic<size_t> marked{0};
    tbb::parallel_for(0, film.height(), [&](int y) {
        size_t here = 0;
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * size_t(w) + size_t(x);
            if (film.converged(p) || film.count(p) != samples || samples < budget.minSpp) continue;
            if (relativeError(film, x, y, budget.darkFloor) <= double(budget.noise)) {
                film.setConverged(p);
                ++here;
            }
        }
        marked += here;
    });
    film.decidedAt = samples;
    return marked;
}

} // namespace pt
