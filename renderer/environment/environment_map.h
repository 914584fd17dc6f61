// An HDR environment in a lat-long (equirectangular) image: radiance for every direction that
// leaves the scene. The convention matches Blender's for a y-up scene (as glTF and Blender's OBJ
// export give it): +y is the top row, the image's centre column looks along +x, and u grows
// towards +z, so -z (straight ahead of the lab's cameras) is a quarter of the way across.
#pragma once

#include "core/math.h"

#include <cmath>
#include <string>
#include <vector>

namespace pt {

struct EnvironmentMap {
    std::string path;
    int width = 0, height = 0;
    std::vector<float> rgb; // linear radiance, row 0 at the top (+y)
    float scale = 1.0f;     // multiplies every texel
    uint64_t sourceHash = 0; // of the file's bytes it was decoded from (readEnvironmentMap)

    // Radians about +y, right-handed: the map turns with it. Its cosine and sine are kept, as
    // every lookup and light sample turns a direction.
    void setRotation(float radians) {
        rotation_ = radians;
        cos_ = std::cos(radians);
        sin_ = std::sin(radians);
    }
    float rotation() const { return rotation_; }

    // (u, v) in [0, 1)^2 of a unit direction in the map's own frame (v = 0 at +y), and back.
    static Vec2 directionToUv(const Vec3& d);
    static Vec3 uvToDirection(Vec2 uv);
    // World direction to the map's frame (undoing the rotation), and back.
    Vec3 toMap(const Vec3& d) const;
    Vec3 toWorld(const Vec3& d) const;

    // Radiance arriving from world direction `dir` (unit): bilinear in the linear texels,
    // wrapping around in u and clamped at the poles.
    Spectrum radiance(const Vec3& dir) const { return lookup(directionToUv(toMap(dir))); }
    Spectrum lookup(Vec2 uv) const;
    Spectrum texel(int x, int y) const {
        const float* t = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
        return scale * Spectrum(t[0], t[1], t[2]);
    }

private:
    float rotation_ = 0.0f, cos_ = 1.0f, sin_ = 0.0f;
};

// Reads a lat-long map through OpenImageIO. It must hold float or half values (EXR, Radiance
// HDR, float TIFF): an 8-bit image is display-referred, not radiance. Throws LoadError naming the
// file (and the pixel, for NaN, infinite or negative values); `warning` is set for a map that is
// not twice as wide as high.
EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees, float scale, std::string& warning);

} // namespace pt
