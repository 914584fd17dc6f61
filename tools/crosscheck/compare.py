#!/usr/bin/env python3
"""Compares two renders of one scene by their means, with standard errors from their variance layers.

Prints, per channel, the image means and their relative difference with its z score, then the
same for a GRID x GRID array of regions. The question it answers is the one of issue 2's
independent check: do two unbiased renderers converge to the same image to 0.1 %? A relative
difference is only evidence of disagreement when it is large against its standard error.
"""
import argparse
import sys

import numpy as np

from exr import RGB, VARIANCE, read_channels


def read(path):
    return read_channels(path, RGB), read_channels(path, VARIANCE)


def region_stats(a, va, b, vb):
    """Relative difference of means a/b - 1 and its z score; pixels are independent estimates."""
    n = a.shape[0] * a.shape[1]
    ma, mb = a.mean(axis=(0, 1)), b.mean(axis=(0, 1))
    # Variance of the region mean = sum of per-pixel variances of the mean / n^2.
    se = np.sqrt(va.sum(axis=(0, 1)) + vb.sum(axis=(0, 1))) / n
    return ma, mb, ma / mb - 1, (ma - mb) / se, se / mb


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("test")
    ap.add_argument("reference")
    ap.add_argument("--grid", type=int, default=4)
    ap.add_argument("--below", type=float, default=1.0,
                    help="also compare only the pixels whose reference is below this in every channel, "
                         "which leaves out emitters seen directly (exact in both) [1]")
    a = ap.parse_args()
    t, vt = read(a.test)
    r, vr = read(a.reference)
    if t.shape != r.shape:
        sys.exit(f"compare: sizes differ: {t.shape[:2]} against {r.shape[:2]}")
    mt, mr, rel, z, serr = region_stats(t, vt, r, vr)
    print(f"{a.test} against {a.reference}")
    print("whole image    " + "   ".join(f"{c}: {mt[i]:.5f} vs {mr[i]:.5f} ({100 * rel[i]:+.3f}% +- {100 * serr[i]:.3f}%, z {z[i]:+.2f})"
                                   for i, c in enumerate("RGB")))
    keep = r.max(axis=2) < a.below
    if keep.any():
        mt, mr, rel, z, serr = region_stats(t[keep][None], vt[keep][None], r[keep][None], vr[keep][None])
        print(f"below {a.below:g} ({100 * keep.mean():.1f}% of pixels)  " + "   ".join(
            f"{c}: {mt[i]:.5f} vs {mr[i]:.5f} ({100 * rel[i]:+.3f}% +- {100 * serr[i]:.3f}%, z {z[i]:+.2f})"
            for i, c in enumerate("RGB")))
    h, w = t.shape[:2]
    g = a.grid
    worst = 0.0
    zs = []
    print(f"regions of {w // g}x{h // g} px, relative difference of the luminance-weighted mean, with z:")
    lum = np.array([0.2126, 0.7152, 0.0722])
    for by in range(g):
        row = []
        for bx in range(g):
            sl = (slice(by * h // g, (by + 1) * h // g), slice(bx * w // g, (bx + 1) * w // g))
            tl, rl = (t[sl] * lum).sum(axis=2, keepdims=True), (r[sl] * lum).sum(axis=2, keepdims=True)
            vtl, vrl = (vt[sl] * lum**2).sum(axis=2, keepdims=True), (vr[sl] * lum**2).sum(axis=2, keepdims=True)
            _, _, rr, zz, _ = region_stats(tl, vtl, rl, vrl)
            row.append(f"{100 * rr[0]:+6.2f}% ({zz[0]:+5.1f})")
            worst = max(worst, abs(rr[0]))
            zs.append(zz[0])
        print("  " + "  ".join(row))
    zs = np.array(zs)
    print(f"largest region difference {100 * worst:.2f}%; region z scores: rms {np.sqrt((zs**2).mean()):.2f}, "
          f"max |z| {np.abs(zs).max():.2f} (about 1 and below 3 when only noise separates them)")


if __name__ == "__main__":
    main()
