"""The Preetham, Shirley and Smits (1999) daylight model, written again for the cross-checks.

An independent implementation of what pt's --sky renders (issue 12), from the paper's formulas
and tables rather than from pt's code: the sky as Perez distributions of Y, x and y fitted to
turbidity, normalised at the zenith; xyY to Rec.709 at 0.06 per kcd/m^2; the ground below the
horizon at albedo 0.2 lit by the sky and the sun; the sun a disk of 959.63 arcseconds' radius whose
radiance is the extraterrestrial spectrum attenuated by Rayleigh, aerosol (Angstrom), ozone,
mixed-gas and water-vapour transmittances, weighted by the CIE 1931 functions at 683 lm/W.
"""
import math

import numpy as np

SUN_RADIUS = math.radians(959.63 / 3600.0)
GROUND_ALBEDO = 0.2
RADIANCE_PER_KCD = 0.06

# [a, b] of a*T + b for A..E, rows Y, x, y (the paper's Appendix A.2).
PEREZ = np.array([
    [[0.1787, -1.4630], [-0.3554, 0.4275], [-0.0227, 5.3251], [0.1206, -2.5771], [-0.0670, 0.3703]],
    [[-0.0193, -0.2592], [-0.0665, 0.0008], [-0.0004, 0.2125], [-0.0641, -0.8989], [-0.0033, 0.0452]],
    [[-0.0167, -0.2608], [-0.0950, 0.0092], [-0.0079, 0.2102], [-0.0441, -1.6537], [-0.0109, 0.0529]],
])
ZENITH_X = np.array([[0.00166, -0.00375, 0.00209, 0.0], [-0.02903, 0.06377, -0.03202, 0.00394],
                     [0.11693, -0.21196, 0.06052, 0.25886]])
ZENITH_Y = np.array([[0.00275, -0.00610, 0.00317, 0.0], [-0.04214, 0.08970, -0.04153, 0.00516],
                     [0.15346, -0.26756, 0.06670, 0.26688]])
XYZ_TO_RGB = np.array([[3.2404542, -1.5371385, -0.4985314], [-0.9692660, 1.8760108, 0.0415560],
                       [0.0556434, -0.2040259, 1.0572252]])

# Extraterrestrial solar spectral radiance, W/(m^2 sr nm), 380 to 750 nm every 10 nm.
SOLAR = np.array([
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2])
OZONE_NM = [300, 305, 310, 315, 320, 325, 330, 335, 340, 345, 350, 355, 445, 450, 455, 460, 465, 470,
            475, 480, 485, 490, 495, 500, 505, 510, 515, 520, 525, 530, 535, 540, 545, 550, 555, 560,
            565, 570, 575, 580, 585, 590, 595, 600, 605, 610, 620, 630, 640, 650, 660, 670, 680, 690,
            700, 710, 720, 730, 740, 750, 760, 770, 780, 790]
OZONE = [10.0, 4.8, 2.7, 1.35, 0.8, 0.38, 0.16, 0.075, 0.04, 0.019, 0.007, 0.0, 0.003, 0.003, 0.004,
         0.006, 0.008, 0.009, 0.012, 0.014, 0.017, 0.021, 0.025, 0.03, 0.035, 0.04, 0.045, 0.048,
         0.057, 0.063, 0.07, 0.075, 0.08, 0.085, 0.095, 0.103, 0.11, 0.12, 0.122, 0.12, 0.118, 0.115,
         0.12, 0.125, 0.13, 0.12, 0.105, 0.09, 0.079, 0.067, 0.057, 0.048, 0.036, 0.028, 0.023,
         0.018, 0.014, 0.011, 0.01, 0.009, 0.007, 0.004, 0.0, 0.0]
GAS_NM, GAS = [759, 760, 770, 771], [0.0, 3.0, 0.21, 0.0]
WATER_NM = [689, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790, 800]
WATER = [0.0, 0.016, 0.024, 0.0125, 1.0, 0.87, 0.061, 0.001, 1e-5, 1e-5, 0.0006, 0.0175, 0.036]
# CIE 1931 2-degree observer, 380 to 750 nm every 5 nm.
CIE_X = np.array([
    0.001368, 0.002236, 0.004243, 0.00765, 0.01431, 0.02319, 0.04351, 0.07763, 0.13438, 0.21477,
    0.2839, 0.3285, 0.34828, 0.34806, 0.3362, 0.3187, 0.2908, 0.2511, 0.19536, 0.1421, 0.09564,
    0.05795001, 0.03201, 0.0147, 0.0049, 0.0024, 0.0093, 0.0291, 0.06327, 0.1096, 0.1655,
    0.2257499, 0.2904, 0.3597, 0.4334499, 0.5120501, 0.5945, 0.6784, 0.7621, 0.8425, 0.9163,
    0.9786, 1.0263, 1.0567, 1.0622, 1.0456, 1.0026, 0.9384, 0.8544499, 0.7514, 0.6424, 0.5419,
    0.4479, 0.3608, 0.2835, 0.2187, 0.1649, 0.1212, 0.0874, 0.0636, 0.04677, 0.0329, 0.0227,
    0.01584, 0.01135916, 0.008110916, 0.005790346, 0.004109457, 0.002899327, 0.00204919,
    0.001439971, 0.0009999493, 0.0006900786, 0.0004760213, 0.0003323011])
CIE_Y = np.array([
    3.9e-05, 6.4e-05, 0.00012, 0.000217, 0.000396, 0.00064, 0.00121, 0.00218, 0.004, 0.0073,
    0.0116, 0.01684, 0.023, 0.0298, 0.038, 0.048, 0.06, 0.0739, 0.09098, 0.1126, 0.13902,
    0.1693, 0.20802, 0.2586, 0.323, 0.4073, 0.503, 0.6082, 0.71, 0.7932, 0.862, 0.9148501,
    0.954, 0.9803, 0.9949501, 1, 0.995, 0.9786, 0.952, 0.9154, 0.87, 0.8163, 0.757, 0.6949,
    0.631, 0.5668, 0.503, 0.4412, 0.381, 0.321, 0.265, 0.217, 0.175, 0.1382, 0.107, 0.0816,
    0.061, 0.04458, 0.032, 0.0232, 0.017, 0.01192, 0.00821, 0.005723, 0.004102, 0.002929,
    0.002091, 0.001484, 0.001047, 0.00074, 0.00052, 0.0003611, 0.0002492, 0.0001719, 0.00012])
CIE_Z = np.array([
    0.006450001, 0.01054999, 0.02005001, 0.03621, 0.06785001, 0.1102, 0.2074, 0.3713, 0.6456,
    1.0390501, 1.3856, 1.62296, 1.74706, 1.7826, 1.77211, 1.7441, 1.6692, 1.5281, 1.28764,
    1.0419, 0.8129501, 0.6162, 0.46518, 0.3533, 0.272, 0.2123, 0.1582, 0.1117, 0.07824999,
    0.05725001, 0.04216, 0.02984, 0.0203, 0.0134, 0.008749999, 0.005749999, 0.0039, 0.002749999,
    0.0021, 0.0018, 0.001650001, 0.0014, 0.0011, 0.001, 0.0008, 0.0006, 0.00034, 0.00024,
    0.00019, 0.0001, 4.999999e-05, 3e-05, 2e-05, 1e-05, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0])


def table(nm, xs, ys):
    return np.interp(nm, xs, ys, left=0.0, right=0.0)


def sun_xyz(turbidity, theta_s):
    """CIE XYZ of the sun's radiance (Y in cd/m^2) at zenith angle theta_s."""
    nm = np.arange(380.0, 751.0, 5.0)
    um = nm / 1000.0
    m = 1.0 / (math.cos(theta_s) + 0.15 * (93.885 - math.degrees(theta_s)) ** -1.253)
    beta = 0.04608365822050 * turbidity - 0.04586025928522
    kg, kwa = table(nm, GAS_NM, GAS), table(nm, WATER_NM, WATER)
    tau = (np.exp(-m * 0.008735 * um ** -4.08) * np.exp(-m * beta * um ** -1.3)
           * np.exp(-m * table(nm, OZONE_NM, OZONE) * 0.35)
           * np.exp(-1.41 * kg * m / (1 + 118.93 * kg * m) ** 0.45)
           * np.exp(-0.2385 * kwa * 2.0 * m / (1 + 20.07 * kwa * 2.0 * m) ** 0.45))
    radiance = np.interp(nm, np.arange(380.0, 751.0, 10.0), SOLAR) * tau
    return np.array([683.0 * 5.0 * np.sum(radiance * c) for c in (CIE_X, CIE_Y, CIE_Z)])


def to_rgb(X, Y, Z):
    rgb = np.einsum("ij,j...->...i", XYZ_TO_RGB, np.array([X, Y, Z]))
    return np.maximum(rgb, 0.0)


class Sky:
    """sun_dir: unit vector towards the sun (+y up)."""

    def __init__(self, sun_dir, turbidity=3.0, scale=1.0):
        self.sun = np.asarray(sun_dir, dtype=np.float64) / np.linalg.norm(sun_dir)
        self.scale = scale
        t = turbidity
        self.theta_s = min(math.acos(max(-1.0, min(1.0, self.sun[1]))), math.pi / 2)
        self.coef = PEREZ[:, :, 0] * t + PEREZ[:, :, 1]  # [channel][A..E]
        chi = (4.0 / 9.0 - t / 120.0) * (math.pi - 2.0 * self.theta_s)
        ts = np.array([self.theta_s ** 3, self.theta_s ** 2, self.theta_s, 1.0])
        tt = np.array([t * t, t, 1.0])
        self.zenith = np.array([max(0.0, (4.0453 * t - 4.9710) * math.tan(chi) - 0.2155 * t + 2.4192),
                                tt @ ZENITH_X @ ts, tt @ ZENITH_Y @ ts])
        self.norm = np.array([self.perez(k, 1.0, self.theta_s) for k in range(3)])
        self.sun_radiance = np.zeros(3)
        if self.sun[1] > -math.sin(SUN_RADIUS):
            self.sun_radiance = to_rgb(*sun_xyz(t, self.theta_s)) * 1e-3 * RADIANCE_PER_KCD * scale
        # Horizontal irradiance of sky and sun, then the ground's radiance.
        th = (np.arange(256) + 0.5) * (math.pi / 2) / 256
        ph = (np.arange(512) + 0.5) * 2 * math.pi / 512
        T, P = np.meshgrid(th, ph, indexing="ij")
        d = np.stack([np.sin(T) * np.cos(P), np.cos(T), np.sin(T) * np.sin(P)], axis=-1)
        w = (np.cos(T) * np.sin(T) * (math.pi / 2 / 256) * (2 * math.pi / 512))[..., None]
        sun_cos_weighted = math.pi * math.sin(SUN_RADIUS) ** 2
        irradiance = (self.sky(d) * w).sum(axis=(0, 1)) + self.sun_radiance * sun_cos_weighted * max(0.0, self.sun[1])
        self.ground = irradiance * GROUND_ALBEDO / math.pi

    def perez(self, k, cos_theta, gamma):
        A, B, C, D, E = self.coef[k]
        with np.errstate(divide="ignore", over="ignore"):
            horizon = np.where(cos_theta > 0, np.exp(B / np.maximum(cos_theta, 1e-300)), 0.0)
        return (1 + A * horizon) * (1 + C * np.exp(D * gamma) + E * np.cos(gamma) ** 2)

    def sky(self, d):
        """Sky radiance (RGB) for unit directions d[..., 3], the sun's disk excluded."""
        cos_theta = np.clip(d[..., 1], 0.0, 1.0)
        gamma = np.arccos(np.clip(d @ self.sun, -1.0, 1.0))
        Y, x, y = (self.zenith[k] * self.perez(k, cos_theta, gamma) / self.norm[k] for k in range(3))
        rgb = to_rgb(x / y * Y, Y, (1 - x - y) / y * Y)
        return rgb * RADIANCE_PER_KCD * self.scale

    def radiance(self, d):
        """Sky above the horizon, ground below."""
        return np.where(d[..., 1:2] >= 0, self.sky(d), self.ground)
