// pt-bench sky: what baking the Preetham sky into a lat-long map buys. The cost of one radiance
// lookup in the baked map (what escaping rays pay) against evaluating the model analytically
// (three Perez functions, an atan2 and a colour conversion), on random directions of the upper
// hemisphere; and the one-off cost per render of baking the map and building its sampler.
#include "bench/bench_common.h"
#include "light/environment_light.h"
#include "environment/sky_environment.h"
#include "sampling/rng.h"
#include "sampling/warp.h"

#include <cstring>

namespace pt::bench {
namespace {

template <typename Lookup>
double nsPerDirection(const std::vector<Vec3>& dirs, Lookup&& lookup) {
    float sum = 0.0f;
    auto t0 = Clock::now();
    for (const Vec3& d : dirs) sum += lookup(d).y;
    double ns = secondsSince(t0) * 1e9 / double(dirs.size());
    return sum == -1.0f ? ns + 1e-9 : ns; // keeps the sums alive
}

} // namespace

int runSkyBench(int argc, char** argv) {
    int rounds = 7;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--rounds" && i + 1 < argc) rounds = std::max(1, std::atoi(argv[++i]));
        else {
            std::fputs("usage: pt-bench sky [--rounds R]\n", a == "--help" || a == "-h" ? stdout : stderr);
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    SkyParameters p;
    p.sunDirection = sunDirectionFromAngles(35.0, 135.0);
    PreethamSky sky(p);
    EnvironmentMap map = bakeSky(sky);
    std::vector<Vec3> dirs;
    Pcg32 rng(1, 1);
    for (int i = 0; i < (1 << 20); ++i) {
        Vec3 d = squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        dirs.push_back(Vec3(d.x, std::abs(d.y), d.z));
    }
    std::vector<double> analytic, baked, bake, sampler;
    for (int r = 0; r < rounds; ++r) {
        analytic.push_back(nsPerDirection(dirs, [&](const Vec3& d) { return sky.radiance(d); }));
        baked.push_back(nsPerDirection(dirs, [&](const Vec3& d) { return map.radiance(d); }));
        auto t0 = Clock::now();
        EnvironmentMap m = bakeSky(PreethamSky(p));
        bake.push_back(secondsSince(t0) * 1e3);
        t0 = Clock::now();
        EnvironmentLight light(m);
        sampler.push_back(secondsSince(t0) * 1e3);
    }
    std::printf("pt-bench sky: %zu directions of the upper hemisphere, one thread, median of %d interleaved rounds\n",
                dirs.size(), rounds);
    std::printf("  analytic model  %7.1f ns per lookup\n", medianOf(analytic));
    std::printf("  baked map       %7.1f ns per lookup (%.1fx faster)\n", medianOf(baked),
                medianOf(analytic) / medianOf(baked));
    std::printf("  per render: baking %dx%d %.1f ms (all threads), building its sampler %.1f ms\n", map.width,
                map.height, medianOf(bake), medianOf(sampler));
    return 0;
}

} // namespace pt::bench
