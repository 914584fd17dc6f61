// pt denoise: an existing pt render (an .exr with its albedo and normal layers) denoised.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/denoising.h"
#include "cli/stop_signals.h"
#include "io/output_file.h"
#include "render/render_job.h"

#include <tbb/info.h>

#include <algorithm>
#include <cstdio>

namespace pt::cli {
namespace {

const char* kDenoiseUsage = R"(usage: pt denoise IN.exr -o OUT [options]

Denoises a pt render with Intel Open Image Denoise (the RT filter on the CPU), guided by the
render's albedo and normal layers (pt render --aov albedo,normal), which are denoised first. OUT
(.exr) holds the denoised RGB, the raw estimate as layer noisy (noisy.R, noisy.G, noisy.B), IN's
other channels (A and the like among them, as they were) and metadata, and pt:denoiser; a .png
holds the denoised picture alone. IN must have R, G and B channels: a file without them (its
picture in a layer, or grey) is refused, naming what it has. An IN that is
already denoised is denoised again from its raw estimate. A part of a split render holds sums,
not an image: pt merge --denoise it.

options (default in brackets):
  -o, --output PATH    the denoised image, .exr or .png [denoised.exr]
  --quality Q          the filter's mode: high, balanced (lower precision where the CPU has
                       AVX-512 BF16) or fast (a smaller network for the image) [high]
  --prefilter on|off   denoise the albedo and normal first, then trust them; off gives the
                       filter the features as rendered (faster, a little noisier) [on]
  --threads N          threads for the filter; 0 uses every hardware thread [0]
  -q, --quiet          print only errors and the summary line
  -h, --help           show this help

Needs Intel Open Image Denoise 2.x: tools/install-oidn installs 2.5.1 where pt finds it;
PT_OIDN_LIBRARY=/path/to/libOpenImageDenoise.so.2 names another.

exit status: 0 denoised, 1 bad input (unreadable, no R, G, B picture, no albedo or normal layer,
a part, an error inside the filter, a library that is not OIDN 2.x or is damaged), 2 bad usage
(the library is not installed).
)";

// Layer `name`'s channels `channels`, picked by name (in any order, beside any others the layer
// has) and interleaved; empty where the layer or one of them is missing.
std::vector<float> featureChannels(const Image& image, const std::string& name, const std::vector<std::string>& channels) {
    auto layer = std::find_if(image.layers.begin(), image.layers.end(), [&](const ImageLayer& l) { return l.name == name; });
    if (layer == image.layers.end()) return {};
    std::vector<size_t> index;
    for (const std::string& c : channels) {
        auto it = std::find(layer->channels.begin(), layer->channels.end(), c);
        if (it == layer->channels.end()) return {};
        index.push_back(size_t(it - layer->channels.begin()));
    }
    const size_t stride = layer->channels.size(), n = size_t(image.width) * size_t(image.height);
    std::vector<float> out(n * channels.size());
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < index.size(); ++c) out[i * index.size() + c] = layer->pixels[i * stride + index[c]];
    return out;
}

} // namespace

int denoiseCommand(int argc, char** argv) {
    FILE* err = errorStream();
    std::string input, outputPath = "denoised.exr";
    DenoiseOptions options;
    int threads = 0;
    bool quiet = false;
    try {
        Args args(argc, argv, 1);
        std::vector<std::string> positional;
        std::string opt;
        while (args.next(opt, positional)) {
            if (opt == "h" || opt == "help") {
                std::fputs(kDenoiseUsage, stdout);
                return 0;
            } else if (opt == "o" || opt == "output") {
                outputPath = args.value(opt);
            } else if (opt == "quality") {
                options.quality = parseQuality(args.spelled(opt), args.value(opt));
            } else if (opt == "prefilter") {
                std::string v = args.value(opt);
                if (v != "on" && v != "off") throw UsageError("option " + args.spelled(opt) + ": expected on or off, got \"" + v + "\"");
                options.prefilter = v == "on";
            } else if (opt == "threads") {
                threads = int(args.integer(opt, 0, 4096));
            } else if (opt == "q" || opt == "quiet") {
                quiet = true;
            } else {
                throw UsageError("unknown option \"" + args.spelled(opt) + "\" (pt denoise --help lists the options)");
            }
        }
        if (positional.size() != 1)
            throw UsageError(positional.empty() ? "expected the IN.exr to denoise"
                                                : "unexpected argument \"" + positional[1] + "\"; expected one IN.exr");
        input = positional[0];
        std::string problem = checkOutputPath(outputPath);
        if (problem.empty()) problem = outputIsInput({outputPath}, {input});
        if (!problem.empty()) throw UsageError(problem);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt denoise: %s\n", e.what());
        return 2;
    }
    if (quiet) {
        silenceLibraryOutput();
        err = errorStream();
    }
    installStopHandlers("pt denoise: interrupted; nothing was written\n",
                        "pt denoise: interrupted after the denoised image was written whole\n");
    const int hardware = tbb::info::default_concurrency();
    threads = threads > 0 ? std::min(threads, hardware) : hardware;
    int status = 0;
    std::unique_ptr<Denoiser> denoiser = openDenoiser("pt denoise", threads, err, status);
    if (!denoiser) return status;

    Image image;
    std::string error = readImage(input, image);
    if (error.empty() && image.parts > 1)
        error = input + " has " + std::to_string(image.parts) + " parts; pt denoise reads single-part images such as pt render writes";
    if (error.empty() && !attributeText(image, "pt:part").empty())
        error = input + " is a part of a split render (per-pixel sums, not an image): merge the parts with "
                        "pt merge --denoise";
    if (error.empty() && image.beauty != Image::Beauty::Rgb)
        error = input + " has " +
                (image.beauty == Image::Beauty::Grey ? std::string("a grey picture (Y) and no R, G, B channels")
                                                     : missingRgb(image)) +
                "; pt denoise denoises the R, G, B picture of a pt render, guided by its albedo and normal layers";
    bool again = false;
    if (error.empty()) {
        std::string why;
        again = restoreRawEstimate(image, why);
        if (!why.empty()) error = input + ": " + why;
    }
    std::vector<float> albedo, normal;
    if (error.empty()) {
        albedo = featureChannels(image, "albedo", {"R", "G", "B"});
        normal = featureChannels(image, "normal", {"X", "Y", "Z"});
        if (albedo.empty() || normal.empty())
            error = input + " has no " + (!albedo.empty() ? "normal layer (normal.X, normal.Y, normal.Z)" : "albedo layer (albedo.R, albedo.G, albedo.B)") +
                    ", which guides the denoiser: render it with --aov albedo,normal (or with --denoise)";
    }
    if (!error.empty()) {
        std::fprintf(err, "pt denoise: error: %s\n", error.c_str());
        return 1;
    }
    if (again && !quiet) std::fprintf(err, "pt denoise: %s was denoised already: denoising its raw estimate (layer noisy)\n", input.c_str());
    OutputFile output;
    if (std::string problem = output.open(outputPath); !problem.empty()) {
        std::fprintf(err, "pt denoise: %s\n", problem.c_str());
        return 2;
    }
    DenoiseReport report;
    if (std::string e = denoiseImage(*denoiser, image, std::move(albedo), std::move(normal), options, report); !e.empty()) {
        std::fprintf(err, "pt denoise: error: %s\n", e.c_str());
        return 1;
    }
    if (report.replaced > 0 && !quiet)
        std::fprintf(err, "pt denoise: warning: %zu values of %s were NaN, infinite or negative and were given 0 before filtering\n",
                     report.replaced, input.c_str());
    if (std::string e = writeImage(output, image); !e.empty()) {
        std::fprintf(err, "pt denoise: error: %s\n", e.c_str());
        return 1;
    }
    std::printf("pt denoise: %dx%d, %s, %.3f s, %d threads -> %s\n", image.width, image.height, report.description.c_str(),
                report.seconds, threads, outputPath.c_str());
    return 0;
}

} // namespace pt::cli
