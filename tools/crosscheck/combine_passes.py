#!/usr/bin/env python3
"""Averages independent passes (EXR files of one image) into one EXR with a variance layer.

    combine_passes.py OUT.exr PASS.exr...

The variance layer is the variance of the mean, estimated from the spread between passes, which
is what pt diff and compare.py expect of a pt render made with --aov variance.
"""
import sys

from exr import RGB, read_channels, write_mean_of_passes


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out_path, passes = sys.argv[1], sys.argv[2:]
    total = total_sq = 0
    for p in passes:
        image = read_channels(p, RGB)
        total, total_sq = total + image, total_sq + image * image
    write_mean_of_passes(out_path, total, total_sq, len(passes), {"crosscheck:passes": len(passes)})
    print(f"{out_path}: mean of {len(passes)} passes")


if __name__ == "__main__":
    main()
