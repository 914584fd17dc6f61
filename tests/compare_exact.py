#!/usr/bin/python3
"""Exits 0 when two EXRs hold the same channels and every value agrees to --max-rel relative
(infinities must match; values below 1e-12 in both count as 0: a variance of 0 comes out 1e-20
when its sums are added in another order), else prints the worst pixel and exits 1. For
split-and-merge tests: a merged image must equal the one a single process renders, per pixel.

    compare_exact.py A.exr B.exr [--max-rel 1e-6]
"""
import sys

import numpy as np
import OpenImageIO as oiio


def load(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"compare_exact: {path}: {buf.geterror()}")
    spec = buf.spec()
    return list(spec.channelnames), buf.get_pixels(oiio.FLOAT), (spec.x, spec.y, spec.width, spec.height)


def main():
    args = sys.argv[1:]
    max_rel = 1e-6
    if "--max-rel" in args:
        i = args.index("--max-rel")
        max_rel = float(args[i + 1])
        del args[i:i + 2]
    (na, a, wa), (nb, b, wb) = load(args[0]), load(args[1])
    if wa != wb:
        sys.exit(f"compare_exact: data windows differ: {wa} and {wb}")
    np.seterr(invalid="ignore", divide="ignore")  # inf - inf where both are +inf: handled by same_inf
    worst, where = 0.0, None
    for c, name in enumerate(na):
        if name not in nb:
            print(f"compare_exact: {args[1]} has no channel {name}")
            return 1
        x, y = a[..., c], b[..., nb.index(name)]
        same_inf = (np.isinf(x) & (x == y))
        rel = np.where(same_inf, 0.0, np.abs(x - y) / np.maximum(np.abs(y), 1e-30))
        rel = np.where((np.abs(x) < 1e-12) & (np.abs(y) < 1e-12), 0.0, rel)
        k = np.unravel_index(np.argmax(rel), rel.shape)
        if rel[k] > worst:
            worst, where = float(rel[k]), (name, k, float(x[k]), float(y[k]))
    extra = sorted(set(nb) - set(na))
    if extra:
        print(f"compare_exact: {args[0]} lacks channels {extra}")
        return 1
    print(f"compare_exact: largest relative difference {worst:.3g}" + (f" ({where[0]} at row, column {where[1]}: "
                                                                      f"{where[2]} against {where[3]})" if where else ""))
    return 0 if worst <= max_rel else 1


if __name__ == "__main__":
    sys.exit(main())
