#!/usr/bin/env python3
"""Compares two renders inside named pixel boxes: each box's mean per channel, their relative
difference and its z score (standard errors from the variance layers). For renderers whose
materials are meant to differ a little (the glTF BRDF against Cycles' Principled BSDF), the
per-object difference is the figure, not the image's.

    compare_boxes.py A.exr B.exr NAME=X0,Y0,X1,Y1 [NAME=...]   (row 0 at the top, ends excluded)
"""
import sys

import numpy as np

from exr import RGB, VARIANCE, read_channels


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    a, va = read_channels(sys.argv[1], RGB), read_channels(sys.argv[1], VARIANCE)
    b, vb = read_channels(sys.argv[2], RGB), read_channels(sys.argv[2], VARIANCE)
    worst = 0.0
    print(f"{'box':<12} {'channel':>7} {'A':>10} {'B':>10} {'A/B - 1':>9} {'z':>7}")
    for spec in sys.argv[3:]:
        name, coords = spec.split("=")
        x0, y0, x1, y1 = (int(v) for v in coords.split(","))
        n = (x1 - x0) * (y1 - y0)
        ma, mb = a[y0:y1, x0:x1].mean(axis=(0, 1)), b[y0:y1, x0:x1].mean(axis=(0, 1))
        se = np.sqrt(va[y0:y1, x0:x1].sum(axis=(0, 1)) + vb[y0:y1, x0:x1].sum(axis=(0, 1))) / n
        for c, ch in enumerate("RGB"):
            rel = ma[c] / mb[c] - 1
            worst = max(worst, abs(rel))
            print(f"{name:<12} {ch:>7} {ma[c]:10.5f} {mb[c]:10.5f} {100 * rel:8.2f}% {(ma[c] - mb[c]) / se[c]:7.1f}")
    print(f"largest |A/B - 1|: {100 * worst:.2f} %")


if __name__ == "__main__":
    main()
