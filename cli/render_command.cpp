// pt render: load a scene, trace it, write the image. The options are parsed in
// render_options.cpp, applied to the scene in scene_overrides.cpp; a part's share and resume in
// render_part.cpp; the metadata in render_metadata.cpp.
#include "accel/accel.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/denoising.h"
#include "cli/progress_line.h"
#include "cli/render_metadata.h"
#include "cli/render_options.h"
#include "cli/render_part.h"
#include "cli/scene_overrides.h"
#include "cli/stop_signals.h"
#include "io/output_file.h"
#include "image/image_io.h"
#include "render/film_image.h"
#include "render/film_part.h"
#include "render/render_job.h"
#include "render/renderer.h"
#include "load/scene_loader.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <csignal>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace pt::cli {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int renderCommand(int argc, char** argv) {
    FILE* err = errorStream();
    RenderArgs args;
    std::string partial;
    try {
        args = parseRenderArgs(argc, argv);
        if (args.quiet) {
            silenceLibraryOutput();
            err = errorStream();
        }
        std::string problem = checkOutputPath(args.output);
        partial = partialPath(args.output);
        // The partial image's name must fit as well: found out only at Ctrl-C would be too late.
        if (problem.empty()) problem = checkOutputLocation(partial);
        if (problem.empty()) problem = outputIsInput({args.output, partial}, {args.scene});
        if (!problem.empty()) throw UsageError(problem);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt render: %s\n", e.what());
        return 2;
    }

    // The denoiser is opened before anything is loaded or written: a missing library is a usage
    // error found at once, not after an hour of rendering.
    const int hardware = tbb::info::default_concurrency();
    const int threads = args.threads > 0 ? std::min(args.threads, hardware) : hardware;
    std::unique_ptr<Denoiser> denoiser;
    if (args.denoise) {
        int status = 0;
        denoiser = openDenoiser("pt render", threads, err, status);
        if (!denoiser) return status;
    }
    // Gathered for --aov albedo, normal, depth, and as the denoiser's guides.
    const bool firstHitLayers = args.aovs.firstHit() || args.denoise;

    RenderProgress progress;
    // Until the render starts a signal quits at once (there is nothing to keep); from then on it
    // stops the render, whose finished samples are written.
    installStopHandlers("pt: interrupted before rendering began; nothing was written\n",
                        "pt: interrupted after the image was written whole\n");

    auto t0 = std::chrono::steady_clock::now();
    Scene scene;
    Warnings warnings;
    try {
        scene = loadScene(args.scene, warnings);
    } catch (const LoadError& e) {
        std::fprintf(err, "pt: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(err, "pt: error: %s: out of memory while loading the scene (its files or textures are too large "
                          "for this machine)\n", args.scene.c_str());
        return 1;
    }
    try {
        applySceneOverrides(scene, args, warnings);
    } catch (const LoadError& e) {
        std::fprintf(err, "pt: error: %s\n", e.what());
        return 1;
    }
    double loadSeconds = secondsSince(t0);

    if (args.threads > hardware)
        warnings.add("--threads " + std::to_string(args.threads) + ": this machine runs " + std::to_string(hardware) +
                     " threads at once; using " + std::to_string(hardware));
    if (!args.quiet)
        for (const std::string& w : warnings.messages()) std::fprintf(err, "pt: warning: %s\n", w.c_str());

    size_t cameraIndex;
    OutputFile output;
    std::string sceneHash;
    try {
        cameraIndex = pickCamera(scene, args.camera);
        sizeForCamera(scene.cameras[cameraIndex], args);
        std::vector<std::string> inputs;
        for (const SourceFile& f : scene.sources) inputs.push_back(f.path);
        std::string problem = outputIsInput({args.output, partial}, inputs);
        // The partial may replace the part it resumes (read whole before rendering); OUT may not.
        if (problem.empty() && !args.resume.empty()) problem = outputIsInput({args.output}, {args.resume});
        // Created now, before any rendering: a folder that refuses it fails here, not in an hour.
        if (problem.empty()) problem = output.open(args.output);
        if (!problem.empty()) throw UsageError(problem);
        sceneHash = jobHash(scene.sources);
    } catch (const UsageError& e) {
        std::fprintf(err, "pt render: %s\n", e.what());
        return 2;
    }

    JobShare share;
    if (std::string error = jobShare(args, share); !error.empty()) {
        std::fprintf(err, "pt: error: %s\n", error.c_str());
        return 1;
    }
    const uint32_t first = share.first, last = share.last;
    const PixelWindow window = share.window;
    Image job; // the job's fields, compared with a part to resume and written into the output
    addJobMetadata(job, args, scene, cameraIndex, sceneHash);
    Image resumeImage;
    Film resumeFilm(0, 0);
    if (!args.resume.empty()) {
        std::string error = readResumePart(args.resume, job, share, firstHitLayers, resumeImage, resumeFilm);
        if (!error.empty()) {
            std::fprintf(err, "pt: error: %s\n", error.c_str());
            return 1;
        }
    }

    auto t1 = std::chrono::steady_clock::now();
    std::unique_ptr<Accel> accel;
    try {
        tbb::task_arena arena(threads);
        arena.execute([&] { accel = std::make_unique<Accel>(scene, threads); });
    } catch (const LoadError& e) {
        std::fprintf(err, "pt: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(err, "pt: error: %s: out of memory while building the BVH of %zu triangles\n", args.scene.c_str(),
                     scene.triangleCount());
        return 1;
    }
    double bvhSeconds = secondsSince(t1);

    setStopTarget(&progress.cancel);
    ProgressLine line(progress, last - first, args.budget, !args.quiet && isatty(STDERR_FILENO));
    // The dark floor of adaptive sampling is meant in the image's units, after --exposure.
    SampleBudget budget = args.budget;
    budget.darkFloor = float(1e-3 / std::exp2(args.exposure));
    std::optional<RenderResult> rendered;
    try {
        RenderRange range{first, last, window, args.resume.empty() ? nullptr : &resumeFilm};
        rendered.emplace(renderImage(scene, *accel, scene.cameras[cameraIndex], args.width, args.height,
                                     uint32_t(args.spp), threads, args.settings, &progress,
                                     firstHitLayers, range, budget));
    } catch (const std::bad_alloc&) {
        line.stop();
        std::fprintf(err, "pt: error: out of memory for a %dx%d image; choose a smaller --res\n", args.width, args.height);
        return 1;
    }
    line.stop();
    const RenderResult& result = *rendered;

    size_t overflowed;
    Image image = filmImage(result.film, args.aovs, args.exposure, overflowed);
    if (overflowed > 0 && !args.quiet)
        std::fprintf(err, "pt: warning: %zu values of the image and its layers pass float's range (at --exposure %g) and "
                          "are written as the largest float\n", overflowed, args.exposure);
    image.metadata = job.metadata;
    // A part (or the partial image of an .exr render, so that it can be resumed or merged) carries
    // the sums merging needs.
    bool writePart = args.part() || (result.cancelled && formatFromPath(args.output) == ImageFormat::Exr);
    addRunMetadata(image, args, result, threads, first, last, window, writePart);

    if (result.cancelled) {
        // Never replace OUT with a partial image: the finished samples go beside it.
        // Every tile finished is kept, those of the first pass too (the pixels of tiles still in
        // flight then hold no sample): only when none had finished is there nothing to write.
        int status = 128 + (stopSignal() ? stopSignal() : SIGINT);
        const Film::SampleCounts done = result.film.sampleCounts();
        if (done.most == 0) {
            std::fprintf(err, "pt: interrupted before any tile of the first pass was finished; nothing written\n");
            return status;
        }
        image.metadata.push_back(ImageAttribute::integerValue("pt:interrupted", 1));
        OutputFile partialFile;
        std::string error = partialFile.open(partial);
        if (error.empty()) error = writeImage(partialFile, image);
        if (!error.empty()) std::fprintf(err, "pt: error: interrupted, and the partial image was lost: %s\n", error.c_str());
        else if (done.fewest == done.most)
            std::fprintf(err, "pt: interrupted after %u of %lld spp; wrote them to %s (%s untouched)\n", done.fewest,
                         args.spp, partial.c_str(), args.output.c_str());
        else
            std::fprintf(err, "pt: interrupted after %u to %u of %lld spp (mean %.2f)%s; wrote them to %s (%s untouched)\n",
                         done.fewest, done.most, args.spp, done.mean,
                         done.fewest == 0 ? ", pixels of the tiles in flight without a sample" : "", partial.c_str(),
                         args.output.c_str());
        return status;
    }
    // Denoised only here, whole: an interrupted render has written its raw partial above.
    DenoiseReport denoised;
    if (denoiser) {
        std::string error = denoiseImage(*denoiser, image, result.film.albedo(), result.film.normal(), DenoiseOptions{}, denoised);
        if (!error.empty()) {
            std::fprintf(err, "pt: error: %s; nothing was written\n", error.c_str());
            return 1;
        }
        if (denoised.replaced > 0 && !args.quiet)
            std::fprintf(err, "pt: warning: %zu values of the image passed float's range and were given 0 before denoising\n",
                         denoised.replaced);
    }
    if (std::string error = writeImage(output, image); !error.empty()) {
        std::fprintf(err, "pt: error: %s\n", error.c_str());
        return 1;
    }
    // The partial this run resumed is inside OUT now: left beside it, a merge of the folder
    // would count its samples twice.
    std::error_code ec;
    if (!args.resume.empty() && std::filesystem::equivalent(args.resume, partial, ec)) std::filesystem::remove(partial, ec);

    if (stopSignal() != 0)
        std::fprintf(err, "pt: the signal came after the last sample; the whole image was written\n");
    // A few discarded samples are rounding; many mean light lost somewhere: say so, not just count.
    const Film& film = result.film;
    const Film::SampleCounts counts = film.sampleCounts();
    uint64_t samples = uint64_t(std::llround(double(window.width()) * window.height() * counts.mean));
    if (!args.quiet && result.rays.discarded > std::max<uint64_t>(10, samples / 10000))
        std::fprintf(err, "pt: warning: %llu of %llu samples came out NaN, infinite or negative and were dropped; the image is "
                          "darker than it should be where they fell\n",
                     (unsigned long long)result.rays.discarded, (unsigned long long)samples);
    const RayCounts& r = result.rays;
    std::string clampNote =
        args.settings.clamp > 0.0f ? ", " + std::to_string(r.clamped) + " clamped (--clamp biases the image)" : "";
    // Pixels of an adaptive render hold different counts: the range, the mean and what stopped it.
    char sppText[160];
    if (counts.most == counts.fewest) std::snprintf(sppText, sizeof sppText, "%u spp", counts.fewest);
    else std::snprintf(sppText, sizeof sppText, "%u to %u spp (mean %.1f)", counts.fewest, counts.most, counts.mean);
    std::string stopNote;
    if (film.hasConvergence())
        stopNote += ", " + std::to_string(film.convergedCount()) + " of " + std::to_string(uint64_t(window.width()) * window.height()) +
                    " pixels converged";
    if (result.outOfTime) stopNote += ", stopped by --time";
    if (args.settings.guideSpp > 0) {
        char guideText[160];
        std::snprintf(guideText, sizeof guideText, ", guided (learnt from %u spp%s, guiding %.0f %% of bounces, %.1f MiB)",
                      result.guideSpp, result.guideSettled ? ", stopped there" : "", 100.0 * result.guidedFraction,
                      double(result.guideBytes) / (1 << 20));
        stopNote += guideText;
        if (!args.quiet && result.guideLimited)
            std::fprintf(err, "pt: warning: the path guide reached its memory bound (%.0f MiB): its regions stopped "
                              "splitting, so it is coarser than its samples would allow\n",
                         double(result.guideBytes) / (1 << 20));
        if (!args.quiet && args.guideSppGiven && result.guideSpp < args.settings.guideSpp && !result.guideSettled)
            std::fprintf(err, "pt: warning: --guide learnt from %u of its %u spp before a quarter of --time was spent\n",
                         result.guideSpp, args.settings.guideSpp);
    }
    char denoiseText[160] = "";
    if (denoiser) std::snprintf(denoiseText, sizeof denoiseText, ", denoised in %.3f s (OIDN %s)", denoised.seconds, denoiser->version().c_str());
    std::printf("pt: %dx%d, %s%s, %.3f s render (load %.3f s, bvh %.3f s)%s, %.2f Mrays/s "
                "(camera %.2fM, continuation %.2fM, shadow %.2fM), %llu discarded samples%s, %d threads -> %s\n",
                window.width(), window.height(), sppText, stopNote.c_str(), result.seconds, loadSeconds, bvhSeconds, denoiseText,
                double(r.total()) / result.seconds * 1e-6, r.camera * 1e-6, r.continuation * 1e-6, r.shadow * 1e-6,
                (unsigned long long)r.discarded, clampNote.c_str(), threads, args.output.c_str());
    return 0;
}

} // namespace pt::cli
