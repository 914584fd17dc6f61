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
            // Each cell is weighted by the largest radiance the bilinear lookup gives inside it
            // (rows clamped at the poles, columns wrapped, as the lookup has them). The lookup is
            // bilinear on the four quarters of a cell between its centre, its edges' midpoints
            // and its corners, so that largest value is at one of those nine points. Bounding
            // the radiance keeps light samples and MIS weights free of fireflies: a cell weighted
            // by its mean (3/4 own, 1/8 each side, per axis) gave a one-texel sun's corner cells
            // a 16th of the density their brightest point needs, and its BSDF-sampled hits there
            // fireflies (sunlit, 16 spp: 3 times the error). The largest value in the texel's
            // 3x3 neighbourhood, the weight before, gave the sun's dark neighbours its own density.
            auto at = [&](int dx, int dy) {
                return level[size_t(std::clamp(y + dy, 0, h - 1)) * w + size_t(((x + dx) % w + w) % w)];
            };
            double m = at(0, 0);
            for (int d = -1; d <= 1; d += 2) {
                m = std::max({m, 0.5 * (at(0, 0) + at(d, 0)), 0.5 * (at(0, 0) + at(0, d))});
                for (int e = -1; e <= 1; e += 2) m = std::max(m, 0.25 * (at(0, 0) + at(d, 0) + at(0, e) + at(d, e)));
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
