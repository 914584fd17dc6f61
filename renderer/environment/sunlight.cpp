#include "environment/sunlight.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace pt {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// Extraterrestrial solar spectral radiance, W / (m^2 sr nm), every 10 nm from 380 to 750 nm (the
// paper's table, as Iqbal gives it).
constexpr double kSolarRadiance[] = {
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2,
};

// Absorption coefficients in cm^-1 at the given wavelengths (Iqbal, pages 127 and 130): ozone,
// uniformly mixed gases, water vapour. Between entries they are linear; outside, zero. The ozone
// table has no entries from 355 to 445 nm, where absorption is negligible.
struct Table {
    const double* nm;
    const double* value;
    int size;
    double operator()(double x) const {
        if (x < nm[0] || x > nm[size - 1]) return 0.0;
        int i = int(std::upper_bound(nm, nm + size, x) - nm);
        if (i >= size) return value[size - 1];
        double t = (x - nm[i - 1]) / (nm[i] - nm[i - 1]);
        return value[i - 1] + t * (value[i] - value[i - 1]);
    }
};
constexpr double kOzoneNm[] = {300, 305, 310, 315, 320, 325, 330, 335, 340, 345, 350, 355, 445, 450, 455, 460,
                               465, 470, 475, 480, 485, 490, 495, 500, 505, 510, 515, 520, 525, 530, 535, 540,
                               545, 550, 555, 560, 565, 570, 575, 580, 585, 590, 595, 600, 605, 610, 620, 630,
                               640, 650, 660, 670, 680, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790};
constexpr double kOzone[] = {10.0,  4.8,   2.7,   1.35,  0.8,   0.38,  0.16,  0.075, 0.04,  0.019, 0.007, 0.0,  0.003,
                             0.003, 0.004, 0.006, 0.008, 0.009, 0.012, 0.014, 0.017, 0.021, 0.025, 0.03, 0.035, 0.04,
                             0.045, 0.048, 0.057, 0.063, 0.07,  0.075, 0.08,  0.085, 0.095, 0.103, 0.11, 0.12,  0.122,
                             0.12,  0.118, 0.115, 0.12,  0.125, 0.13,  0.12,  0.105, 0.09,  0.079, 0.067, 0.057, 0.048,
                             0.036, 0.028, 0.023, 0.018, 0.014, 0.011, 0.01,  0.009, 0.007, 0.004, 0.0,   0.0};
constexpr double kMixedGasNm[] = {759, 760, 770, 771};
constexpr double kMixedGas[] = {0.0, 3.0, 0.21, 0.0};
constexpr double kWaterNm[] = {689, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790, 800};
constexpr double kWater[] = {0.0, 0.016, 0.024, 0.0125, 1.0, 0.87, 0.061, 0.001, 1e-5, 1e-5, 0.0006, 0.0175, 0.036};
static_assert(std::size(kOzoneNm) == std::size(kOzone) && std::size(kWaterNm) == std::size(kWater));
constexpr Table kOzoneTable{kOzoneNm, kOzone, int(std::size(kOzone))};
constexpr Table kMixedGasTable{kMixedGasNm, kMixedGas, int(std::size(kMixedGas))};
constexpr Table kWaterTable{kWaterNm, kWater, int(std::size(kWater))};

// CIE 1931 2-degree colour-matching functions every 5 nm from 380 to 750 nm (CVRL).
constexpr double kCieX[] = {
    0.001368, 0.002236, 0.004243, 0.00765, 0.01431, 0.02319, 0.04351, 0.07763,
    0.13438, 0.21477, 0.2839, 0.3285, 0.34828, 0.34806, 0.3362, 0.3187,
    0.2908, 0.2511, 0.19536, 0.1421, 0.09564, 0.05795001, 0.03201, 0.0147,
    0.0049, 0.0024, 0.0093, 0.0291, 0.06327, 0.1096, 0.1655, 0.2257499,
    0.2904, 0.3597, 0.4334499, 0.5120501, 0.5945, 0.6784, 0.7621, 0.8425,
    0.9163, 0.9786, 1.0263, 1.0567, 1.0622, 1.0456, 1.0026, 0.9384,
    0.8544499, 0.7514, 0.6424, 0.5419, 0.4479, 0.3608, 0.2835, 0.2187,
    0.1649, 0.1212, 0.0874, 0.0636, 0.04677, 0.0329, 0.0227, 0.01584,
    0.01135916, 0.008110916, 0.005790346, 0.004109457, 0.002899327, 0.00204919, 0.001439971, 0.0009999493,
    0.0006900786, 0.0004760213, 0.0003323011,
};
constexpr double kCieY[] = {
    3.9e-05, 6.4e-05, 0.00012, 0.000217, 0.000396, 0.00064, 0.00121, 0.00218,
    0.004, 0.0073, 0.0116, 0.01684, 0.023, 0.0298, 0.038, 0.048,
    0.06, 0.0739, 0.09098, 0.1126, 0.13902, 0.1693, 0.20802, 0.2586,
    0.323, 0.4073, 0.503, 0.6082, 0.71, 0.7932, 0.862, 0.9148501,
    0.954, 0.9803, 0.9949501, 1, 0.995, 0.9786, 0.952, 0.9154,
    0.87, 0.8163, 0.757, 0.6949, 0.631, 0.5668, 0.503, 0.4412,
    0.381, 0.321, 0.265, 0.217, 0.175, 0.1382, 0.107, 0.0816,
    0.061, 0.04458, 0.032, 0.0232, 0.017, 0.01192, 0.00821, 0.005723,
    0.004102, 0.002929, 0.002091, 0.001484, 0.001047, 0.00074, 0.00052, 0.0003611,
    0.0002492, 0.0001719, 0.00012,
};
constexpr double kCieZ[] = {
    0.006450001, 0.01054999, 0.02005001, 0.03621, 0.06785001, 0.1102, 0.2074, 0.3713,
    0.6456, 1.0390501, 1.3856, 1.62296, 1.74706, 1.7826, 1.77211, 1.7441,
    1.6692, 1.5281, 1.28764, 1.0419, 0.8129501, 0.6162, 0.46518, 0.3533,
    0.272, 0.2123, 0.1582, 0.1117, 0.07824999, 0.05725001, 0.04216, 0.02984,
    0.0203, 0.0134, 0.008749999, 0.005749999, 0.0039, 0.002749999, 0.0021, 0.0018,
    0.001650001, 0.0014, 0.0011, 0.001, 0.0008, 0.0006, 0.00034, 0.00024,
    0.00019, 0.0001, 4.999999e-05, 3e-05, 2e-05, 1e-05, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0,
};
constexpr int kCieCount = int(std::size(kCieY));
static_assert(kCieCount == 75 && std::size(kCieX) == 75 && std::size(kCieZ) == 75);

constexpr double kOzoneCm = 0.35;   // ozone layer thickness at NTP
constexpr double kWaterCm = 2.0;    // precipitable water vapour
constexpr double kAngstromAlpha = 1.3;
constexpr double kLumensPerWatt = 683.0;

double solarRadiance(double nm) {
    constexpr int n = int(std::size(kSolarRadiance));
    if (nm < 380.0 || nm > 750.0) return 0.0;
    double x = (nm - 380.0) / 10.0;
    int i = std::min(int(x), n - 2);
    double f = x - i;
    return kSolarRadiance[i] + f * (kSolarRadiance[i + 1] - kSolarRadiance[i]);
}

// XYZ of a spectral radiance sampled every 5 nm on the colour-matching functions' grid.
template <typename Spectrum>
SunlightXyz integrate(Spectrum radiance) {
    SunlightXyz xyz;
    for (int i = 0; i < kCieCount; ++i) {
        double l = radiance(380.0 + 5.0 * i) * 5.0 * kLumensPerWatt;
        xyz.X += l * kCieX[i];
        xyz.Y += l * kCieY[i];
        xyz.Z += l * kCieZ[i];
    }
    return xyz;
}

} // namespace

double relativeOpticalMass(double thetaS) {
    double degrees = std::min(thetaS, kPiD / 2.0) * (180.0 / kPiD);
    return 1.0 / (std::cos(thetaS) + 0.15 * std::pow(93.885 - degrees, -1.253));
}

// As the authors' code has it: the optical mass multiplies the optical depths. (The paper prints
// the Rayleigh and aerosol terms with m in the wavelength's exponent, a typesetting slip.)
double atmosphereTransmittance(double turbidity, double thetaS, double nm) {
    double m = relativeOpticalMass(thetaS);
    double um = nm * 1e-3;
    double beta = 0.04608365822050 * turbidity - 0.04586025928522; // Angstrom's turbidity coefficient
    double rayleigh = std::exp(-m * 0.008735 * std::pow(um, -4.08));
    double aerosol = std::exp(-m * beta * std::pow(um, -kAngstromAlpha));
    double ozone = std::exp(-m * kOzoneTable(nm) * kOzoneCm);
    double kg = kMixedGasTable(nm);
    double gas = std::exp(-1.41 * kg * m / std::pow(1.0 + 118.93 * kg * m, 0.45));
    double kwa = kWaterTable(nm);
    double water = std::exp(-0.2385 * kwa * kWaterCm * m / std::pow(1.0 + 20.07 * kwa * kWaterCm * m, 0.45));
    return rayleigh * aerosol * ozone * gas * water;
}

SunlightXyz sunRadianceXyz(double turbidity, double thetaS) {
    return integrate([&](double nm) { return solarRadiance(nm) * atmosphereTransmittance(turbidity, thetaS, nm); });
}

SunlightXyz extraterrestrialSunRadianceXyz() { return integrate(solarRadiance); }

} // namespace pt
