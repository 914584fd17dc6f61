#!/usr/bin/python3
"""Adaptive sampling against uniform sampling at equal time (issue 27).

For each golden case named, renders its scene with `pt render --time T` (uniform: every pixel the
same samples) and with `--time T --noise E` for each E, several seeds each, and takes the relative
MSE of each image against the case's golden reference (golden/NAME.exr, thousands of spp; the
race's metric, mean (x - ref)^2 / (ref^2 + 0.01)). Also the bias of stopping each pixel on its own
estimate: the image's mean relative to the reference's, from renders capped at -spp CAP with
--noise E and no time limit (so that the budget does not cut them).

    bench/tools/adaptive_equal_time.py CASE... [--time 2] [--noise 0.2,0.1,0.05] [--seeds 3]
        [--cap 1024] [--pt build/pt] [--csv bench/charts/adaptive.csv] [--chart bench/charts/adaptive.png]
Run it on a quiet machine: the budgets are wall-clock.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def case(name):
    for line in open(os.path.join(ROOT, "golden", "manifest.txt")):
        f = line.split()
        if f and f[0] == name and not line.startswith("#"):
            return {"scene": f[1], "camera": f[2], "res": f[3], "reference": name if f[6] == "-" else f[6], "extra": f[7:]}
    sys.exit(f"adaptive_equal_time: no case {name} in golden/manifest.txt")


def rgb(path):
    buf = oiio.ImageBuf(path)
    return buf.get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64), buf.spec()


def render(a, c, out, seed, extra):
    cmd = [a.pt, "render", c["scene"], "--camera", c["camera"], "--res", c["res"], "--seed", str(seed), "-q",
           "-o", out] + c["extra"] + extra
    subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    img, spec = rgb(out)
    return img, float(spec.getattribute("pt:renderSeconds")), float(spec.getattribute("pt:sppMean") or spec.getattribute("pt:spp"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--time", type=float, default=2.0)
    ap.add_argument("--noise", default="0.2,0.1,0.05")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--cap", type=int, default=1024)
    ap.add_argument("--pt", default=os.path.join(ROOT, "build", "pt"))
    ap.add_argument("--csv", default=os.path.join(ROOT, "bench", "charts", "adaptive.csv"))
    ap.add_argument("--chart", default=os.path.join(ROOT, "bench", "charts", "adaptive.png"))
    a = ap.parse_args()
    noises = [float(x) for x in a.noise.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "x.exr")
        for name in a.cases:
            c = case(name)
            ref, _ = rgb(os.path.join(ROOT, "golden", c["reference"] + ".exr"))
            rel = lambda x: float(np.mean((x - ref) ** 2 / (ref * ref + 0.01)))
            variants = [("uniform", 0.0)] + [(f"noise {e:g}", e) for e in noises]
            err = {v: [] for v, _ in variants}
            spp = {v: [] for v, _ in variants}
            secs = {v: [] for v, _ in variants}
            for seed in range(1, a.seeds + 1):
                for v, e in variants:  # alternating, so that both see the same machine
                    extra = ["--time", str(a.time), "-spp", str(a.cap)] + (["--noise", str(e)] if e > 0 else [])
                    img, s, n = render(a, c, out, seed, extra)
                    err[v].append(rel(img))
                    spp[v].append(n)
                    secs[v].append(s)
            base = np.mean(err["uniform"])
            for v, e in variants:
                bias = ""
                if e > 0:  # the stopping rule alone, without the time limit
                    img, _, _ = render(a, c, out, 1000, ["-spp", str(a.cap), "--noise", str(e)])
                    bias = float(img.mean() / ref.mean() - 1.0)
                m = float(np.mean(err[v]))
                rows.append((name, v, e, m, m / base, float(np.mean(spp[v])), float(np.mean(secs[v])), bias))
                print(f"{name:24s} {v:12s} relMSE {m:.5f} ({m / base:.2f}x uniform)  mean spp {np.mean(spp[v]):7.1f}  "
                      f"{np.mean(secs[v]):.2f} s" + (f"  bias of the stopping rule {bias:+.3%}" if bias != "" else ""),
                      flush=True)
    with open(a.csv, "w") as f:
        f.write("case,variant,noise,relative_mse,ratio_to_uniform,mean_spp,seconds,bias\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7, 4))
    for name in a.cases:
        pts = [(r[2], r[4]) for r in rows if r[0] == name and r[2] > 0]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
    ax.axhline(1.0, color="k", lw=0.8, ls="--")
    ax.axhline(0.67, color="r", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_xlabel("--noise E")
    ax.set_ylabel(f"relative MSE / uniform's, equal time ({a.time:g} s)")
    ax.set_title("Adaptive sampling at equal time (below 1: better than uniform)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.chart, dpi=100)


if __name__ == "__main__":
    main()
