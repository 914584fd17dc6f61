// The clear-sky daylight model of Preetham, Shirley and Smits 1999 ("A Practical Analytic Model
// for Daylight"): the sky's luminance and chromaticity as Perez et al.'s distributions fitted to
// turbidity and the sun's zenith angle, and the sun as a disk whose colour is the solar spectrum
// attenuated along its path through the atmosphere (environment/sunlight.h).
//
// Units: radiance is 0.06 times the model's luminance in kcd/m^2 (Cycles' legacy Preetham sky
// uses the same factor), in linear Rec.709 RGB; `scale` multiplies sky, sun and ground alike.
#pragma once

#include "core/math.h"

namespace pt {

inline constexpr float kSkyRadiancePerKcd = 0.06f;
// Mean angular radius of the sun seen from the earth: 959.63 arcseconds.
inline constexpr double kSunAngularRadius = 959.63 / 3600.0 * 3.14159265358979323846 / 180.0;
// Albedo of the ground below the horizon, the usual default of solar-radiation models.
inline constexpr float kGroundAlbedo = 0.2f;
// Where the model's fit holds: below 1.65 its luminance distribution turns negative.
inline constexpr float kMinTurbidity = 1.7f, kMaxTurbidity = 10.0f;
// The one rule for --turbidity and the MTL's turbidity: the value as the sky keeps it, a float,
// within the fit's range (so 1.7 is in range whether typed on the command line or in a file).
inline bool turbidityInRange(double t) { return float(t) >= kMinTurbidity && float(t) <= kMaxTurbidity; }

struct SkyParameters {
    Vec3 sunDirection{0.0f, 1.0f, 0.0f}; // unit, from the scene towards the sun; +y is up
    float turbidity = 3.0f;              // in [kMinTurbidity, kMaxTurbidity]
    float scale = 1.0f;
    double sunAngularRadius = kSunAngularRadius; // radians; tests widen it
};

// The paper's zenith luminance (kcd/m^2) and chromaticity, for turbidity T and the sun's zenith
// angle thetaS (radians, at most pi/2).
double zenithLuminance(double turbidity, double thetaS);
double zenithChromaticityX(double turbidity, double thetaS);
double zenithChromaticityY(double turbidity, double thetaS);

// CIE XYZ to linear Rec.709 RGB (D65), negative components clipped: the sky's chromaticities
// lie inside the gamut, so the clip only removes rounding.
Spectrum xyzToLinearRgb(double X, double Y, double Z);

class PreethamSky {
public:
    explicit PreethamSky(const SkyParameters& parameters);

    const SkyParameters& parameters() const { return parameters_; }
    // Zenith angle used by the model: the sun's, held at the horizon when the sun is below it
    // (the model has no twilight).
    double modelSunZenith() const { return thetaS_; }

    // CIE xyY of the sky (Y in kcd/m^2) at zenith angle theta <= pi/2, gamma from the sun.
    Vec3 xyY(double theta, double gamma) const;
    // Radiance from unit direction d, without the sun's disk: the sky above the horizon, the
    // ground below (albedo kGroundAlbedo, lit by groundIrradiance(), uniform).
    Spectrum radiance(const Vec3& d) const;
    Spectrum skyRadiance(const Vec3& d) const;

    // Uniform radiance of the sun's disk, 0 when it is below the horizon.
    Spectrum sunRadiance() const { return sunRadiance_; }
    // 1 - cos of the disk's angular radius (as 2 sin^2(r / 2): exact for a tiny disk), its solid
    // angle, and the irradiance it gives a surface facing it (radiance times the cosine-weighted
    // solid angle pi sin^2(radius)).
    double sunOneMinusCos() const;
    double sunSolidAngle() const { return 2.0 * 3.14159265358979323846 * sunOneMinusCos(); }
    Spectrum sunNormalIrradiance() const;

    // Irradiance of a horizontal surface from the sky (numerically integrated) and the sun.
    Spectrum groundIrradiance() const { return groundIrradiance_; }

private:
    SkyParameters parameters_;
    double thetaS_ = 0.0;
    Vec3 skySun_{0.0f, 1.0f, 0.0f}; // the sun the sky's gamma is measured to: on the horizon when it is below
    double zenith_[3]{}; // Y, x, y at the zenith
    double perezNormal_[3]{};
    double coefficients_[3][5]{}; // A..E for Y, x, y
    Spectrum sunRadiance_{0.0f}, groundIrradiance_{0.0f};
    Spectrum groundRadiance_{0.0f};
};

} // namespace pt
