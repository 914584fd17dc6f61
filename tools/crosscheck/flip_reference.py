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

from exr import RGB, read_channels, write_channels

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "flip")


def write_grey(path, error):
    write_channels(path, error.reshape(error.shape[0], error.shape[1], 1), ("Y",))


reference = read_channels(os.path.join(DATA, "reference.exr"), RGB).astype(np.float32)
test = read_channels(os.path.join(DATA, "test.exr"), RGB).astype(np.float32)
hdr, hdr_mean, params = flip_evaluator.evaluate(reference, test, "HDR", inputsRGB=False, applyMagma=False)
ldr, ldr_mean, _ = flip_evaluator.evaluate(np.clip(reference, 0, 1), np.clip(test, 0, 1), "LDR",
                                           inputsRGB=False, applyMagma=False)
write_grey(os.path.join(DATA, "official_hdr_error.exr"), hdr)
write_grey(os.path.join(DATA, "official_ldr_error.exr"), ldr)
print(f"HDR-FLIP mean {hdr_mean!r}, exposures {params}")
print(f"LDR-FLIP mean {ldr_mean!r}")
