#include "environment/preetham_sky.h"

#include "environment/sunlight.h"

#include <algorithm>
#include <cmath>

namespace pt {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// Perez et al.'s distribution coefficients A..E as linear functions of turbidity (the paper's
// Appendix A.2), for luminance Y and chromaticities x and y.
constexpr double kPerez[3][5][2] = {
    {{0.1787, -1.4630}, {-0.3554, 0.4275}, {-0.0227, 5.3251}, {0.1206, -2.5771}, {-0.0670, 0.3703}},
    {{-0.0193, -0.2592}, {-0.0665, 0.0008}, {-0.0004, 0.2125}, {-0.0641, -0.8989}, {-0.0033, 0.0452}},
    {{-0.0167, -0.2608}, {-0.0950, 0.0092}, {-0.0079, 0.2102}, {-0.0441, -1.6537}, {-0.0109, 0.0529}},
};

// Zenith chromaticity: [T^2 T 1] M [thetaS^3 thetaS^2 thetaS 1]^T.
constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

double zenithPolynomial(const double (&m)[3][4], double t, double thetaS) {
    double tt[3] = {t * t, t, 1.0};
    double ss[4] = {thetaS * thetaS * thetaS, thetaS * thetaS, thetaS, 1.0};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) sum += tt[i] * m[i][j] * ss[j];
    return sum;
}

// F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma). At the horizon
// B / cos(theta) runs to -inf (B < 0 for every turbidity allowed), so the exponential goes to 0.
double perez(const double (&c)[5], double cosTheta, double gamma, double cosGamma) {
    double horizon = cosTheta > 0.0 ? std::exp(c[1] / cosTheta) : 0.0;
    return (1.0 + c[0] * horizon) * (1.0 + c[2] * std::exp(c[3] * gamma) + c[4] * cosGamma * cosGamma);
}

} // namespace

double zenithLuminance(double turbidity, double thetaS) {
    double chi = (4.0 / 9.0 - turbidity / 120.0) * (kPiD - 2.0 * thetaS);
    return (4.0453 * turbidity - 4.9710) * std::tan(chi) - 0.2155 * turbidity + 2.4192;
}
double zenithChromaticityX(double turbidity, double thetaS) { return zenithPolynomial(kZenithX, turbidity, thetaS); }
double zenithChromaticityY(double turbidity, double thetaS) { return zenithPolynomial(kZenithY, turbidity, thetaS); }

Spectrum xyzToLinearRgb(double X, double Y, double Z) {
    double r = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
    double g = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
    double b = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
    return Spectrum(float(std::max(r, 0.0)), float(std::max(g, 0.0)), float(std::max(b, 0.0)));
}

PreethamSky::PreethamSky(const SkyParameters& p) : parameters_(p) {
    const double t = p.turbidity;
    const double sunY = std::clamp(double(p.sunDirection.y), -1.0, 1.0);
    thetaS_ = std::min(std::acos(sunY), kPiD / 2.0);
    // Below the horizon the sky is that of the sun on the horizon at the same azimuth (the model
    // has no twilight): its angle gamma to each direction too, not only its zenith angle. Straight
    // down there is no azimuth; the sun is then taken at -z (azimuth 0).
    skySun_ = p.sunDirection;
    if (sunY < 0.0) {
        skySun_ = safeNormalize(Vec3(p.sunDirection.x, 0.0f, p.sunDirection.z));
        if (skySun_ == Vec3(0.0f)) skySun_ = Vec3(0.0f, 0.0f, -1.0f);
    }
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 5; ++i) coefficients_[k][i] = kPerez[k][i][0] * t + kPerez[k][i][1];
    zenith_[0] = std::max(0.0, zenithLuminance(t, thetaS_));
    zenith_[1] = zenithChromaticityX(t, thetaS_);
    zenith_[2] = zenithChromaticityY(t, thetaS_);
    // Each distribution is normalised by its value at the zenith, where theta = 0, gamma = thetaS.
    for (int k = 0; k < 3; ++k) perezNormal_[k] = perez(coefficients_[k], 1.0, thetaS_, std::cos(thetaS_));

    // The sun's disk shines where any of it is above the horizon (the ground hides the rest).
    if (sunY > -std::sin(p.sunAngularRadius)) {
        double sunZenith = std::min(std::acos(sunY), kPiD / 2.0);
        SunlightXyz s = sunRadianceXyz(t, sunZenith);
        // cd/m^2 to kcd/m^2, then to radiance.
        sunRadiance_ = xyzToLinearRgb(s.X, s.Y, s.Z) * (1e-3f * kSkyRadiancePerKcd * p.scale);
    }

    // Irradiance of a horizontal surface: the sky by the midpoint rule over (theta, phi), the sun
    // by its normal irradiance times the cosine of its elevation.
    const int nTheta = 90, nPhi = 180;
    Spectrum skySum(0.0f);
    for (int i = 0; i < nTheta; ++i) {
        double theta = (i + 0.5) * (kPiD / 2.0) / nTheta;
        double weight = std::cos(theta) * std::sin(theta) * (kPiD / 2.0 / nTheta) * (2.0 * kPiD / nPhi);
        for (int j = 0; j < nPhi; ++j) {
            double phi = (j + 0.5) * 2.0 * kPiD / nPhi;
            Vec3 d(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
            skySum += skyRadiance(d) * float(weight);
        }
    }
    groundIrradiance_ = skySum + sunNormalIrradiance() * float(std::max(0.0, sunY));
    groundRadiance_ = groundIrradiance_ * (kGroundAlbedo / kPi);
}

Vec3 PreethamSky::xyY(double theta, double gamma) const {
    double cosTheta = std::cos(std::min(theta, kPiD / 2.0)), cosGamma = std::cos(gamma);
    double v[3];
    for (int k = 0; k < 3; ++k) v[k] = zenith_[k] * perez(coefficients_[k], cosTheta, gamma, cosGamma) / perezNormal_[k];
    return Vec3(float(v[1]), float(v[2]), float(v[0]));
}

Spectrum PreethamSky::skyRadiance(const Vec3& d) const {
    double cosTheta = std::clamp(double(d.y), 0.0, 1.0);
    const Vec3& s = skySun_;
    // The angle to the sun from its sine and cosine: exact near the sun, where acos is not.
    double cosGamma = double(d.x) * s.x + double(d.y) * s.y + double(d.z) * s.z;
    Vec3 c = glm::cross(d, s);
    double gamma = std::atan2(double(glm::length(c)), cosGamma);
    double v[3];
    for (int k = 0; k < 3; ++k) v[k] = zenith_[k] * perez(coefficients_[k], cosTheta, gamma, cosGamma) / perezNormal_[k];
    double Y = v[0], x = v[1], y = v[2];
    if (!(y > 0.0) || !(Y > 0.0)) return Spectrum(0.0f);
    Spectrum rgb = xyzToLinearRgb(x / y * Y, Y, (1.0 - x - y) / y * Y);
    return rgb * (kSkyRadiancePerKcd * parameters_.scale);
}

Spectrum PreethamSky::radiance(const Vec3& d) const { return d.y >= 0.0f ? skyRadiance(d) : groundRadiance_; }

double PreethamSky::sunOneMinusCos() const {
    double h = std::sin(0.5 * parameters_.sunAngularRadius);
    return 2.0 * h * h;
}

Spectrum PreethamSky::sunNormalIrradiance() const {
    double s = std::sin(parameters_.sunAngularRadius);
    return sunRadiance_ * float(kPiD * s * s);
}

} // namespace pt
