#!/usr/bin/python3
"""Writes renderer/material/sheen_albedo_table.h: the directional albedo E(cos, alpha) of
KHR_materials_sheen's lobe (Charlie distribution, the Charlie visibility of Estevez and Kulla
2017, sheen colour 1), which the albedo-scaling of the base layer needs.

    E(mu, alpha) = integral over the hemisphere of D(h) / (4 mu (1 + Lambda(mu) + Lambda(cos_i))) d omega_i

(f cos_i with the extension's visibility), by the midpoint rule in (theta_i, phi_i), 512 x 256
cells over the half hemisphere phi in [0, pi] (the lobe is symmetric in phi), times 2. The grid:
mu = i / 63 for i in 0..63 (the first node taken at mu = 0.5 / 63, where E is finite; the last at
mu = 1, since the visibility's fit is steep there) and alpha = (j + 1) / 32 for j in 0..31. Independent of the C++ lobe:
tests/metal_rough_bsdf_test.cpp integrates that one by Monte Carlo and compares.

Run from the repository root: /usr/bin/python3 tools/sheen_albedo.py
"""
import os
import numpy as np

N = 32   # alpha nodes
M = 64   # mu nodes


def lam(x, alpha):
    t = (1.0 - alpha) ** 2
    a = 21.5473 * (1 - t) + 25.3245 * t
    b = 3.82987 * (1 - t) + 3.32435 * t
    c = 0.19823 * (1 - t) + 0.16801 * t
    d = -1.97760 * (1 - t) + -1.27393 * t
    e = -4.32054 * (1 - t) + -4.85967 * t
    l = lambda y: a / (1.0 + b * np.power(y, c)) + d * y + e
    return np.where(x < 0.5, np.exp(l(x)), np.exp(2.0 * l(0.5) - l(np.maximum(1.0 - x, 0.0))))


def albedo(mu, alpha, nt=512, nphi=256):
    theta = (np.arange(nt) + 0.5) * (np.pi / 2) / nt
    phi = (np.arange(nphi) + 0.5) * np.pi / nphi
    th, ph = np.meshgrid(theta, phi, indexing="ij")
    wi = np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)], -1)
    wo = np.array([np.sqrt(1 - mu * mu), 0.0, mu])
    h = wi + wo
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    sin2h = np.maximum(1.0 - h[..., 2] ** 2, 0.0)
    D = (2.0 + 1.0 / alpha) * np.power(sin2h, 0.5 / alpha) / (2 * np.pi)
    fcos = D / (4.0 * mu * (1.0 + lam(mu, alpha) + lam(wi[..., 2], alpha)))
    cell = np.sin(th) * (np.pi / 2 / nt) * (np.pi / nphi)
    return 2.0 * float(np.sum(fcos * cell))


def main():
    rows = []
    for j in range(N):
        alpha = (j + 1) / N
        rows.append([albedo(max(i, 0.5) / (M - 1), alpha) for i in range(M)])
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "renderer", "material", "sheen_albedo_table.h")
    with open(out, "w") as f:
        f.write("// Made by tools/sheen_albedo.py (see there how); do not edit.\n")
        f.write("// E(mu, alpha) of the sheen lobe: row j is alpha = (j + 1) / 32, column i is mu = i / 63.\n")
        f.write("#pragma once\n\nnamespace pt {\n\n")
        f.write("inline constexpr int kSheenAlphaNodes = %d, kSheenCosNodes = %d;\n" % (N, M))
        f.write("inline constexpr float kSheenAlbedo[kSheenAlphaNodes][kSheenCosNodes] = {\n")
        for r in rows:
            f.write("    {" + ", ".join("%.6ff" % v for v in r) + "},\n")
        f.write("};\n\n} // namespace pt\n")
    print("E at mu 1:", [round(rows[j][-1], 4) for j in (0, 7, 15, 31)], " at mu 0.008:", [round(rows[j][0], 4) for j in (0, 7, 15, 31)])


if __name__ == "__main__":
    main()
