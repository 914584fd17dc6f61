// The Preetham sky as an environment. Its radiance is baked once per render (by the light set)
// into a lat-long map whose texels are the density that samples it, as any map is sampled; the radiance itself comes
// from the model, which costs no more than a map lookup (pt-bench sky: about 100 ns each, most of
// it the atan2 and acos that turn a direction into map coordinates) and keeps the horizon's step
// and the circumsolar peak exact, where bilinear lookups would blur them. The sun's disk is an
// emitter of its own.
#pragma once

#include "environment/environment_map.h"
#include "environment/preetham_sky.h"
#include "environment/sun_disk.h"

namespace pt {

// 512x256 texels of 0.7 degrees: as a density the baked sky departs from the model by less than
// 0.1 % except within 2 degrees of the sun (Perez's circumsolar cusp, up to 1 %) and 0.35 degrees
// of the horizon (SkyEnvironment.BakedMapMatchesTheModel); a sampler needs no more.
inline constexpr int kSkyMapWidth = 512;

// The sky (and ground) without the sun's disk, sampled at texel centres, row 0 at +y.
EnvironmentMap bakeSky(const PreethamSky& sky, int width = kSkyMapWidth);
SunDisk sunDisk(const PreethamSky& sky);

struct Environment;
// The environment of a scene lit by the sky and its sun.
Environment skyEnvironment(const SkyParameters& parameters);
// The brightest radiance of that environment, its scale included: the sun's disk, or where the
// sun is down the sky itself (towards the sun, and at the zenith). Checked against kMaxRadiance.
double skyPeakRadiance(const SkyParameters& parameters);

// Direction towards the sun from its elevation above the horizon and its azimuth, in degrees.
// Azimuth 0 is -z (straight ahead of a camera looking down -z), 90 is +x: clockwise seen from
// above, as on a compass with north at -z.
Vec3 sunDirectionFromAngles(double elevationDegrees, double azimuthDegrees);
// And back, for metadata and messages.
double sunElevationDegrees(const Vec3& d);
double sunAzimuthDegrees(const Vec3& d);

} // namespace pt
