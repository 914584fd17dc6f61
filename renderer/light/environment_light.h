// Importance sampling of an environment map: a piecewise-constant density over its texels,
// weighted by sin(theta) (the solid angle a texel row covers), built only when a map is used.
// A texel's weight is the largest value in its 3x3 neighbourhood, because bilinear lookups
// spread each texel into its neighbours' cells: every direction with radiance has density, so
// light sampling alone (--light-sampling nee) converges too.
#pragma once

#include "environment/environment_map.h"
#include "sampling/distribution2d.h"

namespace pt {

class EnvironmentLight {
public:
    explicit EnvironmentLight(const EnvironmentMap& map);

    // A world direction towards the environment for u in [0, 1)^2, its radiance and its
    // solid-angle density (0: no sample).
    Vec3 sample(Vec2 u, Spectrum& radiance, float& pdf) const;
    float pdf(const Vec3& dir) const;
    // Integral of the map's radiance (channel mean) over the sphere, for choosing lights by power.
    double radiantIntensityIntegral() const { return integral_; }

private:
    const EnvironmentMap& map_;
    Distribution2D distribution_;
    double integral_ = 0.0;
};

} // namespace pt
