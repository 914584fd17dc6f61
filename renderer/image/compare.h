// Statistical comparison of a Monte Carlo render against a reference. Two renders of the same
// physics never match bit for bit, so the test is on block means: for each block and channel,
// z = (mean_test - mean_ref) / sqrt(var_test + var_ref), with the variances of the block means
// taken from the images' variance layers (pixels are independent estimates). Blocks come in
// several sizes (the smallest, doubled up to 64 pixels) on grids shifted by half a block, so a
// changed region of any size and position meets a block that fits it. The z threshold is set by
// a Bonferroni correction over every test, so the chance of any false failure over the whole
// image is `falsePositiveRate`.
#pragma once

#include "image/image_io.h"

#include <string>
#include <vector>

namespace pt {

struct CompareOptions {
    int blockSize = 8;    // smallest block side; larger scales double it up to maxBlockSize
    int maxBlockSize = 64;
    double falsePositiveRate = 1e-3;
    // Floor on the standard deviation of a block difference, as a fraction of the reference block
    // mean: absorbs float differences between CPUs and compilers in noise-free regions (a
    // directly seen light, the sky) without hiding a real change of a percent or more.
    double relativeFloor = 1e-3;
    size_t worstCount = 10;
    // Each pixel's sample count in each image, when known (empty if not; pixelSampleCounts). With
    // both, a test pixel's variance is taken as at least the reference pixel's scaled to the test
    // pixel's count: a low-sample variance estimate misses the rare, bright paths (caustics,
    // fireflies) exactly when the low-sample mean falls short of the reference, which would
    // otherwise make the test fail far more often than falsePositiveRate. Per pixel, because an
    // adaptive render's pixels hold from --min-spp to -spp samples: scaled by the fewest, every
    // pixel's variance was inflated to the fewest's, and a light 2 % brighter passed.
    std::vector<float> testCounts, referenceCounts;
};

struct BlockDifference {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // pixel rectangle [x0, x1) x [y0, y1)
    int channel = 0;                    // 0 R, 1 G, 2 B
    double test = 0, reference = 0;     // block means
    double z = 0;
};

struct CompareReport {
    std::string inputError;   // non-empty: the images cannot be compared (size, NaN, ...)
    bool statistical = false; // both images had variance layers
    bool pass = false;        // statistical: no test beyond the threshold; else relativeMse <= threshold
    double relativeMse = 0;   // mean of (t - r)^2 / (r^2 + 0.01), over pixels and channels
    double meanAbsError = 0;
    double zThreshold = 0;
    size_t tests = 0, failedTests = 0;
    int smallestBlock = 0;    // side of the smallest blocks: options.blockSize, or the image's longer side where that is less
    std::vector<BlockDifference> worst; // largest |z| first, overlapping blocks merged away
    // Per pixel: the largest |z| / zThreshold of any block covering it (1 = at the threshold).
    std::vector<float> heat;
};

// Finds the variance layer ("variance") of an image, or nullptr.
const ImageLayer* varianceLayer(const Image& image);

// Samples per pixel from pt's metadata (pt:spp: the fewest any pixel holds), or 0.
double samplesPerPixel(const Image& image);

// Each pixel's sample count: the image's `spp` layer (pt render and pt merge write one beside the
// variance layer wherever pixels hold different counts), else pt:spp for every pixel where the
// metadata says they hold the same (no pt:sppMax); empty where nothing says (another renderer's
// file). `error` is set, and the result empty, where the pixels differ and no layer says how, or
// the layer holds what cannot be a count.
std::vector<float> pixelSampleCounts(const Image& image, std::string& error);

// Without variance layers, `relativeMseThreshold` decides instead (not a statistical test).
CompareReport compareImages(const Image& test, const Image& reference, const CompareOptions& options = {},
                            double relativeMseThreshold = 1e-3);

// Two-sided z threshold for a false-positive rate alpha spread over `tests` tests (Bonferroni).
double bonferroniZ(double alpha, double tests);

// The heat map as an image: the reference, darkened and grey, with blocks near or beyond the
// threshold in red (at it) to yellow (twice it).
Image heatmapImage(const CompareReport& report, const Image& reference);

} // namespace pt
