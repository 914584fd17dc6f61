// Adaptive sampling's decision (render/convergence.h) on films whose sums are known.
#include "render/convergence.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pt::test {
namespace {

// Adds n grey samples to pixel p: the values alternate a and b (n even).
void addSamples(Film& film, size_t p, uint32_t n, double a, double b) {
    for (uint32_t i = 0; i < n; ++i) {
        double v = i % 2 ? b : a;
        film.add(p, glm::dvec3(v), glm::dvec3(v * v), 1);
    }
}

// Every pixel of a w x h film holds n samples alternating between a and b.
Film uniformFilm(int w, int h, uint32_t n, double a, double b) {
    Film film(w, h);
    film.enableConvergence();
    for (size_t p = 0; p < size_t(w) * h; ++p) addSamples(film, p, n, a, b);
    return film;
}

TEST(Convergence, RelativeErrorIsTheStandardErrorOverTheMean) {
    // Samples 0.5 and 1.5: mean 1, sample variance n/(n-1) * 0.25, standard error sqrt(var / n).
    const uint32_t n = 64;
    Film film = uniformFilm(3, 3, n, 0.5, 1.5);
    double expected = std::sqrt(0.25 * n / (n - 1.0) / n) / (1.0 + double(1e-3f));
    EXPECT_NEAR(relativeError(film, 1, 1, 1e-3f), expected, 1e-12);
    EXPECT_NEAR(relativeError(film, 0, 0, 1e-3f), expected, 1e-12); // a corner pools over the 4 pixels it has
}

TEST(Convergence, FewerThanTwoSamplesIsNeverConverged) {
    Film film(1, 1);
    film.add(0, glm::dvec3(1.0), glm::dvec3(1.0), 1);
    EXPECT_TRUE(std::isinf(relativeError(film, 0, 0, 1e-3f)));
}

TEST(Convergence, AQuietPixelBesideANoisyOneKeepsSampling) {
    // The centre's own samples are all equal (variance 0), its right neighbour's are not: the
    // pooled variance keeps the centre going; its left neighbour, two pixels from the noise, stops.
    // (Relative error of pixel 1: sqrt(max(0, 0, 16/15) / 16) / 1 = 0.26 > 0.05.)
    Film film(3, 1);
    film.enableConvergence();
    addSamples(film, 0, 16, 1.0, 1.0);
    addSamples(film, 1, 16, 1.0, 1.0);
    addSamples(film, 2, 16, 0.0, 2.0);
    SampleBudget budget;
    budget.noise = 0.05f;
    budget.minSpp = 16;
    EXPECT_EQ(markConverged(film, budget, 16), 1u);
    EXPECT_TRUE(film.converged(0));  // its neighbourhood (pixels 0 and 1) is quiet
    EXPECT_FALSE(film.converged(1)); // quiet itself, but beside the noise
    EXPECT_FALSE(film.converged(2));
}

TEST(Convergence, OnlyPixelsStillSamplingAtTheBoundaryAreDecided) {
    Film film = uniformFilm(4, 1, 32, 1.0, 1.0);
    addSamples(film, 3, 8, 1.0, 1.0); // 40 samples: not at this boundary
    film.setConverged(0);
    SampleBudget budget;
    budget.noise = 0.01f;
    budget.minSpp = 16;
    EXPECT_EQ(markConverged(film, budget, 32), 2u); // pixels 1 and 2
    EXPECT_TRUE(film.converged(1) && film.converged(2));
    EXPECT_FALSE(film.converged(3));
    EXPECT_EQ(film.decidedAt, 32u);
    EXPECT_EQ(film.convergedCount(), 3u);
}

TEST(Convergence, NoPixelStopsBeforeMinSpp) {
    Film film = uniformFilm(2, 2, 8, 1.0, 1.0);
    SampleBudget budget;
    budget.noise = 0.5f;
    budget.minSpp = 16;
    EXPECT_EQ(markConverged(film, budget, 8), 0u);
}

TEST(Convergence, ThresholdAndDarkFloor) {
    // Standard error 0.0625 (n = 16, samples 0.75 and 1.25: variance 0.0625 * 16/15).
    Film film = uniformFilm(1, 1, 16, 0.75, 1.25);
    double e = relativeError(film, 0, 0, 0.0f);
    EXPECT_NEAR(e, std::sqrt(0.0625 * 16.0 / 15.0 / 16.0), 1e-12);
    SampleBudget budget;
    budget.minSpp = 16;
    budget.darkFloor = 0.0f;
    budget.noise = float(e) * 0.99f;
    EXPECT_EQ(markConverged(film, budget, 16), 0u);
    budget.noise = float(e) * 1.01f;
    EXPECT_EQ(markConverged(film, budget, 16), 1u);
    // A pixel far below the floor counts as that bright: its relative error shrinks accordingly.
    Film dark = uniformFilm(1, 1, 16, 0.75e-6, 1.25e-6);
    EXPECT_NEAR(relativeError(dark, 0, 0, 1e-3f), e * 1e-6 / (1e-6 + 1e-3), 1e-9);
}

} // namespace
} // namespace pt::test
