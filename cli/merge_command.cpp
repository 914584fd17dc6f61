// pt merge: the parts of a split render (sample ranges, crops, interrupted renders) into the
// image one process would have rendered from the same samples.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "io/output_file.h"
#include "image/image_io.h"
#include "render/film_image.h"
#include "render/render_job.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pt::cli {
namespace {

const char* kMergeUsage = R"(usage: pt merge PART.exr... -o OUT [options]

Merges the parts of one render job: outputs of pt render with --samples A:B (sample ranges),
--crop X0,Y0,X1,Y1 (windows of the image) or both, and the .partial.exr of interrupted .exr
renders. Each part holds, per pixel, its sample count and exact sums; the merge adds them, so
the image equals the one a single process renders from the same samples (to float rounding).

The parts must be of one job: the same scene content, camera, resolution, -spp, seed and every
option that changes a sample; the first field that differs is named. Two parts that hold the same
samples of a pixel are refused; pixels that miss samples (a range nobody rendered, a task that
was stopped) are reported, and the image holds what there is.

options (default in brackets):
  -o, --output PATH    the merged image, .exr or .png [merged.exr]
  --aov LIST           extra EXR layers from the parts' sums: variance, albedo, normal, depth
                       (albedo, normal and depth need parts rendered with them) [none]
  -q, --quiet          print no warnings, only errors and the summary line
  -h, --help           show this help

exit status: 0 merged, 1 bad input (a missing, truncated or foreign file, parts of different
jobs, overlapping samples), 2 bad usage. On an error nothing is written and OUT is untouched.
)";

struct Part {
    std::string path;
    Image image;
    Film film{0, 0};
    uint32_t first = 0, last = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Runs of indices [a, b) of [0, n) that `covered` leaves out, as "a:b, c:d".
std::string missingRanges(std::vector<std::pair<uint32_t, uint32_t>> covered, uint32_t n) {
    std::sort(covered.begin(), covered.end());
    std::ostringstream out;
    uint32_t at = 0;
    auto gap = [&](uint32_t a, uint32_t b) {
        if (out.tellp() > 0) out << ", ";
        out << a << ":" << b;
    };
    for (auto [a, b] : covered) {
        if (a > at) gap(at, a);
        at = std::max(at, b);
    }
    if (at < n) gap(at, n);
    return out.str();
}

} // namespace

int mergeCommand(int argc, char** argv) {
    FILE* err = errorStream();
    std::vector<std::string> paths;
    std::string outputPath = "merged.exr";
    AovSelection aovs;
    bool quiet = false;
    OutputFile output;
    try {
        Args args(argc, argv, 1);
        while (!args.done()) {
            std::string opt;
            if (!args.nextOption(opt)) {
                paths.push_back(args.positional());
                continue;
            }
            if (opt == "h" || opt == "help") {
                std::fputs(kMergeUsage, stdout);
                return 0;
            } else if (opt == "o" || opt == "output") {
                outputPath = args.value(opt);
            } else if (opt == "aov") {
                aovs = parseAovList(args.value(opt));
            } else if (opt == "q" || opt == "quiet") {
                quiet = true;
            } else {
                throw UsageError("unknown option \"" + args.spelled(opt) + "\" (pt merge --help lists the options)");
            }
        }
        if (paths.empty()) throw UsageError("expected one or more PART.exr files");
        bool anyAov = aovs.any();
        if (anyAov && formatFromPath(outputPath) != ImageFormat::Exr)
            throw UsageError("--aov needs an .exr output; \"" + outputPath + "\" cannot hold extra layers");
        std::string problem = checkOutputPath(outputPath);
        if (problem.empty()) problem = outputIsInput({outputPath}, paths);
        if (!problem.empty()) throw UsageError(problem);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt merge: %s\n", e.what());
        return 2;
    }
    if (quiet) silenceLibraryOutput();

    // Every part read and checked before anything is written.
    std::vector<Part> parts(paths.size());
    for (size_t i = 0; i < paths.size(); ++i) {
        Part& p = parts[i];
        p.path = paths[i];
        if (std::string error = readPart(p.path, p.image, p.film); !error.empty()) {
            std::fprintf(err, "pt merge: error: %s\n", error.c_str());
            return 1;
        }
        std::string field, a, b;
        if (i > 0 && jobMismatch(parts[0].image, p.image, field, a, b)) {
            std::fprintf(err, "pt merge: error: %s is a part of another job than %s: its %s is \"%s\", not \"%s\"\n",
                         p.path.c_str(), parts[0].path.c_str(), field.c_str(), b.c_str(), a.c_str());
            return 1;
        }
        p.first = uint32_t(std::stoul("0" + attributeText(p.image, "pt:samplesFirst")));
        p.last = uint32_t(std::stoul("0" + attributeText(p.image, "pt:samplesLast")));
        bool windowed = p.image.fullWidth > 0;
        p.x0 = windowed ? p.image.x : 0, p.y0 = windowed ? p.image.y : 0;
        p.x1 = p.x0 + p.image.width, p.y1 = p.y0 + p.image.height;
    }
    const int width = std::stoi("0" + attributeText(parts[0].image, "pt:fullWidth"));
    const int height = std::stoi("0" + attributeText(parts[0].image, "pt:fullHeight"));
    const uint32_t spp = uint32_t(std::stoul("0" + attributeText(parts[0].image, "pt:sppRequested")));
    bool layers = true;
    for (const Part& p : parts) {
        if (p.x0 < 0 || p.y0 < 0 || p.x1 > width || p.y1 > height || p.last <= p.first || p.last > spp) {
            std::fprintf(err, "pt merge: error: %s: its window or sample range does not fit its job (%dx%d, %u spp)\n",
                         p.path.c_str(), width, height, spp);
            return 1;
        }
        layers &= p.film.hasFirstHitLayers();
    }
    if (aovs.firstHit() && !layers) {
        for (const Part& p : parts)
            if (!p.film.hasFirstHitLayers())
                std::fprintf(err, "pt merge: error: %s has no first-hit sums; --aov albedo, normal and depth need every part "
                                  "rendered with one of them\n", p.path.c_str());
        return 1;
    }
    // No two parts may hold the same samples of a pixel.
    for (size_t i = 0; i < parts.size(); ++i)
        for (size_t j = i + 1; j < parts.size(); ++j) {
            const Part &a = parts[i], &b = parts[j];
            bool pixels = a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
            bool samples = a.first < b.last && b.first < a.last;
            if (pixels && samples) {
                std::fprintf(err, "pt merge: error: %s and %s both hold samples %u:%u of pixels [%d, %d) x [%d, %d); "
                                  "merging them would count those samples twice\n",
                             a.path.c_str(), b.path.c_str(), std::max(a.first, b.first), std::min(a.last, b.last),
                             std::max(a.x0, b.x0), std::min(a.x1, b.x1), std::max(a.y0, b.y0), std::min(a.y1, b.y1));
                return 1;
            }
        }

    Film film(width, height);
    if (layers) film.enableFirstHitLayers();
    double seconds = 0.0;
    for (const Part& p : parts) {
        for (int y = p.y0; y < p.y1; ++y)
            for (int x = p.x0; x < p.x1; ++x)
                film.addPixel(size_t(y) * width + x, p.film, size_t(y - p.y0) * p.image.width + (x - p.x0));
        seconds += std::atof(attributeText(p.image, "pt:renderSeconds").c_str());
    }

    // Gaps: pixels short of the job's samples, and which sample ranges no part covers.
    size_t empty = 0, short_ = 0;
    uint32_t fewest = spp;
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        uint32_t n = film.count(i);
        empty += n == 0;
        short_ += n < spp;
        fewest = std::min(fewest, n);
    }
    if (short_ > 0 && !quiet) {
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        for (const Part& p : parts)
            if (p.x0 == 0 && p.y0 == 0 && p.x1 == width && p.y1 == height) ranges.emplace_back(p.first, p.last);
        std::string missing = missingRanges(ranges, spp);
        std::fprintf(err, "pt merge: warning: %zu of %d pixels hold fewer than the job's %u samples (the fewest %u)%s%s\n",
                     short_, width * height, spp, fewest,
                     missing.empty() ? "" : "; no whole-image part holds samples ", missing.c_str());
        if (empty > 0)
            std::fprintf(err, "pt merge: warning: %zu pixels hold no sample at all (no part covers them): they are black\n", empty);
    }

    size_t overflowed;
    Image image = filmImage(film, aovs, std::atof(attributeText(parts[0].image, "pt:exposure").c_str()), overflowed);
    for (const ImageAttribute& a : parts[0].image.metadata) {
        if (a.name.rfind("pt:", 0) != 0 && a.name != "Software") continue; // OpenEXR's own header fields stay its own
        static const char* const kPartOnly[] = {"pt:part", "pt:samplesFirst", "pt:samplesLast", "pt:spp", "pt:renderSeconds",
                                               "pt:threads", "pt:threadsRequested", "pt:interrupted"};
        if (std::find_if(std::begin(kPartOnly), std::end(kPartOnly), [&](const char* n) { return a.name == n; }) ==
            std::end(kPartOnly))
            image.metadata.push_back(a);
    }
    image.metadata.push_back(ImageAttribute::integerValue("pt:spp", fewest));
    image.metadata.push_back(ImageAttribute::integerValue("pt:mergedParts", (long long)parts.size()));
    image.metadata.push_back(ImageAttribute::floatValue("pt:renderSeconds", seconds));
    if (std::string error = output.open(outputPath); !error.empty()) {
        std::fprintf(err, "pt merge: %s\n", error.c_str());
        return 2;
    }
    if (std::string error = writeImage(output, image); !error.empty()) {
        std::fprintf(err, "pt merge: error: %s\n", error.c_str());
        return 1;
    }
    std::printf("pt merge: %zu parts, %dx%d, %u of %u spp in every pixel, %.3f s of rendering -> %s\n", parts.size(), width,
                height, fewest, spp, seconds, outputPath.c_str());
    return 0;
}

} // namespace pt::cli
