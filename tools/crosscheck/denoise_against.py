#!/usr/bin/python3
"""A pt render made with --denoise against another renderer's converged image (issue 36).

    denoise_against.py PT_DENOISED.exr REFERENCE.exr

Prints, for the denoised RGB and for the raw estimate kept beside it (layer noisy): the
displayed-image error (mean squared difference of clamped sRGB values), the image mean relative
to the reference's, and the largest relative difference of an 8x8 block's mean (what a filter
that shifts light locally, a caustic's or a glow's, shows first). Exit 1 if the file is not
denoised by pt (no pt:denoiser or no noisy layer).
"""
import sys

import numpy as np
import OpenImageIO as oiio


def read(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        sys.exit("denoise_against: cannot read %s" % path)
    spec = inp.spec()
    px = inp.read_image(0, 0, 0, spec.nchannels, "float")
    inp.close()
    names = list(spec.channelnames)
    layer = lambda prefix: np.stack([px[:, :, names.index(prefix + c)] for c in "RGB"], axis=-1) \
        if all(prefix + c in names for c in "RGB") else None
    return layer(""), layer("noisy."), spec.get_string_attribute("pt:denoiser")


def displayed(x):
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def blocks(x, n=8):
    h, w = (x.shape[0] // n) * n, (x.shape[1] // n) * n
    return x[:h, :w].reshape(h // n, n, w // n, n, 3).mean(axis=(1, 3))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    denoised, raw, denoiser = read(sys.argv[1])
    ref = read(sys.argv[2])[0]
    if raw is None or not denoiser:
        print("denoise_against: %s is not a pt --denoise render (no pt:denoiser or noisy layer)" % sys.argv[1])
        return 1
    if ref.shape != denoised.shape:
        sys.exit("denoise_against: sizes differ: %s against %s" % (denoised.shape, ref.shape))
    print("denoiser: %s" % denoiser)
    rb = blocks(ref)
    for label, img in (("denoised", denoised), ("raw", raw)):
        mse = float(np.mean((displayed(img) - displayed(ref)) ** 2))
        mean = float(img.mean() / ref.mean() - 1.0)
        worst = float(np.max(np.abs(blocks(img) - rb) / (np.abs(rb) + 0.01)))
        print("  %-8s displayed-image MSE %.3g, mean %+.2f %%, largest 8x8 block difference %.1f %%" %
              (label, mse, 100 * mean, 100 * worst))
    return 0


if __name__ == "__main__":
    sys.exit(main())
