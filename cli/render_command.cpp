// pt render: load a scene, trace it, write the image.
#include "accel/accel.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

#include <tbb/task_arena.h>
#include <csignal>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <thread>

namespace pt::cli {
namespace {

const char* kRenderUsage = R"(usage: pt render SCENE [options]

Renders SCENE (Wavefront .obj with the lab's extended .mtl) and writes one image.

options (default in brackets):
  -o, --output PATH      output image [out.exr]; the extension picks the format:
                           .exr  linear float RGB, metadata, and any --aov layers
                           .png  sRGB-encoded 8-bit RGB
  -spp, --spp N          samples per pixel [16]
  --res WxH              image size in pixels [512x512]
  --camera NAME|INDEX    camera by name, or by 0-based index in file order [0]
  --threads N            worker threads; 0 uses every hardware thread [0]
  --seed S               random seed; the image depends only on it, never on --threads [0]
  --max-depth D          most scattering events on a path: 0 shows only emitters seen
                         directly, 1 gives direct lighting [16]
  --light-sampling M     direct light by mis (light and BSDF sampling, weighted),
                         nee (light sampling only) or bsdf (BSDF sampling only) [mis]
  --hemisphere M         Lambert sampling, cosine or uniform (a diagnostic) [cosine]
  --sampler S            sample values: sobol (Owen-scrambled Sobol points) or random
                         (independent) [sobol]
  --aov LIST             extra EXR layers, comma-separated [none]:
                           variance  variance of each pixel's mean (variance.R/G/B; pt diff uses it)
                           albedo    first-hit reflectance, all lobes (albedo.R/G/B)
                           normal    first-hit shading normal facing the camera (normal.X/Y/Z)
                           depth     distance to the first hit, +inf where none (depth.Z)
  --clamp X              scale down any sample whose largest channel exceeds X: fewer
                         fireflies, but biased (light is lost); 0 is off [0]
  -q, --quiet            print neither warnings nor progress, only the summary line
  -h, --help             show this help

Progress goes to stderr when it is a terminal; one summary line always ends the render.
Ctrl-C (SIGINT) or SIGTERM stops the render within a moment: the samples finished so far go to
OUT with ".partial" before the extension (out.partial.exr), and OUT itself is left untouched.
A second signal quits at once.
exit status: 0 success, 1 bad input (scene, texture, failed write), 2 bad usage,
             130 or 143 interrupted by SIGINT or SIGTERM
)";

struct RenderArgs {
    std::string scene;
    std::string output = "out.exr";
    long long spp = 16;
    int width = 512, height = 512;
    std::string camera = "0";
    int threads = 0;
    RenderSettings settings;
    bool aovVariance = false;
    bool aovAlbedo = false, aovNormal = false, aovDepth = false;
    bool quiet = false;
};

void parseResolution(const std::string& v, int& w, int& h) {
    unsigned long long a = 0, b = 0;
    char x = 0, extra = 0;
    std::istringstream in(v);
    if (!(in >> a >> x >> b) || (x != 'x' && x != 'X') || (in >> extra) || a == 0 || b == 0)
        throw UsageError("option --res: expected WIDTHxHEIGHT such as 512x512, got \"" + v + "\"");
    if (a > 65536 || b > 65536) throw UsageError("option --res: " + v + " exceeds the 65536 pixel limit per side");
    w = int(a);
    h = int(b);
}

RenderArgs parseArgs(int argc, char** argv) {
    RenderArgs r;
    Args args(argc, argv, 1);
    std::vector<std::string> positional;
    while (!args.done()) {
        std::string opt;
        if (!args.nextOption(opt)) {
            positional.push_back(args.positional());
            continue;
        }
        if (opt == "h" || opt == "help") {
            std::fputs(kRenderUsage, stdout);
            std::exit(0);
        } else if (opt == "o" || opt == "output") {
            r.output = args.value(opt);
        } else if (opt == "spp") {
            r.spp = args.integer(opt, 1, 1 << 24);
        } else if (opt == "res") {
            parseResolution(args.value(opt), r.width, r.height);
        } else if (opt == "camera") {
            r.camera = args.value(opt);
        } else if (opt == "threads") {
            r.threads = int(args.integer(opt, 0, 4096));
        } else if (opt == "seed") {
            r.settings.seed = uint64_t(args.integer(opt, 0, (1LL << 62)));
        } else if (opt == "max-depth") {
            r.settings.maxDepth = int(args.integer(opt, 0, 100000));
        } else if (opt == "light-sampling") {
            std::string v = args.value(opt);
            if (v == "mis") r.settings.lightSampling = LightSampling::Mis;
            else if (v == "nee") r.settings.lightSampling = LightSampling::Nee;
            else if (v == "bsdf") r.settings.lightSampling = LightSampling::Bsdf;
            else throw UsageError("option --light-sampling: expected mis, nee or bsdf, got \"" + v + "\"");
        } else if (opt == "hemisphere") {
            std::string v = args.value(opt);
            if (v == "cosine") r.settings.hemisphere = HemisphereSampling::Cosine;
            else if (v == "uniform") r.settings.hemisphere = HemisphereSampling::Uniform;
            else throw UsageError("option --hemisphere: expected cosine or uniform, got \"" + v + "\"");
        } else if (opt == "sampler") {
            std::string v = args.value(opt);
            if (v == "sobol") r.settings.sampler = SamplerKind::Sobol;
            else if (v == "random") r.settings.sampler = SamplerKind::Random;
            else throw UsageError("option --sampler: expected sobol or random, got \"" + v + "\"");
        } else if (opt == "aov") {
            std::stringstream list(args.value(opt));
            for (std::string name; std::getline(list, name, ',');) {
                if (name == "variance") r.aovVariance = true;
                else if (name == "albedo") r.aovAlbedo = true;
                else if (name == "normal") r.aovNormal = true;
                else if (name == "depth") r.aovDepth = true;
                else throw UsageError("option --aov: unknown layer \"" + name + "\"; known: variance, albedo, normal, depth");
            }
        } else if (opt == "clamp") {
            r.settings.clamp = float(args.number(opt, 0.0, 3e38));
        } else if (opt == "q" || opt == "quiet") {
            r.quiet = true;
        } else {
            throw UsageError("unknown option \"" + opt + "\" (pt render --help lists the options)");
        }
    }
    if (positional.empty()) throw UsageError("missing the SCENE argument");
    if (positional.size() > 1) throw UsageError("unexpected argument \"" + positional[1] + "\"; expected one SCENE");
    r.scene = positional[0];
    bool anyAov = r.aovVariance || r.aovAlbedo || r.aovNormal || r.aovDepth;
    if (anyAov && formatFromPath(r.output) != ImageFormat::Exr)
        throw UsageError("--aov needs an .exr output; \"" + r.output + "\" cannot hold extra layers");
    // Film sums (2 x 3 doubles), sample counts and the output copies: about 80 bytes a pixel.
    double bytes = double(r.width) * r.height * 80.0;
    double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (physical > 0 && bytes > 0.8 * physical)
        throw UsageError("--res " + std::to_string(r.width) + "x" + std::to_string(r.height) + " needs about " +
                         std::to_string(int(bytes / 1e9)) + " GB, more than this machine's memory");
    return r;
}

size_t pickCamera(const Scene& scene, const std::string& spec) {
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == spec) return i;
    bool numeric = !spec.empty() && spec.find_first_not_of("0123456789") == std::string::npos;
    if (numeric && spec.size() < 9 && std::stoul(spec) < scene.cameras.size()) return std::stoul(spec);
    std::string names;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " \"" + scene.cameras[i].name + "\"";
    throw UsageError("--camera " + spec + ": no such camera; the scene has " + names);
}

// Redraws one progress line on stderr until told to stop.
class ProgressLine {
public:
    ProgressLine(const RenderProgress& progress, bool enabled) : progress_(progress) {
        if (enabled) thread_ = std::thread([this] { run(); });
    }
    ~ProgressLine() { stop(); }
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        if (thread_.joinable()) {
            thread_.join();
            std::fputs("\r\033[K", stderr);
        }
    }

private:
    void run() {
        auto start = std::chrono::steady_clock::now();
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; })) {
            double total = double(std::max<uint64_t>(1, progress_.total));
            double f = double(progress_.done.load()) / total;
            double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (f > 0.0)
                std::fprintf(stderr, "\r\033[K%5.1f%%  %.1f s elapsed, about %.1f s left", 100.0 * f, elapsed,
                             elapsed * (1.0 - f) / f);
            else
                std::fprintf(stderr, "\r\033[K  0.0%%  %.1f s elapsed", elapsed);
            std::fflush(stderr);
        }
    }

    const RenderProgress& progress_;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
};

// SIGINT and SIGTERM ask the running render to stop; a second signal gets the default action.
std::atomic<bool>* gCancel = nullptr;
volatile std::sig_atomic_t gSignal = 0;

extern "C" void onStopSignal(int sig) {
    if (gSignal != 0) {
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    gSignal = sig;
    if (gCancel) gCancel->store(true); // lock-free, so safe in a handler
}

void installStopHandlers(std::atomic<bool>& cancel) {
    static_assert(std::atomic<bool>::is_always_lock_free);
    gCancel = &cancel;
    struct sigaction sa {};
    sa.sa_handler = onStopSignal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM}) {
        struct sigaction old {};
        sigaction(sig, nullptr, &old);
        if (old.sa_handler == SIG_IGN) continue; // ignored by whoever started us (a background job): keep it so
        sigaction(sig, &sa, nullptr);
    }
}

// out.exr -> out.partial.exr: where an interrupted render puts what it finished.
std::string partialPath(const std::string& output) {
    std::filesystem::path p(output);
    return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int renderCommand(int argc, char** argv) {
    RenderArgs args;
    try {
        args = parseArgs(argc, argv);
        std::string outputProblem = checkOutputPath(args.output);
        if (!outputProblem.empty()) throw UsageError(outputProblem);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "pt render: %s\n", e.what());
        return 2;
    }

    RenderProgress progress;
    installStopHandlers(progress.cancel);

    auto t0 = std::chrono::steady_clock::now();
    Scene scene;
    Warnings warnings;
    try {
        scene = loadScene(args.scene, warnings);
    } catch (const LoadError& e) {
        std::fprintf(stderr, "pt: error: %s\n", e.what());
        return 1;
    }
    if (!args.quiet)
        for (const std::string& w : warnings.messages()) std::fprintf(stderr, "pt: warning: %s\n", w.c_str());
    double loadSeconds = secondsSince(t0);

    size_t cameraIndex;
    try {
        cameraIndex = pickCamera(scene, args.camera);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "pt render: %s\n", e.what());
        return 2;
    }

    int threads = args.threads > 0 ? args.threads : tbb::this_task_arena::max_concurrency();
    auto t1 = std::chrono::steady_clock::now();
    std::unique_ptr<Accel> accel;
    try {
        tbb::task_arena arena(threads);
        arena.execute([&] { accel = std::make_unique<Accel>(scene, threads); });
    } catch (const LoadError& e) {
        std::fprintf(stderr, "pt: error: %s\n", e.what());
        return 1;
    }
    double bvhSeconds = secondsSince(t1);

    ProgressLine line(progress, !args.quiet && isatty(STDERR_FILENO));
    RenderResult result = renderImage(scene, *accel, scene.cameras[cameraIndex], args.width, args.height,
                                      uint32_t(args.spp), threads, args.settings, &progress,
                                      args.aovAlbedo || args.aovNormal || args.aovDepth);
    line.stop();

    Image image;
    image.width = args.width;
    image.height = args.height;
    image.rgb = result.film.mean();
    if (args.aovVariance) image.layers.push_back({"variance", {"R", "G", "B"}, result.film.varianceOfMean()});
    if (args.aovAlbedo) image.layers.push_back({"albedo", {"R", "G", "B"}, result.film.albedo()});
    if (args.aovNormal) image.layers.push_back({"normal", {"X", "Y", "Z"}, result.film.normal()});
    if (args.aovDepth) image.layers.push_back({"depth", {"Z"}, result.film.depth()});
    auto meta = [&](const std::string& k, const std::string& v) { image.metadata.emplace_back(k, v); };
    meta("Software", "pt " PT_VERSION);
    meta("pt:version", PT_VERSION);
    meta("pt:scene", args.scene);
    meta("pt:camera", scene.cameras[cameraIndex].name);
    meta("pt:spp", std::to_string(result.film.minSamples()));
    meta("pt:seed", std::to_string(args.settings.seed));
    meta("pt:maxDepth", std::to_string(args.settings.maxDepth));
    meta("pt:renderSeconds", std::to_string(result.seconds));
    meta("pt:clamp", std::to_string(args.settings.clamp));
    if (result.cancelled) {
        // Never replace OUT with a partial image: the finished samples go beside it.
        int status = 128 + int(gSignal ? gSignal : SIGINT);
        uint32_t done = result.film.minSamples();
        if (done == 0) {
            std::fprintf(stderr, "pt: interrupted before every pixel had a sample; nothing written\n");
            return status;
        }
        std::string partial = partialPath(args.output);
        meta("pt:interrupted", "1");
        std::string error = writeImage(partial, image);
        if (!error.empty()) std::fprintf(stderr, "pt: error: %s\n", error.c_str());
        else
            std::fprintf(stderr, "pt: interrupted after %u of %lld spp; wrote them to %s (%s untouched)\n", done,
                         args.spp, partial.c_str(), args.output.c_str());
        return status;
    }
    std::string error = writeImage(args.output, image);
    if (!error.empty()) {
        std::fprintf(stderr, "pt: error: %s\n", error.c_str());
        return 1;
    }

    const RayCounts& r = result.rays;
    std::string clampNote =
        args.settings.clamp > 0.0f ? ", " + std::to_string(r.clamped) + " clamped (--clamp biases the image)" : "";
    std::printf("pt: %dx%d, %u spp, %.3f s render (load %.3f s, bvh %.3f s), %.2f Mrays/s "
                "(camera %.2fM, continuation %.2fM, shadow %.2fM), %llu discarded samples%s, %d threads -> %s\n",
                args.width, args.height, result.film.minSamples(), result.seconds, loadSeconds, bvhSeconds,
                double(r.total()) / result.seconds * 1e-6, r.camera * 1e-6, r.continuation * 1e-6, r.shadow * 1e-6,
                (unsigned long long)r.discarded, clampNote.c_str(), threads, args.output.c_str());
    return 0;
}

} // namespace pt::cli
