// The sun's radiance at the ground (Preetham, Shirley and Smits 1999, Appendix A.2, after
// Iqbal's "An Introduction to Solar Radiation"): the extraterrestrial solar spectrum attenuated
// by Rayleigh scattering, aerosols (Angstrom's formula, from turbidity), ozone, uniformly mixed
// gases and water vapour along the relative optical mass of the sun's path, then weighted by the
// CIE 1931 colour-matching functions.
#pragma once

namespace pt {

// CIE XYZ of a radiance; Y is luminance in cd/m^2.
struct SunlightXyz {
    double X = 0.0, Y = 0.0, Z = 0.0;
};

// Radiance of the sun's disk for turbidity T and the sun's zenith angle (radians, at most pi/2).
SunlightXyz sunRadianceXyz(double turbidity, double thetaS);
// The same without the atmosphere: the extraterrestrial sun.
SunlightXyz extraterrestrialSunRadianceXyz();
// Spectral transmittance of the atmosphere along the sun's path at wavelength `nm`.
double atmosphereTransmittance(double turbidity, double thetaS, double nm);
// Relative optical mass of the path (Kasten's formula), 1 at the zenith.
double relativeOpticalMass(double thetaS);

} // namespace pt
