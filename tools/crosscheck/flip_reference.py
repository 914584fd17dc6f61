#!/usr/bin/env python3
"""Recomputes tests/data/flip/official_{hdr,ldr}_error.exr with NVIDIA's flip-evaluator.

    build-crosscheck/venv/bin/pip install flip-evaluator==1.7
    build-crosscheck/venv/bin/python tools/crosscheck/flip_reference.py

The maps are the oracle of tests/flip_test.cpp; the script prints the means and exposure range
that the test expects.
"""
import os

import flip_evaluator
import numpy as np
import OpenImageIO as oiio

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "flip")


def read_rgb(path):
    buf = oiio.ImageBuf(path)
    names = list(buf.spec().channelnames)
    return np.ascontiguousarray(buf.get_pixels(oiio.FLOAT)[:, :, [names.index(c) for c in "RGB"]])


def write_grey(path, error):
    error = np.ascontiguousarray(error.reshape(error.shape[0], error.shape[1], 1), dtype=np.float32)
    spec = oiio.ImageSpec(error.shape[1], error.shape[0], 1, oiio.FLOAT)
    spec.channelnames = ("Y",)
    spec.attribute("compression", "zip")
    out = oiio.ImageOutput.create(path)
    out.open(path, spec)
    out.write_image(error)
    out.close()


reference = read_rgb(os.path.join(DATA, "reference.exr"))
test = read_rgb(os.path.join(DATA, "test.exr"))
hdr, hdr_mean, params = flip_evaluator.evaluate(reference, test, "HDR", inputsRGB=False, applyMagma=False)
ldr, ldr_mean, _ = flip_evaluator.evaluate(np.clip(reference, 0, 1), np.clip(test, 0, 1), "LDR",
                                           inputsRGB=False, applyMagma=False)
write_grey(os.path.join(DATA, "official_hdr_error.exr"), hdr)
write_grey(os.path.join(DATA, "official_ldr_error.exr"), ldr)
print(f"HDR-FLIP mean {hdr_mean!r}, exposures {params}")
print(f"LDR-FLIP mean {ldr_mean!r}")
