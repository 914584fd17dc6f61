// pt-bench: times cornellbottle2 (or any scene) against the lab's 4-second goal, in one process:
// load and BVH build, K frames of 1 spp with pt render's defaults, the same rays replayed through
// bare Embree calls (efficiency = path-tracer rays/s over bare rays/s), thread scaling, memory.
// `pt-bench converge` runs the convergence study instead (bench/converge.cpp).
#include "accel/accel.h"
#include "bench/bench_common.h"
#include "io/output_file.h"
#include "environment/environment_map.h"
#include "render/renderer.h"
#include "load/scene_loader.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <atomic>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace pt::bench {
namespace {

constexpr double kLabGoalSeconds = 4.0;   // the lab's goal for one 1-spp frame
constexpr double kTargetSeconds = 0.12;   // issue 3's goal on 2 cores

struct Options {
    std::string scene = "../shared/scenes/lab/cornellbottle2.obj";
    int frames = 20;
    int width = 512, height = 512;
    int threads = 0;
    bool scaling = true;
    bool configs = false;
    bool batching = false;
    std::string env; // an environment map lighting the scene, as pt render --env
    std::string json = "bench/results/latest.json";
};

struct FrameSeries {
    std::vector<double> seconds;
    RayCounts rays; // of one frame (all frames trace the same number within noise)
    double median() const { return medianOf(seconds); }
};

// Renders `frames` 1-spp frames (sample indices first, first+1, ...) after one warm-up frame.
FrameSeries timeFrames(const Renderer& renderer, Film& film, int frames, int threads) {
    FrameSeries series;
    tbb::task_arena arena(threads);
    arena.execute([&] {
        renderer.renderSamples(film, 1000, 1001); // warm-up: caches, page faults, TBB workers
        for (int k = 0; k < frames; ++k) {
            auto t0 = Clock::now();
            RayCounts rays = renderer.renderSamples(film, uint32_t(k), uint32_t(k + 1));
            series.seconds.push_back(secondsSince(t0));
            if (k == 0) series.rays = rays;
        }
    });
    return series;
}

// Replays recorded rays once through bare Embree calls, in chunks on the calling arena's threads.
// `chunk` rays go to a task (4096: about a tile's worth of paths, which keeps the recorded
// coherence); `mode` says which of Embree's calls trace them (Accel::Replay).
double replayOnce(const Accel& accel, const std::vector<RayRecord>& rays, Accel::Replay mode = Accel::Replay::AsTraced,
                  size_t chunk = 4096) {
    std::atomic<size_t> hits{0};
    auto t0 = Clock::now();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), chunk), [&](const tbb::blocked_range<size_t>& b) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        hits += accel.traceBare(rays.data() + b.begin(), b.size(), mode);
    }, tbb::simple_partitioner());
    return secondsSince(t0);
}

double timeReplay(const Accel& accel, const std::vector<RayRecord>& rays, int threads, int repeats) {
    std::vector<double> seconds;
    tbb::task_arena(threads).execute([&] {
        replayOnce(accel, rays); // warm-up
        for (int r = 0; r < repeats; ++r) seconds.push_back(replayOnce(accel, rays));
    });
    return medianOf(seconds);
}

// Efficiency from interleaved pairs: a frame of the path tracer, then a bare replay of the same
// number of rays, so both see the same machine (these machines are shared and noisy).
// `ratio` is against the calls pt makes (camera packets); `ratioOneByOne` against rtcIntersect1
// and rtcOccluded1 for every ray.
struct Efficiency {
    double ratio = 0, ratioOneByOne = 0, pathTracerRps = 0, bareRps = 0;
};
Efficiency measureEfficiency(const Renderer& renderer, Film& film, const Accel& accel,
                             const std::vector<RayRecord>& rays, int threads, int pairs) {
    std::vector<double> ratios, ratiosOneByOne, pt, bare;
    tbb::task_arena(threads).execute([&] {
        renderer.renderSamples(film, 0, 1);
        replayOnce(accel, rays);
        for (int k = 0; k < pairs; ++k) {
            auto t0 = Clock::now();
            RayCounts counts = renderer.renderSamples(film, uint32_t(k), uint32_t(k + 1));
            double ptRps = double(counts.total()) / secondsSince(t0);
            double bareRps = double(rays.size()) / replayOnce(accel, rays);
            double oneByOneRps = double(rays.size()) / replayOnce(accel, rays, Accel::Replay::OneByOne);
            ratios.push_back(ptRps / bareRps);
            ratiosOneByOne.push_back(ptRps / oneByOneRps);
            pt.push_back(ptRps);
            bare.push_back(bareRps);
        }
    });
    return {medianOf(ratios), medianOf(ratiosOneByOne), medianOf(pt), medianOf(bare)};
}

std::vector<RayRecord> onlyKind(const std::vector<RayRecord>& rays, RayRecord::Kind kind) {
    std::vector<RayRecord> out;
    for (const RayRecord& r : rays)
        if (r.kind == kind) out.push_back(r);
    return out;
}

int runBench(const Options& o) {
    const int hw = tbb::this_task_arena::max_concurrency();
    const int threads = o.threads > 0 ? o.threads : hw;

    auto t0 = Clock::now();
    Warnings warnings;
    Scene scene = loadScene(o.scene, warnings);
    double loadSeconds = secondsSince(t0);
    if (!o.env.empty()) {
        std::string warning;
        scene.environment = Environment{};
        scene.environment.map = std::make_shared<const EnvironmentMap>(readEnvironmentMap(o.env, 0.0f, 1.0f, warning));
    }

    auto t1 = Clock::now();
    std::unique_ptr<Accel> accel;
    tbb::task_arena(threads).execute([&] { accel = std::make_unique<Accel>(scene, threads); });
    double bvhSeconds = secondsSince(t1);

    RenderSettings settings; // pt render's defaults
    Renderer renderer(scene, *accel, scene.cameras[0], o.width, o.height, settings, 1); // a frame is 1 spp
    Film film(o.width, o.height);

    std::printf("pt-bench: %s, %zu triangles, %dx%d, 1 spp per frame, %d frames, %d threads\n", o.scene.c_str(),
                scene.triangleCount(), o.width, o.height, o.frames, threads);
    FrameSeries main = timeFrames(renderer, film, o.frames, threads);
    const RayCounts& rays = main.rays;
    double median = main.median();
    double rps = double(rays.total()) / median;

    // Record the rays of one frame (one thread, so the log needs no lock) and replay them bare.
    std::vector<RayRecord> log;
    log.reserve(size_t(rays.total() * 1.1));
    accel->setRayLog(&log);
    tbb::task_arena(1).execute([&] { renderer.renderSamples(film, 0, 1); });
    accel->setRayLog(nullptr);
    const int repeats = 5;
    Efficiency eff = measureEfficiency(renderer, film, *accel, log, threads, std::max(5, o.frames / 2));
    double bareRps = eff.bareRps;
    double efficiency = eff.ratio;
    struct KindRate {
        const char* name;
        RayRecord::Kind kind;
        double rps = 0;
        size_t count = 0;
    };
    KindRate kinds[] = {{"camera", RayRecord::Kind::Camera}, {"continuation", RayRecord::Kind::Continuation},
                        {"shadow", RayRecord::Kind::Shadow}};
    for (KindRate& k : kinds) {
        std::vector<RayRecord> subset = onlyKind(log, k.kind);
        k.count = subset.size();
        k.rps = subset.empty() ? 0.0 : double(subset.size()) / timeReplay(*accel, subset, threads, repeats);
    }

    // Embree's build options, compared on the same recorded rays in interleaved rounds.
    struct Config {
        std::string name;
        AccelOptions options;
        std::unique_ptr<Accel> accel;
        double buildSeconds = 0;
        std::vector<double> seconds;
    };
    std::vector<Config> configs;
    if (o.configs) {
        for (bool robust : {true, false})
            for (auto q : {AccelOptions::Quality::High, AccelOptions::Quality::Medium, AccelOptions::Quality::Low})
                for (bool compact : {false, true}) {
                    Config c;
                    c.options = AccelOptions{q, robust, compact};
                    c.name = std::string(robust ? "robust " : "") +
                             (q == AccelOptions::Quality::High ? "high" : q == AccelOptions::Quality::Medium ? "medium" : "low") +
                             (compact ? " compact" : "");
                    auto tb = Clock::now();
                    tbb::task_arena(threads).execute([&] { c.accel = std::make_unique<Accel>(scene, threads, c.options); });
                    c.buildSeconds = secondsSince(tb);
                    configs.push_back(std::move(c));
                }
        tbb::task_arena(threads).execute([&] {
            for (Config& c : configs) replayOnce(*c.accel, log); // warm-up
            for (int round = 0; round < repeats; ++round)
                for (Config& c : configs) c.seconds.push_back(replayOnce(*c.accel, log));
        });
    }

    // What batching would buy (issue 15's leads): camera rays in packets of 8, shadow rays in
    // streams of a tile's size or more, against one-by-one calls, in interleaved rounds.
    if (o.batching) {
        std::printf("  Embree's batched calls against one ray at a time (median of %d interleaved rounds):\n", 2 * repeats);
        for (RayRecord::Kind kind : {RayRecord::Kind::Camera, RayRecord::Kind::Shadow}) {
            std::vector<RayRecord> subset = onlyKind(log, kind);
            for (size_t chunk : {256, 1024, 4096}) {
                std::vector<double> single, batched;
                tbb::task_arena(threads).execute([&] {
                    const Accel::Replay batch = kind == RayRecord::Kind::Camera ? Accel::Replay::AsTraced
                                                                                : Accel::Replay::ShadowStreams;
                    replayOnce(*accel, subset, batch, chunk);
                    for (int r = 0; r < 2 * repeats; ++r) {
                        single.push_back(replayOnce(*accel, subset, Accel::Replay::OneByOne, chunk));
                        batched.push_back(replayOnce(*accel, subset, batch, chunk));
                    }
                });
                double a = double(subset.size()) / medianOf(single), b = double(subset.size()) / medianOf(batched);
                std::printf("    %-7s rays, batches of %4zu: one by one %6.2f, %s %6.2f Mrays/s (x%.2f)\n",
                            kind == RayRecord::Kind::Camera ? "camera" : "shadow", chunk, a * 1e-6,
                            kind == RayRecord::Kind::Camera ? "rtcIntersect8 " : "rtcOccluded1M", b * 1e-6, b / a);
            }
        }
    }

    std::vector<std::pair<int, double>> scaling;
    if (o.scaling)
        for (int t = 1; t <= hw; ++t)
            scaling.emplace_back(t, timeFrames(renderer, film, std::max(3, o.frames / 4), t).median());

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    double peakRssMb = double(usage.ru_maxrss) / 1024.0;

    double pathLength = double(rays.camera + rays.continuation) / double(std::max<uint64_t>(1, rays.camera));
    std::printf("\n  load %.3f s, BVH build %.3f s, peak memory %.0f MB\n", loadSeconds, bvhSeconds, peakRssMb);
    std::printf("  frame: median %.4f s, min %.4f s, max %.4f s (%d frames)\n", median, minOf(main.seconds),
                maxOf(main.seconds), o.frames);
    std::printf("  rays per frame: camera %llu, continuation %llu, shadow %llu; %.2f segments per path\n",
                (unsigned long long)rays.camera, (unsigned long long)rays.continuation, (unsigned long long)rays.shadow,
                pathLength);
    std::printf("  path tracer %.2f Mrays/s (%.2f in the interleaved pairs); bare Embree on the same rays %.2f Mrays/s;\n"
                "  efficiency %.1f %% (median of frame/replay pairs; camera rays in packets of %d in both);\n"
                "  %.1f %% against bare rtcIntersect1/rtcOccluded1 for every ray\n",
                rps * 1e-6, eff.pathTracerRps * 1e-6, bareRps * 1e-6, 100.0 * efficiency, Accel::kPacket,
                100.0 * eff.ratioOneByOne);
    std::printf("  bare Embree by kind: camera %.1f, continuation %.1f, shadow %.1f Mrays/s\n", kinds[0].rps * 1e-6,
                kinds[1].rps * 1e-6, kinds[2].rps * 1e-6);
    if (!configs.empty()) {
        std::printf("  Embree build options on the same rays (median of %d interleaved rounds):\n", repeats);
        for (const Config& c : configs)
            std::printf("    %-22s build %.3f s, %6.2f Mrays/s\n", c.name.c_str(), c.buildSeconds,
                        double(log.size()) / medianOf(c.seconds) * 1e-6);
    }
    if (!scaling.empty()) {
        std::printf("  scaling:");
        for (auto [t, s] : scaling) std::printf("  %d thr %.4f s (x%.2f)", t, s, scaling[0].second / s);
        std::printf("\n");
    }
    std::printf("\n  %-34s %10s %12s\n", "against", "seconds", "this is");
    auto row = [&](const char* name, double seconds) {
        std::printf("  %-34s %10.3f %11.1fx %s\n", name, seconds, seconds / median, median <= seconds ? "inside" : "OVER");
    };
    row("lab goal (one frame)", kLabGoalSeconds);
    row("issue 3 target (2 cores)", kTargetSeconds);
    // Mitsuba is timed on this machine by tools/crosscheck/race, not quoted from another one.
    std::printf("  (pt against Mitsuba 3 on this machine: tools/crosscheck/race --all)\n");

    if (!o.json.empty()) {
        std::filesystem::path dir = std::filesystem::path(o.json).parent_path();
        if (!dir.empty()) std::filesystem::create_directories(dir);
        Json j;
        j.field("scene", o.scene).field("width", o.width).field("height", o.height).field("threads", threads);
        j.field("frames", o.frames).field("seconds_per_frame_median", median);
        j.field("seconds_per_frame_min", minOf(main.seconds)).field("seconds_per_frame_max", maxOf(main.seconds));
        j.field("goal_seconds", kLabGoalSeconds).field("target_seconds", kTargetSeconds);
        j.field("rays_per_second", rps).field("embree_rays_per_second", bareRps).field("efficiency", efficiency);
        j.field("camera_rays", double(rays.camera)).field("continuation_rays", double(rays.continuation));
        j.field("shadow_rays", double(rays.shadow)).field("segments_per_path", pathLength);
        j.field("embree_camera_rays_per_second", kinds[0].rps);
        j.field("embree_continuation_rays_per_second", kinds[1].rps);
        j.field("embree_shadow_rays_per_second", kinds[2].rps);
        j.field("load_seconds", loadSeconds).field("bvh_seconds", bvhSeconds).field("peak_rss_mb", peakRssMb);
        std::string list = "[";
        for (size_t i = 0; i < scaling.size(); ++i)
            list += (i ? ", " : "") + std::string("{\"threads\": ") + std::to_string(scaling[i].first) +
                    ", \"seconds_per_frame\": " + std::to_string(scaling[i].second) + "}";
        j.raw("scaling", list + "]");
        std::string error = writeWholeFile(o.json, j.str());
        if (!error.empty()) {
            std::fprintf(stderr, "pt-bench: %s\n", error.c_str());
            return 1;
        }
        std::printf("\n  wrote %s\n", o.json.c_str());
    }
    return 0;
}

int usage(int status) {
    std::fputs("usage: pt-bench [--scene PATH] [--frames K] [--res WxH] [--threads N] [--no-scaling] [--json PATH]\n"
               "                [--embree-configs]   (also compare Embree's build options on the recorded rays)\n"
               "                [--batching]   (also time camera-ray packets and shadow-ray streams on them)\n"
               "                [--env MAP]   (light the scene with an environment map, as pt render --env)\n"
               "       pt-bench converge --help\n"
               "       pt-bench textures [--rounds R] [--size N]   (cost of a texture lookup)\n"
               "       pt-bench sky [--rounds R]   (the baked sky map against the analytic model)\n"
               "       pt-bench load [--scene PATH | --grid N]   (load and BVH build of 1 M triangles, memory)\n"
               "       pt-bench leak [--rays N]   (rays slipping through closed meshes, per Embree build option)\n"
               "defaults: cornellbottle2 from ../shared/scenes/lab, 20 frames, 512x512, all threads,\n"
               "          JSON to bench/results/latest.json\n",
               status == 0 ? stdout : stderr);
    return status;
}

} // namespace
} // namespace pt::bench

int main(int argc, char** argv) {
    using namespace pt::bench;
    if (argc > 1 && !std::strcmp(argv[1], "converge")) return runConverge(argc - 1, argv + 1);
    if (argc > 1 && !std::strcmp(argv[1], "textures")) return runTextureBench(argc - 1, argv + 1);
    if (argc > 1 && !std::strcmp(argv[1], "sky")) return runSkyBench(argc - 1, argv + 1);
    if (argc > 1 && !std::strcmp(argv[1], "load")) return runLoadBench(argc - 1, argv + 1);
    if (argc > 1 && !std::strcmp(argv[1], "leak")) return runLeakBench(argc - 1, argv + 1);
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) std::exit(usage(2));
            return argv[++i];
        };
        if (a == "--scene") o.scene = next();
        else if (a == "--frames") o.frames = std::max(1, std::stoi(next()));
        else if (a == "--threads") o.threads = std::stoi(next());
        else if (a == "--res") {
            if (std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height) != 2) return usage(2);
        } else if (a == "--no-scaling") o.scaling = false;
        else if (a == "--embree-configs") o.configs = true;
        else if (a == "--batching") o.batching = true;
        else if (a == "--env") o.env = next();
        else if (a == "--json") o.json = next();
        else if (a == "-h" || a == "--help") return usage(0);
        else return usage(2);
    }
    try {
        return runBench(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt-bench: %s\n", e.what());
        return 1;
    }
}
