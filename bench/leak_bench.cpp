// pt-bench leak: what Embree's robust mode buys and costs (issue 15). Rays start inside closed,
// watertight meshes (a subdivided icosahedron: neighbouring triangles share their corners'
// coordinates exactly, so there are no cracks) in random directions; every one must hit the
// mesh, so a miss is a ray that slipped between two triangles. Counted for each build option, on
// meshes at the unit scale, tiny, huge, and far from the origin, with the time the rays took.
#include "accel/accel.h"
#include "bench/bench_common.h"
#include "sampling/rng.h"
#include "tests/scene_builders.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace pt::bench {
namespace {

struct Trial {
    const char* name;
    float scale;
    Vec3 offset;
};

int usage(int status) {
    std::fprintf(status ? stderr : stdout, "usage: pt-bench leak [--rays N (per mesh and option, default 4000000)] "
                                           "[--levels L (icosphere subdivisions, default 7)]\n");
    return status;
}

} // namespace

int runLeakBench(int argc, char** argv) {
    long long rays = 4000000;
    int levels = 7;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--rays") && i + 1 < argc) rays = std::max(1LL, std::atoll(argv[++i]));
        else if (!std::strcmp(argv[i], "--levels") && i + 1 < argc) levels = std::clamp(std::atoi(argv[++i]), 0, 9);
        else if (!std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help")) return usage(0);
        else return usage(2);
    }
    // A subdivided icosahedron of 20 * 4^levels triangles, at each trial's place and size.
    auto sphereAt = [&](Vec3 center, float radius) {
        Scene s;
        test::addIcosphere(s, center, radius, levels, test::addMaterial(s, Material{}));
        return s;
    };
    std::printf("pt-bench leak: icosphere of %zu triangles, %lld rays from inside per mesh and option\n",
                size_t(20) << (2 * levels), rays);
    const Trial trials[] = {{"unit sphere at the origin", 1.0f, Vec3(0.0f)},
                            {"radius 1e-3", 1e-3f, Vec3(0.0f)},
                            {"radius 1e4", 1e4f, Vec3(0.0f)},
                            {"unit sphere at (1e3, 1e3, 1e3)", 1.0f, Vec3(1e3f)}};
    struct Option {
        const char* name;
        AccelOptions options;
    };
    const Option options[] = {{"robust, high (pt's)", {AccelOptions::Quality::High, true, false}},
                              {"high", {AccelOptions::Quality::High, false, false}},
                              {"medium", {AccelOptions::Quality::Medium, false, false}},
                              {"low", {AccelOptions::Quality::Low, false, false}}};
    for (const Trial& trial : trials) {
        Scene scene = sphereAt(trial.offset, trial.scale);
        std::printf("\n  %s\n", trial.name);
        for (const Option& option : options) {
            Accel accel(scene, 0, option.options);
            std::atomic<long long> misses{0};
            auto t0 = Clock::now();
            tbb::parallel_for(tbb::blocked_range<long long>(0, rays, 1 << 14), [&](const tbb::blocked_range<long long>& r) {
                Pcg32 rng(uint64_t(r.begin()), 7);
                long long local = 0;
                for (long long i = r.begin(); i != r.end(); ++i) {
                    // A point inside half the radius and a uniform direction.
                    Vec3 o, d;
                    do o = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 2.0f - 1.0f;
                    while (glm::dot(o, o) > 1.0f);
                    do d = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 2.0f - 1.0f;
                    while (glm::dot(d, d) > 1.0f || glm::dot(d, d) < 1e-4f);
                    Ray ray{trial.offset + 0.5f * trial.scale * o, glm::normalize(d)};
                    local += !accel.intersect(ray).found();
                }
                misses += local;
            });
            double s = secondsSince(t0);
            std::printf("    %-20s %8lld of %lld rays slipped through (%.2g), %6.2f Mrays/s\n", option.name,
                        misses.load(), rays, double(misses.load()) / double(rays), double(rays) / s * 1e-6);
        }
    }
    return 0;
}

} // namespace pt::bench
