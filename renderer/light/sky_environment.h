// The Preetham sky as an environment: its radiance baked once per render into a lat-long map,
// which is then importance-sampled like any map, and the sun's disk as an emitter of its own.
#pragma once

#include "light/environment_map.h"
#include "light/preetham_sky.h"
#include "light/sun_disk.h"

namespace pt {

// 512x256 texels of 0.7 degrees: the baked sky departs from the analytic one by less than 0.1 %
// except within 2 degrees of the sun, where Perez's circumsolar term has a cusp that bilinear
// lookups round off (by up to 1 %, hidden by the sun's disk, 1e5 times brighter); the mean error
// is 1.4e-5 (SkyEnvironment.BakedMapMatchesTheModel). A lookup costs a fraction of evaluating the
// model (pt-bench sky).
inline constexpr int kSkyMapWidth = 512;

// The sky (and ground) without the sun's disk, sampled at texel centres, row 0 at +y.
EnvironmentMap bakeSky(const PreethamSky& sky, int width = kSkyMapWidth);
SunDisk sunDisk(const PreethamSky& sky);

struct Environment;
// The environment of a scene lit by the sky and its sun.
Environment skyEnvironment(const SkyParameters& parameters);

// Direction towards the sun from its elevation above the horizon and its azimuth, in degrees.
// Azimuth 0 is -z (straight ahead of a camera looking down -z), 90 is +x: clockwise seen from
// above, as on a compass with north at -z.
Vec3 sunDirectionFromAngles(double elevationDegrees, double azimuthDegrees);
// And back, for metadata and messages.
double sunElevationDegrees(const Vec3& d);
double sunAzimuthDegrees(const Vec3& d);

} // namespace pt
