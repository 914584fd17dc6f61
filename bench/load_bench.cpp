// pt-bench load: scene load and BVH build of a large mesh, and the memory each stage keeps per
// triangle (issue 15's goal: 1 M triangles loaded and built in under 1 s on 2 cores). Without
// --scene, a displaced grid of about 1 M triangles is written as OBJ to a temporary file first.
#include "accel/accel.h"
#include "bench/bench_common.h"
#include "render/shading_triangles.h"
#include "load/scene_loader.h"

#include <tbb/task_arena.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace pt::bench {
namespace {

// Resident memory now, from /proc/self/statm.
double residentBytes() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE));
}

double seconds(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// A grid of n x n quads (2 n^2 triangles) over [-1, 1]^2, displaced by a few sines, with normals.
std::string writeGrid(int n) {
    std::string path = (std::filesystem::temp_directory_path() / ("pt-bench-grid-" + std::to_string(n) + ".obj")).string();
    if (std::filesystem::exists(path)) return path;
    std::string tmp = path + ".tmp";
    FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) return "";
    std::fprintf(f, "# pt-bench load: %d x %d grid, %lld triangles\n", n, n, 2LL * n * n);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double x = -1.0 + 2.0 * i / n, z = -1.0 + 2.0 * j / n;
            std::fprintf(f, "v %.6f %.6f %.6f\n", x, 0.05 * std::sin(9.0 * x) * std::cos(7.0 * z), z);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            long a = long(j) * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
            std::fprintf(f, "f %ld %ld %ld\nf %ld %ld %ld\n", a, b, c, a, c, d);
        }
    std::fclose(f);
    std::filesystem::rename(tmp, path);
    return path;
}

} // namespace

int runLoadBench(int argc, char** argv) {
    std::string scene;
    int grid = 708; // 2 * 708^2 = 1.0 M triangles
    int threads = 0, runs = 3;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--scene" && i + 1 < argc) scene = argv[++i];
        else if (a == "--grid" && i + 1 < argc) grid = std::max(1, std::atoi(argv[++i]));
        else if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else {
            std::fputs("usage: pt-bench load [--scene PATH | --grid N (2 N^2 triangles, default 708)] [--threads N] "
                       "[--runs K]\n", a == "-h" || a == "--help" ? stdout : stderr);
            return a == "-h" || a == "--help" ? 0 : 2;
        }
    }
    if (scene.empty()) scene = writeGrid(grid);
    if (scene.empty()) {
        std::fprintf(stderr, "pt-bench load: cannot write the grid to %s\n", std::filesystem::temp_directory_path().c_str());
        return 1;
    }
    const int n = threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
    tbb::task_arena arena(n);
    std::printf("pt-bench load: %s, %d threads, %d runs\n", scene.c_str(), n, runs);
    std::vector<double> loads, builds;
    double sceneBytes = 0, embreeBytes = 0, shadingBytes = 0;
    size_t triangles = 0;
    for (int r = 0; r < runs; ++r) {
        double before = residentBytes();
        auto t0 = std::chrono::steady_clock::now();
        Warnings warnings;
        std::unique_ptr<Scene> s;
        try {
            s = std::make_unique<Scene>(loadScene(scene, warnings));
        } catch (const LoadError& e) {
            std::fprintf(stderr, "pt-bench load: %s\n", e.what());
            return 1;
        }
        loads.push_back(seconds(t0));
        double afterLoad = residentBytes();
        auto t1 = std::chrono::steady_clock::now();
        std::unique_ptr<Accel> accel;
        arena.execute([&] { accel = std::make_unique<Accel>(*s, n); });
        builds.push_back(seconds(t1));
        double afterBuild = residentBytes();
        std::vector<ShadingTriangle> shading = buildShadingTriangles(*s);
        double afterShading = residentBytes();
        triangles = s->triangleCount();
        if (r == 0) sceneBytes = afterLoad - before, embreeBytes = afterBuild - afterLoad, shadingBytes = afterShading - afterBuild;
        std::printf("  run %d: load %.3f s, BVH %.3f s, together %.3f s\n", r + 1, loads.back(), builds.back(),
                    loads.back() + builds.back());
    }
    std::sort(loads.begin(), loads.end());
    std::sort(builds.begin(), builds.end());
    double load = loads[loads.size() / 2], build = builds[builds.size() / 2];
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    double perTri = 1.0 / double(std::max<size_t>(triangles, 1));
    std::printf("  %zu triangles: load %.3f s + BVH %.3f s = %.3f s (median; goal for 1 M: under 1 s) %s\n", triangles, load,
                build, load + build, load + build < 1.0 ? "MET" : "NOT MET");
    std::printf("  resident memory kept, first run: scene arrays %.0f B/triangle, Embree's BVH %.0f B/triangle, "
                "shading records %.0f B/triangle; peak %.0f MB (%.0f B/triangle)\n",
                sceneBytes * perTri, embreeBytes * perTri, shadingBytes * perTri, double(usage.ru_maxrss) / 1024.0,
                double(usage.ru_maxrss) * 1024.0 * perTri);
    return 0;
}

} // namespace pt::bench
