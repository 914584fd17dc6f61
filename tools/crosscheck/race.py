#!/usr/bin/env python3
"""Races pt against Mitsuba 3's LLVM path tracer on one lab scene: error against time for both.

Both render the scene at 1, 2, 4, ... samples per pixel, one launch each, on all threads. The time
is the render alone, without process start, scene load or BVH build for pt (the render time it
prints), and without scene load or kernel compilation for Mitsuba (each sample count is rendered
once untimed first, so its kernel is cached). Each sample count is rendered with several seeds,
--budget samples per pixel in all (at least 2 renders); the curve takes the median time and the
mean error, since a single render's error is dominated by its few brightest outliers.

The error is the relative MSE, mean over pixels and channels of (x - r)^2 / (r^2 + 0.01), against a
reference rendered by Mitsuba (cached in build-crosscheck/): any disagreement between the
renderers counts against pt. Mitsuba gets pt's Russian roulette depth (3) unless --rr-depth says
otherwise; its survival rule stays its own (the throughput, at most 0.95), where pt keeps a path
whose throughput is above a quarter.

For unbiased renderers error falls as 1 / time, so error x seconds is one number per renderer:
its mean over the sample counts from 8 spp on gives the equal-time error ratio, steadier than
reading two noisy curves at one time.

With --pt-noise C, pt also races with adaptive sampling: at N spp it renders with --noise
C/sqrt(N), the target falling as the uniform error does, and --min-spp min(16, N); its error x
seconds is reported beside the others (issue 27). With --pt-guide, pt also races with --guide, its
training passes (a quarter of the count at most, at most 63; the image's first samples) inside
its time (issue 38).

Writes bench/charts/race_NAME.csv and .png (error against seconds, both renderers) and prints
seconds per sample and the equal-time error ratio. Run it with tools/crosscheck/race, which
installs Mitsuba into the crosscheck's virtual environment.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_lab  # noqa: E402  (sets Mitsuba's variant)
from exr import RGB, read_channels, write_channels  # noqa: E402
from lab_scene import sun_direction  # noqa: E402

mi = mitsuba_lab.mi


def relative_mse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref * ref + 0.01)))


def adaptive_args(a, spp):
    """pt's adaptive sampling for a race at `spp`: the noise target falls as 1 / sqrt(spp), as the
    uniform error does, so that at every sample count the pixels quieter than --pt-noise's
    relative spread per sample stop early and the others go on to the cap."""
    return ["--noise", f"{min(0.99, a.pt_noise / spp ** 0.5):.6g}", "--min-spp", str(min(16, spp))]


def render_pt(a, spp, seed, tmp, adaptive=False, guided=False):
    out = os.path.join(tmp, "pt.exr")
    cmd = [a.pt, "render", a.scene, "--camera", str(a.camera), "--res", a.res, "-spp", str(spp),
           "--seed", str(seed), "-o", out] + a.pt_args + (adaptive_args(a, spp) if adaptive else [])
    cmd += ["--guide"] if guided else []  # its training (a quarter of spp, at most 63) is in its time
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    seconds = float(re.search(r"([0-9.]+) s render", text).group(1))
    return read_channels(out, RGB), seconds


def render_mitsuba(scene, spp, seed):
    t0 = time.perf_counter()
    img = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)[:, :, :3]  # the copy waits for the kernel
    return img, time.perf_counter() - t0


def reference(a, scene, path):
    if os.path.exists(path):
        return read_channels(path, RGB)
    passes = max(1, a.reference_spp // 64)
    total = None
    start = time.time()
    for p in range(passes):
        img = np.array(mi.render(scene, spp=64, seed=100000 + p), dtype=np.float64)[:, :, :3]
        total = img if total is None else total + img
        print(f"\rrace: reference pass {p + 1}/{passes}, {time.time() - start:.0f} s", end="", file=sys.stderr)
    print(file=sys.stderr)
    ref = total / passes
    write_channels(path, ref, RGB)
    return ref


def plot(rows, title, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for name, style in (("pt", "o-"), ("mitsuba", "s-"), ("pt adaptive", "^-"), ("pt guided", "d-")):
        pts = [(r["seconds"], r["rel_mse"]) for r in rows if r["renderer"] == name]
        if not pts:
            continue
        label = {"pt": "pt", "pt adaptive": "pt --noise (target falling as 1/sqrt(spp))",
                 "pt guided": "pt --guide (its learning included)"}.get(
            name, f"Mitsuba {mi.__version__} LLVM path tracer")
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=label, markersize=4)
    ax.set_title(f"{title}: error against render time")
    ax.set_xlabel("seconds (2 threads)")
    ax.set_ylabel("relative MSE vs. Mitsuba reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--name", help="the chart's name [the scene's]")
    ap.add_argument("--camera", type=int, default=0)
    ap.add_argument("--res", default="256x256")
    ap.add_argument("--max-spp", type=int, default=256)
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--rr-depth", type=int, default=3)
    ap.add_argument("--summary", action="store_true", help="print the figures and redraw the chart from the CSV")
    ap.add_argument("--budget", type=int, default=256, help="samples per pixel rendered at each sample count [256]")
    ap.add_argument("--pt", default="build/pt")
    ap.add_argument("--out-dir", default="bench/charts")
    ap.add_argument("--pt-normals", action="store_true", help="as for mitsuba_lab.py (cornellbottle2)")
    ap.add_argument("--pt-noise", type=float, default=0.0,
                    help="also race pt with adaptive sampling, --noise C/sqrt(spp) at each spp (C: this value)")
    ap.add_argument("--pt-guide", action="store_true", help="pt also races with --guide (issue 38)")
    ap.add_argument("--env")
    ap.add_argument("--env-rotate", type=float, default=0.0)
    ap.add_argument("--sky", action="store_true")
    ap.add_argument("--sun-elevation", type=float, default=45.0)
    ap.add_argument("--sun-azimuth", type=float, default=135.0)
    ap.add_argument("--turbidity", type=float, default=3.0)
    a = ap.parse_args()
    name = a.name or os.path.splitext(os.path.basename(a.scene))[0]
    width, height = (int(x) for x in a.res.lower().split("x"))
    a.pt_args = ["-q"]
    env = sky = None
    if a.env:
        env = (a.env, a.env_rotate, 1.0)
        a.pt_args += ["--env", a.env, "--env-rotate", str(a.env_rotate)]
    if a.sky:
        sky = (sun_direction(a.sun_elevation, a.sun_azimuth), a.turbidity, 1.0)
        a.pt_args += ["--sky", "--sun-elevation", str(a.sun_elevation), "--sun-azimuth", str(a.sun_azimuth),
                      "--turbidity", str(a.turbidity)]
    os.makedirs(a.out_dir, exist_ok=True)
    csv_path = os.path.join(a.out_dir, f"race_{name}.csv")
    if a.summary:  # the figures and chart again from the CSV, nothing rendered
        with open(csv_path) as f:
            rows = [{"renderer": r["renderer"], "spp": int(r["spp"]), "seconds": float(r["seconds"]),
                     "rel_mse": float(r["rel_mse"])} for r in csv.DictReader(f)]
    else:
        rows = []
        with tempfile.TemporaryDirectory() as tmp:
            scene = mitsuba_lab.build_scene(a.scene, a.camera, width, height, 16, a.pt_normals, tmp, a.rr_depth, env, sky)
            ref = reference(a, scene, os.path.join("build-crosscheck", f"race_{name}_{a.res}_reference.exr"))
            render_pt(a, 1, 999, tmp)  # warm the file cache
            spp = 1
            while spp <= a.max_spp:
                repeats = max(2, a.budget // spp)
                render_mitsuba(scene, spp, 999)  # compiles (or finds) the kernel for this size
                for renderer in ("pt", "mitsuba") + (("pt adaptive",) if a.pt_noise > 0 else ()) + (
                        ("pt guided",) if a.pt_guide else ()):
                    errors, seconds = [], []
                    for k in range(repeats):
                        seed = 1 + k
                        if renderer == "mitsuba":
                            img, s = render_mitsuba(scene, spp, seed)
                        else:
                            img, s = render_pt(a, spp, seed, tmp, renderer == "pt adaptive", renderer == "pt guided")
                        errors.append(relative_mse(img, ref))
                        seconds.append(s)
                    rows.append({"renderer": renderer, "spp": spp, "seconds": float(np.median(seconds)),
                                 "rel_mse": float(np.mean(errors))})
                    print(f"race {name}: {renderer:8s} {spp:5d} spp  {rows[-1]['seconds']:8.3f} s  "
                          f"relative MSE {rows[-1]['rel_mse']:.4g}", file=sys.stderr)
                spp *= 2

        with open(csv_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["renderer", "spp", "seconds", "rel_mse"])
            w.writeheader()
            w.writerows(rows)
    plot(rows, f"{name} ({a.res})", csv_path[:-4] + ".png")

    top = a.max_spp if a.max_spp & (a.max_spp - 1) == 0 else 1 << (a.max_spp.bit_length() - 1)
    t_pt = next(r["seconds"] for r in rows if r["renderer"] == "pt" and r["spp"] == top)
    t_mi = next(r["seconds"] for r in rows if r["renderer"] == "mitsuba" and r["spp"] == top)
    # Error x time, averaged from 8 spp on: the equal-time error of each renderer, up to a constant.
    def work(n):
        return float(np.mean([r["rel_mse"] * r["seconds"] for r in rows if r["renderer"] == n and r["spp"] >= 8]))
    w_pt, w_mi = work("pt"), work("mitsuba")
    # Error at equal sample counts: what the samples themselves are worth.
    err = {(r["renderer"], r["spp"]): r["rel_mse"] for r in rows}
    per_sample = np.mean([err[("mitsuba", n)] / err[("pt", n)] for (who, n) in err if who == "pt" and n >= 16])
    print(f"{name}: at {top} spp pt {t_pt:.3f} s, Mitsuba {t_mi:.3f} s: pt {t_mi / t_pt:.2f}x faster per sample; "
          f"at equal spp (16 on) Mitsuba's error is {per_sample:.2f}x pt's; "
          f"error x seconds pt {w_pt:.4g}, Mitsuba {w_mi:.4g}: at equal time Mitsuba's error is {w_mi / w_pt:.2f}x pt's"
          f"  ({csv_path})")
    if any(r["renderer"] == "pt adaptive" for r in rows):
        w_ad = work("pt adaptive")
        print(f"{name}: pt adaptive: error x seconds {w_ad:.4g}: at equal time Mitsuba's error is {w_mi / w_ad:.2f}x, "
              f"uniform pt's {w_pt / w_ad:.2f}x adaptive pt's")
    if any(r["renderer"] == "pt guided" for r in rows):
        w_g = work("pt guided")
        print(f"{name}: pt guided: error x seconds {w_g:.4g}: at equal time Mitsuba's error is {w_mi / w_g:.2f}x, "
              f"unguided pt's {w_pt / w_g:.2f}x guided pt's")


if __name__ == "__main__":
    main()
