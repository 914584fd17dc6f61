// Adaptive sampling's decision: which pixels have converged, taken at a pass boundary from the
// film's sums alone, so that the answer does not depend on threads or on the order tiles ran.
//
// A pixel's error is the standard error of its mean relative to its brightness,
//   E = sqrt(s2 / n) / (mean + darkFloor),
// with mean and the sample variance s2 averaged over R, G and B. One pixel's own s2 is a poor
// estimate after a few samples (zero until the first firefly lands), and a pixel that stops on
// an estimate that came out low keeps a mean that is low too (the bias of stopping on one's own
// estimate). So s2 is the largest over the pixel's 3x3 neighbourhood: a pixel stops only when
// none of its neighbours has seen a firefly either. Against the mean over the neighbourhood
// (with the pixel's own), this cut the stopping bias on scenes/glass at E = 0.2 from -0.98 % to
// -0.13 % (bench/tools/adaptive_equal_time.py).
#pragma once

#include "render/film.h"
#include "render/sample_budget.h"

namespace pt {

// The relative error E of pixel (x, y) of `film` as defined above; +inf with fewer than 2 samples.
double relativeError(const Film& film, int x, int y, float darkFloor);

// Marks converged every pixel that holds exactly `samples` samples (those still sampling at this
// boundary), is not converged yet and whose E is at most budget.noise; sets film.decidedAt.
// Returns how many pixels it marked.
size_t markConverged(Film& film, const SampleBudget& budget, uint32_t samples);

} // namespace pt
