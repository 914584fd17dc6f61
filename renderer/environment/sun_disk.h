// The sun as seen from the scene: a disk of uniform radiance at infinity, in a cone about its
// direction. It is an emitter of the light set of its own (sampled uniformly over the cone), so
// that a tiny, very bright source does not have to be found in a map's texels.
#pragma once

#include "core/math.h"

namespace pt {

struct SunDisk {
    Vec3 direction{0.0f, 1.0f, 0.0f}; // unit, towards the sun
    float oneMinusCosRadius = 0.0f;   // 1 - cos of the angular radius, kept exact for tiny disks
    Spectrum radiance{0.0f};

    // Whether unit direction d points into the disk. |d - s|^2 = 2 (1 - cos): no cosine near 1,
    // which float could not tell from 1 for a disk of 0.27 degrees. Below the horizon the ground
    // hides the disk, so a sun that is setting shows only its upper part.
    bool covers(const Vec3& d) const {
        Vec3 e = d - direction;
        return glm::dot(e, e) <= 2.0f * oneMinusCosRadius && d.y >= 0.0f;
    }
    float solidAngle() const { return 2.0f * kPi * oneMinusCosRadius; }
};

} // namespace pt
