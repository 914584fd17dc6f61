#include "environment/sky_environment.h"

#include "environment/environment.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace pt {

EnvironmentMap bakeSky(const PreethamSky& sky, int width) {
    EnvironmentMap map;
    map.path = "(Preetham sky)";
    map.width = width;
    map.height = width / 2;
    map.rgb.resize(size_t(map.width) * size_t(map.height) * 3);
    tbb::parallel_for(0, map.height, [&](int y) {
        for (int x = 0; x < map.width; ++x) {
            Vec3 d = EnvironmentMap::uvToDirection(Vec2((x + 0.5f) / map.width, (y + 0.5f) / map.height));
            Spectrum c = sky.radiance(d);
            float* t = &map.rgb[(size_t(y) * size_t(map.width) + size_t(x)) * 3];
            t[0] = c.x, t[1] = c.y, t[2] = c.z;
        }
    });
    return map;
}

SunDisk sunDisk(const PreethamSky& sky) {
    SunDisk sun;
    sun.direction = sky.parameters().sunDirection;
    sun.oneMinusCosRadius = float(sky.sunOneMinusCos());
    sun.radiance = sky.sunRadiance();
    return sun;
}

Environment skyEnvironment(const SkyParameters& parameters) {
    auto sky = std::make_shared<const PreethamSky>(parameters);
    Environment env;
    if (!isBlack(sky->sunRadiance())) env.sun = sunDisk(*sky);
    env.preetham = sky;
    return env;
}

double skyPeakRadiance(const SkyParameters& parameters) {
    PreethamSky sky(parameters);
    Vec3 sun = parameters.sunDirection, horizon = safeNormalize(Vec3(sun.x, std::max(sun.y, 0.0f), sun.z));
    double peak = maxComponent(sky.sunRadiance());
    for (Vec3 d : {sun, horizon, Vec3(0.0f, 1.0f, 0.0f)})
        if (d != Vec3(0.0f)) peak = std::max(peak, double(maxComponent(sky.radiance(d))));
    return peak;
}

Vec3 sunDirectionFromAngles(double elevationDegrees, double azimuthDegrees) {
    double e = elevationDegrees * (M_PI / 180.0), a = azimuthDegrees * (M_PI / 180.0);
    return glm::normalize(Vec3(float(std::sin(a) * std::cos(e)), float(std::sin(e)), float(-std::cos(a) * std::cos(e))));
}

double sunElevationDegrees(const Vec3& d) { return std::asin(std::clamp(double(d.y), -1.0, 1.0)) * (180.0 / M_PI); }

double sunAzimuthDegrees(const Vec3& d) {
    double a = std::atan2(double(d.x), -double(d.z)) * (180.0 / M_PI);
    return a < 0.0 ? a + 360.0 : a;
}

} // namespace pt
