"""EXR reading and writing for the cross-check scripts, through Debian's OpenImageIO bindings.

Images are float arrays of shape (height, width, channels), row 0 at the top, as pt writes them.
"""
import sys

import numpy as np
import OpenImageIO as oiio

RGB = ("R", "G", "B")
VARIANCE = ("variance.R", "variance.G", "variance.B")


def read_channels(path, names):
    """The named channels of an image, in that order; exits with a message naming what is missing."""
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"crosscheck: {path}: {buf.geterror()}")
    have = list(buf.spec().channelnames)
    missing = [n for n in names if n not in have]
    if missing:
        sys.exit(f"crosscheck: {path}: expected channels {','.join(names)}; missing {','.join(missing)}")
    return buf.get_pixels(oiio.FLOAT)[:, :, [have.index(n) for n in names]].astype(np.float64)


def write_channels(path, pixels, names, attributes=None):
    pixels = np.ascontiguousarray(pixels, dtype=np.float32)
    h, w, c = pixels.shape
    spec = oiio.ImageSpec(w, h, c, oiio.FLOAT)
    spec.channelnames = tuple(names)
    spec.attribute("compression", "zip")
    for key, value in (attributes or {}).items():
        spec.attribute(key, value)
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, spec) or not out.write_image(pixels):
        sys.exit(f"crosscheck: cannot write {path}: {out.geterror() if out else oiio.geterror()}")
    out.close()


def write_mean_of_passes(path, total, total_sq, n, attributes=None):
    """The mean of n independent passes, from their sum and sum of squares, with the variance of
    that mean (estimated from the spread between passes) as the layer pt diff and compare.py read."""
    mean = total / n
    var_of_mean = np.maximum(total_sq / n - mean * mean, 0) / (n - 1)
    write_channels(path, np.concatenate([mean, var_of_mean], axis=2), RGB + VARIANCE, attributes)
