// pt diff: is a render statistically the same image as a reference?
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/denoising.h"
#include "io/output_file.h"
#include "image/compare.h"
#include "image/flip.h"
#include "image/image_io.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pt::cli {
namespace {

const char* kDiffUsage = R"(usage: pt diff TEST.exr REFERENCE.exr [options]

Compares two renders of the same scene. With variance layers in both (pt render --aov variance),
block means at several scales are compared by a z-test whose threshold holds the chance of any
false failure over the whole image at --alpha: identical physics with different noise passes, a
change of a few percent in a region fails. Each pixel is weighed by its own sample count: the spp
layer of an adaptive or --time render (pt render writes it beside the variance layer wherever
counts differ), else pt:spp. Without variance layers, the relative MSE is compared
with --threshold instead (not a statistical test; a warning says so).

options (default in brackets):
  --alpha A            false-failure rate for the whole image [0.001]
  --block N            smallest block side in pixels; larger blocks double up to 64 [8]; an image
                       smaller than N is tested with blocks as large as its longer side
  --threshold T        without variance layers: fail when the relative MSE exceeds T [0.001]
  --heatmap OUT.png    write where the images differ (red at the threshold, yellow at twice it)
  --json OUT.json      write the report as JSON
  --ppd P              pixels per degree of visual angle for FLIP [67, a 4K 0.7 m monitor at 0.7 m]
  -q, --quiet          print only the verdict line
  -h, --help           show this help

Also reported, not part of the verdict: HDR-FLIP (Andersson et al. 2021), the mean perceptual
difference in [0, 1] of the test against the reference at --ppd, which says how visible a
difference is (noise included), where the z-test says whether it is more than noise.

The heat map and the JSON are written whole or not at all, and never over TEST or REFERENCE.

exit status: 0 the images agree, 1 they differ, 2 bad input (a missing or unreadable file, not a
regular file, a multipart EXR, no R, G, B (or grey Y) picture, sizes or channel lists that differ (the spp layer aside), NaN or Inf
in an image, which is reported with its pixel, a pixel of one sample, whose variance is unknown,
an image whose pixels hold different counts without an spp layer), bad usage, or a report that
could not be written

A denoised image (pt render --denoise, pt denoise) is compared by its raw estimate, the noisy
layer kept beside it: denoised pixels share their neighbours' samples, which no per-pixel test
can judge. A note says so.
)";

const char* channelName(int c) { return c == 0 ? "R" : c == 1 ? "G" : "B"; }

std::string jsonReport(const CompareReport& r, const FlipResult& flip, const std::string& test, const std::string& ref) {
    auto esc = [](const std::string& s) {
        std::string o;
        for (char c : s) {
            if (c == '"' || c == '\\') o += '\\';
            o += c;
        }
        return o;
    };
    std::ostringstream j;
    j << "{\n  \"test\": \"" << esc(test) << "\",\n  \"reference\": \"" << esc(ref) << "\",\n"
      << "  \"pass\": " << (r.pass ? "true" : "false") << ",\n  \"statistical\": " << (r.statistical ? "true" : "false")
      << ",\n  \"relative_mse\": " << r.relativeMse << ",\n  \"mean_abs_error\": " << r.meanAbsError
      << ",\n  \"z_threshold\": " << r.zThreshold << ",\n  \"tests\": " << r.tests
      << ",\n  \"failed_tests\": " << r.failedTests << ",\n  \"flip_mean\": " << flip.mean
      << ",\n  \"flip_exposures\": [" << flip.startExposure << ", " << flip.stopExposure << ", " << flip.exposures
      << "],\n  \"worst\": [";
    for (size_t i = 0; i < r.worst.size(); ++i) {
        const BlockDifference& d = r.worst[i];
        j << (i ? ",\n" : "\n") << "    {\"x0\": " << d.x0 << ", \"y0\": " << d.y0 << ", \"x1\": " << d.x1
          << ", \"y1\": " << d.y1 << ", \"channel\": \"" << channelName(d.channel) << "\", \"test\": " << d.test
          << ", \"reference\": " << d.reference << ", \"z\": " << d.z << "}";
    }
    j << (r.worst.empty() ? "]\n}\n" : "\n  ]\n}\n");
    return j.str();
}

} // namespace

int diffCommand(int argc, char** argv) {
    std::vector<std::string> files;
    CompareOptions options;
    double threshold = 1e-3;
    std::string heatmap, json;
    float ppd = kFlipDefaultPpd;
    bool quiet = false;
    FILE* err = errorStream();
    OutputFile heatmapFile, jsonFile;
    try {
        Args args(argc, argv, 1);
        std::string opt;
        while (args.next(opt, files)) {
            if (opt == "h" || opt == "help") {
                std::fputs(kDiffUsage, stdout);
                return 0;
            } else if (opt == "alpha") {
                options.falsePositiveRate = args.number(opt, 1e-12, 0.5);
            } else if (opt == "block") {
                options.blockSize = int(args.integer(opt, 1, 4096));
                options.maxBlockSize = std::max(options.maxBlockSize, options.blockSize);
            } else if (opt == "threshold") {
                threshold = args.number(opt, 0.0, 1e30);
            } else if (opt == "heatmap") {
                heatmap = args.value(opt);
            } else if (opt == "json") {
                json = args.value(opt);
            } else if (opt == "ppd") {
                ppd = float(args.number(opt, 1.0, 1000.0));
            } else if (opt == "q" || opt == "quiet") {
                quiet = true;
                silenceLibraryOutput();
                err = errorStream();
            } else {
                throw UsageError("unknown option \"" + args.spelled(opt) + "\" (pt diff --help lists the options)");
            }
        }
        if (files.size() != 2) throw UsageError("expected TEST and REFERENCE images, got " + std::to_string(files.size()));
        if (!heatmap.empty() && formatFromPath(heatmap) != ImageFormat::Png) throw UsageError("--heatmap: expected a .png path");
        std::vector<std::string> outputs;
        for (const std::string& out : {heatmap, json})
            if (!out.empty()) outputs.push_back(out);
        if (std::string problem = outputIsInput(outputs, files); !problem.empty()) throw UsageError(problem);
        // Created before any work, so that a folder that refuses them fails now.
        for (auto [path, file] : {std::pair{&heatmap, &heatmapFile}, std::pair{&json, &jsonFile}}) {
            if (path->empty()) continue;
            std::string problem = file->open(*path);
            if (!problem.empty()) throw UsageError(problem);
        }
    } catch (const UsageError& e) {
        std::fprintf(err, "pt diff: %s\n", e.what());
        return 2;
    }

    Image test, reference;
    for (auto [path, image] : {std::pair{&files[0], &test}, std::pair{&files[1], &reference}}) {
        std::string error = readImage(*path, *image);
        if (error.empty() && image->beauty == Image::Beauty::Missing)
            error = "\"" + *path + "\" has " + missingRgb(*image) + "; pt diff compares the R, G, B (or grey Y) pictures of two images";
        if (error.empty() && image->parts > 1)
            error = "\"" + *path + "\" has " + std::to_string(image->parts) +
                    " parts; pt diff compares single-part images such as pt render writes";
        // A denoised image is no estimate a statistical test can judge (its pixels share their
        // neighbours' samples): its raw estimate, kept beside it, is compared instead.
        std::string why;
        if (error.empty() && restoreRawEstimate(*image, why)) {
            if (!why.empty()) error = *path + ": " + why;
            else if (!quiet)
                std::fprintf(err, "pt diff: note: %s is denoised; comparing its raw estimate (layer noisy), not the "
                                  "denoised picture\n", path->c_str());
        }
        if (!error.empty()) {
            std::fprintf(err, "pt diff: %s\n", error.c_str());
            return 2;
        }
    }
    bool sameSize = test.width == reference.width && test.height == reference.height; // else compareImages says so
    // The spp layer is no picture but each pixel's count, which weighs it: one image may have it
    // (an adaptive render) and the other not (a uniform one, whose count is pt:spp).
    auto compared = [](const Image& image) {
        std::vector<std::string> names;
        for (const std::string& c : image.channelNames)
            if (c != "spp.Z") names.push_back(c);
        return names;
    };
    if (sameSize && compared(test) != compared(reference)) {
        auto list = [](const std::vector<std::string>& names) {
            std::string s;
            for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
            return s;
        };
        std::fprintf(err, "pt diff: %s and %s have different channels (%s against %s); render both with the same --aov\n",
                     files[0].c_str(), files[1].c_str(), list(compared(test)).c_str(),
                     list(compared(reference)).c_str());
        return 2;
    }
    // Each pixel's count weighs its variance (statistical comparisons only).
    if (varianceLayer(test) && varianceLayer(reference)) {
        std::string testError, referenceError;
        options.testCounts = pixelSampleCounts(test, testError);
        options.referenceCounts = pixelSampleCounts(reference, referenceError);
        for (auto [path, error] : {std::pair{&files[0], &testError}, std::pair{&files[1], &referenceError}})
            if (!error->empty()) {
                std::fprintf(err, "pt diff: %s: %s\n", path->c_str(), error->c_str());
                return 2;
            }
    }
    CompareReport r = compareImages(test, reference, options, threshold);
    if (!r.inputError.empty()) {
        std::fprintf(err, "pt diff: %s vs %s: %s\n", files[0].c_str(), files[1].c_str(), r.inputError.c_str());
        return 2;
    }

    // FLIP is only reported, never part of the verdict: skip it when nothing would show it.
    FlipResult flip;
    if (!quiet || !json.empty()) flip = hdrFlip(test.rgb, reference.rgb, test.width, test.height, ppd);
    if (!quiet) {
        std::printf("pt diff: %s vs %s (%dx%d)\n", files[0].c_str(), files[1].c_str(), test.width, test.height);
        if (r.statistical && r.smallestBlock < options.blockSize)
            std::printf("  note: the image is smaller than --block %d: its smallest blocks are %d pixels a side%s\n",
                        options.blockSize, r.smallestBlock, r.smallestBlock == std::max(test.width, test.height) ? " (the whole image)" : "");
        if (r.statistical) {
            std::printf("  %zu of %zu block tests beyond |z| > %.2f (false-failure rate %g for the image)\n",
                        r.failedTests, r.tests, r.zThreshold, options.falsePositiveRate);
        } else {
            std::printf("  warning: no variance layers (render with --aov variance); comparing relative MSE with "
                        "--threshold %g instead of a statistical test\n", threshold);
        }
        std::printf("  relative MSE %.3g, mean absolute error %.3g, HDR-FLIP %.4f (%.3g ppd, %d exposures from %+.2f to %+.2f)\n",
                    r.relativeMse, r.meanAbsError, flip.mean, ppd, flip.exposures, flip.startExposure, flip.stopExposure);
        if (r.statistical && !r.worst.empty()) {
            std::printf("  largest differences:\n");
            for (const BlockDifference& d : r.worst) {
                double rel = d.reference != 0 ? 100.0 * (d.test - d.reference) / std::abs(d.reference) : 0.0;
                std::printf("    pixels [%d,%d) x [%d,%d) %s: test %.5g, reference %.5g (%+.2f%%), z %+.2f\n", d.x0, d.x1,
                            d.y0, d.y1, channelName(d.channel), d.test, d.reference, rel, d.z);
            }
        }
    }
    std::printf("pt diff: %s\n", r.pass ? "the images agree" : "the images DIFFER");

    int status = r.pass ? 0 : 1;
    if (heatmapFile.isOpen()) {
        if (std::string error = writeImage(heatmapFile, heatmapImage(r, reference)); !error.empty()) {
            std::fprintf(err, "pt diff: --heatmap: %s\n", error.c_str());
            status = 2;
        }
    }
    if (jsonFile.isOpen()) {
        std::string text = jsonReport(r, flip, files[0], files[1]);
        std::string error = jsonFile.commit(text.data(), text.size());
        if (!error.empty()) {
            std::fprintf(err, "pt diff: --json: %s\n", error.c_str());
            status = 2;
        }
    }
    return status;
}

} // namespace pt::cli
