#include "light/environment_light.h"

#include <cmath>

namespace pt {

EnvironmentLight::EnvironmentLight(const EnvironmentMap& map) : map_(map) {
    const int w = map.width, h = map.height;
    std::vector<double> level(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) level[size_t(y) * w + x] = average(map.texel(x, y));
    std::vector<double> weights(level.size());
    for (int y = 0; y < h; ++y) {
        // The row's exact solid angle per texel, so that a constant map integrates to 4 pi.
        double rowSolidAngle = (2.0 * kPi / w) * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
        for (int x = 0; x < w; ++x) {
            // The bilinear lookup spreads a texel's radiance as a tent over its own cell and its
            // eight neighbours': each cell is weighted by the mean of that tent over it (per axis
            // 3/4 from its own texel, 1/8 from each side's), as the lookup clamps rows at the
            // poles and wraps columns. Every cell the lookup lights has weight; the largest value
            // around a texel, weighted before, gave a lone bright texel's eight dark neighbours
            // as many samples as itself.
            double m = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int yy = std::clamp(y + dy, 0, h - 1), xx = ((x + dx) % w + w) % w;
                    m += level[size_t(yy) * w + xx] * (dx == 0 ? 0.75 : 0.125) * (dy == 0 ? 0.75 : 0.125);
                }
            weights[size_t(y) * w + x] = m * rowSolidAngle;
            integral_ += level[size_t(y) * w + x] * rowSolidAngle;
        }
    }
    distribution_ = Distribution2D(weights, w, h);
}

Vec3 EnvironmentLight::sample(Vec2 u, Spectrum& radiance, float& pdf) const {
    float pdfUv;
    Vec2 uv = distribution_.sample(u, pdfUv);
    Vec3 d = EnvironmentMap::uvToDirection(uv);
    // d(omega) = sin(theta) d(theta) d(phi) = 2 pi^2 sin(theta) du dv; sin(theta) from the
    // direction itself, as pdf() computes it, so that both agree at the poles too (d is a unit
    // vector: no overflow for std::hypot to guard against).
    float sinTheta = std::sqrt(d.x * d.x + d.z * d.z);
    pdf = pdfUv > 0.0f && sinTheta > 0.0f ? pdfUv / (2.0f * kPi * kPi * sinTheta) : 0.0f;
    radiance = map_.lookup(uv);
    return map_.toWorld(d);
}

float EnvironmentLight::pdf(const Vec3& dir) const {
    Vec3 d = map_.toMap(dir);
    float sinTheta = std::sqrt(d.x * d.x + d.z * d.z);
    if (!(sinTheta > 0.0f)) return 0.0f;
    return distribution_.pdf(EnvironmentMap::directionToUv(d)) / (2.0f * kPi * kPi * sinTheta);
}

} // namespace pt
