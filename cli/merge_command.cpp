// pt merge: the parts of a split render (sample ranges, crops, interrupted renders) into the
// image one process would have rendered from the same samples.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/denoising.h"
#include "cli/stop_signals.h"
#include "io/output_file.h"
#include "image/image_io.h"
#include "render/film_image.h"
#include "render/film_part.h"
#include "render/render_job.h"

#include <tbb/info.h>

#include <algorithm>
#include <cstdio>
#include <optional>
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
  --aov LIST           extra EXR layers from the parts' sums: variance, albedo, normal, depth,
                       spp (each pixel's sample count)
                       (albedo, normal and depth need parts rendered with them) [none]
  --denoise            denoise the merged image with Intel Open Image Denoise, as pt render
                       --denoise does (the RGB denoised, the raw estimate as layer noisy);
                       the parts must hold first-hit sums: render them with --aov albedo,normal.
                       The only correct place to denoise a split render [off]
  -q, --quiet          print no warnings, only errors and the summary line
  -h, --help           show this help

exit status: 0 merged, 1 bad input (a missing, truncated or foreign file, parts of different
jobs, overlapping samples), 2 bad usage. On an error nothing is written and OUT is untouched.
)";

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
    bool denoise = false;
    bool quiet = false;
    OutputFile output;
    try {
        Args args(argc, argv, 1);
        std::string opt;
        while (args.next(opt, paths)) {
            if (opt == "h" || opt == "help") {
                std::fputs(kMergeUsage, stdout);
                return 0;
            } else if (opt == "o" || opt == "output") {
                outputPath = args.value(opt);
            } else if (opt == "aov") {
                aovs = parseAovList(args.value(opt));
            } else if (opt == "denoise") {
                denoise = true;
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
    if (quiet) {
        silenceLibraryOutput();
        err = errorStream(); // pt's own stderr, which -q leaves open for errors
    }
    // Reading and writing are quick to do again: a signal quits at once, and removes the
    // temporary output file if it is being written.
    installStopHandlers("pt merge: interrupted; nothing was written\n",
                        "pt merge: interrupted after the merged image was written whole\n");
    std::unique_ptr<Denoiser> denoiser;
    if (denoise) {
        int status = 0;
        denoiser = openDenoiser("pt merge", tbb::info::default_concurrency(), err, status);
        if (!denoiser) return status;
    }

    // One part at a time: read, checked against the first (the job) and against those before it
    // (no sample of a pixel twice), added to the merged film and let go, so that a merge holds one
    // part beside the image whatever their number. Nothing is written before all are in.
    struct Merged {
        std::string path;
        PartInfo info;
        bool layers;
    };
    std::vector<Merged> merged;
    Image job; // the first part's metadata
    std::optional<Film> film;
    double seconds = 0.0;
    bool adaptive = false; // a part rendered with --noise: its stopped pixels are counted
    size_t converged = 0;
    bool budgeted = false; // parts stopped by --noise or --time: pixels short of -spp are expected
    for (const std::string& path : paths) {
        Image image;
        Film part(0, 0);
        PartInfo in;
        if (std::string error = readPart(path, image, part, in); !error.empty()) {
            std::fprintf(err, "pt merge: error: %s\n", error.c_str());
            return 1;
        }
        std::string field, a, b;
        if (!merged.empty() && jobMismatch(job, image, field, a, b)) {
            std::fprintf(err, "pt merge: error: %s is a part of another job than %s: its %s is \"%s\", not \"%s\"\n",
                         path.c_str(), merged[0].path.c_str(), field.c_str(), b.c_str(), a.c_str());
            return 1;
        }
        for (const Merged& m : merged) {
            const PartInfo& o = m.info;
            bool pixels = o.x0 < in.x1 && in.x0 < o.x1 && o.y0 < in.y1 && in.y0 < o.y1;
            bool samples = o.first < in.last && in.first < o.last;
            if (pixels && samples) {
                std::fprintf(err, "pt merge: error: %s and %s both hold samples %u:%u of pixels [%d, %d) x [%d, %d); "
                                  "merging them would count those samples twice\n",
                             m.path.c_str(), path.c_str(), std::max(o.first, in.first), std::min(o.last, in.last),
                             std::max(o.x0, in.x0), std::min(o.x1, in.x1), std::max(o.y0, in.y0), std::min(o.y1, in.y1));
                return 1;
            }
        }
        if (merged.empty()) {
            job.metadata = image.metadata;
            film.emplace(in.fullWidth, in.fullHeight); // within the memory budget: partFromImage checked
            if (part.hasFirstHitLayers()) film->enableFirstHitLayers(); // used only if every part has them
        }
        for (int y = in.y0; y < in.y1; ++y)
            for (int x = in.x0; x < in.x1; ++x)
                film->addPixel(size_t(y) * size_t(in.fullWidth) + size_t(x), part,
                               size_t(y - in.y0) * size_t(image.width) + size_t(x - in.x0));
        seconds += in.seconds;
        if (part.hasConvergence()) adaptive = true, converged += part.convergedCount();
        budgeted |= !attributeText(image, "pt:noise").empty() || !attributeText(image, "pt:time").empty();
        merged.push_back({path, in, part.hasFirstHitLayers()});
    }
    const int width = merged[0].info.fullWidth, height = merged[0].info.fullHeight;
    const uint32_t spp = merged[0].info.spp;
    bool layers = std::all_of(merged.begin(), merged.end(), [](const Merged& m) { return m.layers; });
    if ((aovs.firstHit() || denoise) && !layers) {
        for (const Merged& m : merged)
            if (!m.layers)
                std::fprintf(err, "pt merge: error: %s has no first-hit sums; %s need every part rendered with --aov "
                                  "albedo,normal (or any of albedo, normal, depth)\n",
                             m.path.c_str(), denoise ? "--denoise (its albedo and normal guides)" : "--aov albedo, normal and depth");
        return 1;
    }

    // Gaps: pixels short of the job's samples, and which sample ranges no part covers.
    const Film::SampleCounts counts = film->sampleCounts();
    size_t empty = 0, short_ = 0;
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        uint32_t n = film->count(i);
        empty += n == 0;
        short_ += n < spp;
    }
    if (short_ > 0 && !quiet && budgeted && empty > 0)
        std::fprintf(err, "pt merge: warning: %zu pixels hold no sample at all (no part covers them): they are black\n", empty);
    if (short_ > 0 && !quiet && !budgeted) {
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        for (const Merged& m : merged)
            if (m.info.x0 == 0 && m.info.y0 == 0 && m.info.x1 == width && m.info.y1 == height)
                ranges.emplace_back(m.info.first, m.info.last);
        std::string missing = missingRanges(ranges, spp);
        std::fprintf(err, "pt merge: warning: %zu of %d pixels hold fewer than the job's %u samples (the fewest %u)%s%s\n",
                     short_, width * height, spp, counts.fewest,
                     missing.empty() ? "" : "; no whole-image part holds samples ", missing.c_str());
        if (empty > 0)
            std::fprintf(err, "pt merge: warning: %zu pixels hold no sample at all (no part covers them): they are black\n", empty);
    }

    size_t overflowed;
    Image image = filmImage(*film, aovs, merged[0].info.exposure, overflowed);
    if (overflowed > 0 && !quiet)
        std::fprintf(err, "pt merge: warning: %zu values of the image and its layers pass float's range (at pt:exposure %g) "
                          "and are written as the largest float\n", overflowed, merged[0].info.exposure);
    for (const ImageAttribute& a : job.metadata) {
        if (a.name.rfind("pt:", 0) != 0 && a.name != "Software") continue; // OpenEXR's own header fields stay its own
        static const char* const kPartOnly[] = {"pt:part", "pt:samplesFirst", "pt:samplesLast", "pt:spp", "pt:renderSeconds",
                                               "pt:threads", "pt:threadsRequested", "pt:interrupted",
                                               "pt:decidedAt", "pt:sppMax", "pt:sppMean", "pt:converged", "pt:outOfTime"};
        if (std::find_if(std::begin(kPartOnly), std::end(kPartOnly), [&](const char* n) { return a.name == n; }) ==
            std::end(kPartOnly))
            image.metadata.push_back(a);
    }
    // As pt render writes them: the fewest as pt:spp, and where pixels differ the most and the mean.
    image.metadata.push_back(ImageAttribute::integerValue("pt:spp", counts.fewest));
    if (counts.most != counts.fewest) {
        image.metadata.push_back(ImageAttribute::integerValue("pt:sppMax", counts.most));
        image.metadata.push_back(ImageAttribute::floatValue("pt:sppMean", counts.mean));
    }
    if (adaptive) image.metadata.push_back(ImageAttribute::integerValue("pt:converged", (long long)converged));
    image.metadata.push_back(ImageAttribute::integerValue("pt:mergedParts", (long long)merged.size()));
    image.metadata.push_back(ImageAttribute::floatValue("pt:renderSeconds", seconds));
    DenoiseReport denoised;
    if (denoiser) {
        std::string error = denoiseImage(*denoiser, image, film->albedo(), film->normal(), DenoiseOptions{}, denoised);
        if (!error.empty()) {
            std::fprintf(err, "pt merge: error: %s; nothing was written\n", error.c_str());
            return 1;
        }
    }
    if (std::string error = output.open(outputPath); !error.empty()) {
        std::fprintf(err, "pt merge: %s\n", error.c_str());
        return 2;
    }
    if (std::string error = writeImage(output, image); !error.empty()) {
        std::fprintf(err, "pt merge: error: %s\n", error.c_str());
        return 1;
    }
    char sppText[160];
    if (counts.most == counts.fewest) std::snprintf(sppText, sizeof sppText, "%u of %u spp in every pixel", counts.fewest, spp);
    else std::snprintf(sppText, sizeof sppText, "%u to %u of %u spp (mean %.1f)", counts.fewest, counts.most, spp, counts.mean);
    std::string convergedText =
        adaptive ? ", " + std::to_string(converged) + " of " + std::to_string(size_t(width) * height) + " pixels converged" : "";
    char denoiseText[160] = "";
    if (denoiser) std::snprintf(denoiseText, sizeof denoiseText, ", denoised in %.3f s (OIDN %s)", denoised.seconds, denoiser->version().c_str());
    std::printf("pt merge: %zu parts, %dx%d, %s%s, %.3f s of rendering%s -> %s\n", merged.size(), width, height, sppText,
                convergedText.c_str(), seconds, denoiseText, outputPath.c_str());
    return 0;
}

} // namespace pt::cli
