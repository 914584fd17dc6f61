#!/usr/bin/env python3
"""Averages independent passes (EXR files of one image) into one EXR with a variance layer.

    combine_passes.py OUT.exr PASS.exr...

The variance layer is the variance of the mean, estimated from the spread between passes, which
is what pt diff and compare.py expect of a pt render made with --aov variance.
"""
import sys

import numpy as np
import OpenImageIO as oiio


def read_rgb(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"combine_passes: {path}: {buf.geterror()}")
    names = list(buf.spec().channelnames)
    return buf.get_pixels(oiio.FLOAT)[:, :, [names.index(c) for c in "RGB"]].astype(np.float64)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out_path, passes = sys.argv[1], sys.argv[2:]
    images = np.stack([read_rgb(p) for p in passes])
    n = len(passes)
    mean = images.mean(axis=0)
    var_of_mean = images.var(axis=0, ddof=1) / n
    h, w, _ = mean.shape
    spec = oiio.ImageSpec(w, h, 6, oiio.FLOAT)
    spec.channelnames = ("R", "G", "B", "variance.R", "variance.G", "variance.B")
    spec.attribute("crosscheck:passes", n)
    out = oiio.ImageOutput.create(out_path)
    if not out or not out.open(out_path, spec):
        sys.exit(f"combine_passes: cannot write {out_path}: {oiio.geterror()}")
    pixels = np.ascontiguousarray(np.concatenate([mean, var_of_mean], axis=2), dtype=np.float32)
    if not out.write_image(pixels):
        sys.exit(f"combine_passes: cannot write {out_path}: {out.geterror()}")
    out.close()
    print(f"{out_path}: mean of {n} passes")


if __name__ == "__main__":
    main()
