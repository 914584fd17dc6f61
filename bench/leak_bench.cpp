// pt-bench leak: what Embree's robust mode buys and costs (issue 15). Rays start inside closed,
// watertight meshes (shared vertices, no cracks) in random directions; every one must hit the
// mesh, so a miss is a ray that slipped between two triangles. Counted for each build option, on
// meshes at the unit scale, tiny, huge, and far from the origin, with the time the rays took.
#include "accel/accel.h"
#include "bench/bench_common.h"
#include "sampling/rng.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace pt::bench {
namespace {

// An icosahedron subdivided `levels` times onto the unit sphere: 20 * 4^levels triangles that
// share their vertices, so the mesh is closed and has no cracks.
Scene icosphere(int levels) {
    Scene s;
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    s.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : s.positions) p = glm::normalize(p);
    s.triPositions = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto mid = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            s.positions.push_back(glm::normalize(s.positions[a] + s.positions[b]));
            return midpoints[key] = uint32_t(s.positions.size() - 1);
        };
        std::vector<glm::uvec3> finer;
        for (const glm::uvec3& f : s.triPositions) {
            uint32_t ab = mid(f.x, f.y), bc = mid(f.y, f.z), ca = mid(f.z, f.x);
            finer.insert(finer.end(), {{f.x, ab, ca}, {f.y, bc, ab}, {f.z, ca, bc}, {ab, bc, ca}});
        }
        s.triPositions = std::move(finer);
    }
    s.triMaterial.assign(s.triPositions.size(), 0);
    s.materials.emplace_back();
    return s;
}

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
    const Scene unit = icosphere(levels);
    std::printf("pt-bench leak: icosphere of %zu triangles, %lld rays from inside per mesh and option\n",
                unit.triangleCount(), rays);
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
        Scene scene = unit;
        for (Vec3& p : scene.positions) p = trial.offset + trial.scale * p;
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
