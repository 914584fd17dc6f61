#!/usr/bin/python3
"""The denoiser against plain rendering (issue 36): error against time, denoised and raw.

For each scene, at --res: two independent references (--ref-spp each, seeds 1001 and 1002, kept
in --out and reused while their settings match); renders at each of --spps with the albedo and
normal layers (seed 1); each denoised by `pt denoise` in every quality mode, with and without
prefiltering the features. For each image:
  - displayed-image error: mean squared difference of clamped sRGB values against the mean of
    the two references, less the references' own share (a quarter of their mutual difference,
    the standard correction for a noisy reference; both figures are in the CSV);
  - the image's mean over the pixels that are not emitters (those a --max-depth 0 render leaves
    black) relative to the references';
  - HDR-FLIP against the reference (pt diff's metric, on the RGB as displayed by each).
Times are pt's own: pt:renderSeconds and pt:denoiseSeconds from the files (no start-up).

    bench/tools/denoise_bench.py [--res 512] [--ref-spp 512] [--spps 1,2,4,8,16,32,64]
        [--scenes cornellbottle2,cornell,glass,textured,outdoor_env] [--pt build/pt]
        [--out bench/results/denoise] [--csv bench/charts/denoise.csv] [--chart bench/charts/denoise.png]
Run it on a quiet machine: the times are wall-clock. Needs tools/install-oidn.
"""
import argparse
import csv
import json
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAB = os.path.join(ROOT, "..", "shared", "scenes", "lab")
SCENES = {
    "cornellbottle2": [os.path.join(LAB, "cornellbottle2.obj")],
    "cornell": [os.path.join(LAB, "cornell.obj")],
    "glass": [os.path.join(ROOT, "scenes", "glass.obj")],
    "textured": [os.path.join(ROOT, "scenes", "textured.obj")],
    "outdoor_env": [os.path.join(ROOT, "scenes", "outdoor.obj"), "--env", os.path.join(ROOT, "scenes", "env_sun.exr")],
}
VARIANTS = [(q, p) for p in ("on", "off") for q in ("high", "balanced", "fast")]


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 1) or (r.returncode == 1 and cmd[1] != "diff"):
        sys.exit("failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))
    return r


def read(path, layer=None):
    inp = oiio.ImageInput.open(path)
    spec = inp.spec()
    names = list(spec.channelnames)
    px = inp.read_image(0, 0, 0, spec.nchannels, "float")
    inp.close()
    want = ["R", "G", "B"] if layer is None else [layer + "." + c for c in ("R", "G", "B")]
    img = np.stack([px[:, :, names.index(c)] for c in want], axis=-1)
    meta = {a.name: a.value for a in spec.extra_attribs}
    return img, meta


def write_rgb(path, rgb):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, "float"))
    out.write_image(np.ascontiguousarray(rgb, dtype=np.float32))
    out.close()


def displayed(x):
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def mse(a, b):
    return float(np.mean((displayed(a) - displayed(b)) ** 2))


def render(pt, scene, spp, seed, res, out, extra=()):
    if os.path.exists(out):
        _, meta = read(out)
        if meta.get("pt:sppRequested") == spp and meta.get("pt:seed") == seed and meta.get("pt:fullWidth") == res:
            return
    run([pt, "render", *scene, "-spp", str(spp), "--seed", str(seed), "--res", "%dx%d" % (res, res), "-q", *extra, "-o", out])


def flip(pt, rgb, ref_path, tmp):
    write_rgb(tmp, rgb)
    r = run([pt, "diff", tmp, ref_path, "-q", "--json", tmp + ".json"])
    return json.load(open(tmp + ".json"))["flip_mean"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--res", type=int, default=512)
    ap.add_argument("--ref-spp", type=int, default=512)
    ap.add_argument("--spps", default="1,2,4,8,16,32,64")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--pt", default=os.path.join(ROOT, "build", "pt"))
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "denoise"))
    ap.add_argument("--csv", default=os.path.join(ROOT, "bench", "charts", "denoise.csv"))
    ap.add_argument("--chart", default=os.path.join(ROOT, "bench", "charts", "denoise.png"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    spps = [int(s) for s in a.spps.split(",")]
    rows = []
    for name in a.scenes.split(","):
        scene = SCENES[name]
        if not os.path.exists(scene[0]):
            print("skipping %s: %s is missing" % (name, scene[0]))
            continue
        d = lambda f: os.path.join(a.out, "%s_%s" % (name, f))
        refs = []
        for seed in (1001, 1002):
            render(a.pt, scene, a.ref_spp, seed, a.res, d("ref%d.exr" % seed))
            refs.append(read(d("ref%d.exr" % seed))[0])
        ref = 0.5 * (refs[0] + refs[1])
        write_rgb(d("ref.exr"), ref)
        ref_noise = mse(refs[0], refs[1]) / 4.0  # the mean reference's own squared error, expected
        render(a.pt, scene, 4, 1, a.res, d("emitters.exr"), ["--max-depth", "0"])
        surface = np.max(read(d("emitters.exr"))[0], axis=-1) <= 0.0
        ref_mean = float(np.mean(ref[surface]))

        def measure(rgb, spp, method, render_s, denoise_s):
            e = mse(rgb, ref)
            row = dict(scene=name, spp=spp, method=method, render_s=round(render_s, 4), denoise_s=round(denoise_s, 4),
                       total_s=round(render_s + denoise_s, 4), mse_display=e, mse_display_corrected=max(e - ref_noise, 0.0),
                       reference_noise=ref_noise, mean_rel=float(np.mean(rgb[surface])) / ref_mean - 1.0,
                       flip=flip(a.pt, rgb, d("ref.exr"), d("flip_tmp.exr")))
            rows.append(row)
            print("%-15s %3d spp %-18s render %6.2f s denoise %5.2f s  mse %.3g (corr %.3g)  mean %+.2f%%  flip %.4f" % (
                name, spp, method, render_s, denoise_s, row["mse_display"], row["mse_display_corrected"],
                100 * row["mean_rel"], row["flip"]), flush=True)

        for spp in spps:
            raw_path = d("%dspp.exr" % spp)
            run([a.pt, "render", *scene, "-spp", str(spp), "--seed", "1", "--res", "%dx%d" % (a.res, a.res), "-q",
                 "--aov", "albedo,normal", "-o", raw_path])
            raw, meta = read(raw_path)
            measure(raw, spp, "raw", float(meta["pt:renderSeconds"]), 0.0)
            for q, p in VARIANTS:
                out = d("%dspp_%s_%s.exr" % (spp, q, p))
                run([a.pt, "denoise", raw_path, "--quality", q, "--prefilter", p, "-q", "-o", out])
                den, dmeta = read(out)
                measure(den, spp, "denoise_%s_prefilter_%s" % (q, p), float(meta["pt:renderSeconds"]),
                        float(dmeta["pt:denoiseSeconds"]))
    if not rows:
        sys.exit("no scene rendered")
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    summary(rows, spps)
    chart(rows, a.chart)


def summary(rows, spps):
    print("\n4-spp denoised against plain 64 spp, displayed-image error (corrected for the reference's noise):")
    for scene in dict.fromkeys(r["scene"] for r in rows):
        pick = lambda m, s: next((r for r in rows if r["scene"] == scene and r["method"] == m and r["spp"] == s), None)
        plain = pick("raw", max(spps))
        if plain is None or 4 not in spps:
            continue
        parts = []
        for q, p in VARIANTS:
            r = pick("denoise_%s_prefilter_%s" % (q, p), 4)
            parts.append("%s/%s %.3f (%.2f s)" % (q, p, r["mse_display_corrected"] / max(plain["mse_display_corrected"], 1e-12), r["denoise_s"]))
        print("  %-15s " % scene + ", ".join(parts))


def chart(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 3.8), squeeze=False)
    styles = {"raw": ("k", "-", "raw (plain render)"),
              "denoise_high_prefilter_on": ("tab:blue", "-", "denoised: high, prefiltered"),
              "denoise_balanced_prefilter_on": ("tab:green", "--", "denoised: balanced, prefiltered"),
              "denoise_fast_prefilter_off": ("tab:orange", ":", "denoised: fast, features as rendered")}
    for ax, scene in zip(axes[0], scenes):
        for method, (color, ls, label) in styles.items():
            pts = sorted((r["total_s"], r["mse_display_corrected"], r["spp"]) for r in rows
                         if r["scene"] == scene and r["method"] == method)
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [max(p[1], 1e-7) for p in pts], color=color, ls=ls, marker="o", ms=3, label=label)
            if method == "raw":
                for t, e, s in pts:
                    ax.annotate(str(s), (t, max(e, 1e-7)), fontsize=6, xytext=(2, 2), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(scene)
        ax.set_xlabel("seconds (render + denoise, 2 threads)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("displayed-image MSE (clamped sRGB)")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("chart:", path)


if __name__ == "__main__":
    main()
