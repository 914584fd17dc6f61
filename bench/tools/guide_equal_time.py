#!/usr/bin/python3
"""Path guiding against plain path tracing at equal time (issue 38).

For each scene, renders `pt render --time T` without and with --guide, several seeds each, the
two alternating so that both see the same machine, and takes the relative MSE of each image
against a high-sample reference (the race's metric, mean (x - ref)^2 / (ref^2 + 0.01)). The
references are rendered once, unguided, and cached in bench/results/guide/. The guided render's
training is inside its time (a quarter of it at most), so the ratio is what a user gets.

    bench/tools/guide_equal_time.py [--scenes cornellbottle2,glass,...] [--time 20,60] [--seeds 3]
        [--res 256x256] [--reference-spp 4096] [--pt build/pt] [--csv bench/charts/guide.csv]
        [--chart bench/charts/guide.png]

Run it on a quiet machine: the budgets are wall-clock. The defaults take about 35 minutes on 2
cores once the references exist (cornellbottle2's takes 11 minutes, the others 3 to 5 each).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAB = os.path.join(ROOT, "..", "shared", "scenes", "lab")
# name: (scene, options); the times each is raced at come from --time, cornellbottle2 takes all
# of them, the others the first.
SCENES = {
    "cornellbottle2": (os.path.join(LAB, "cornellbottle2.obj"), []),
    "cornell_textured": (os.path.join(LAB, "cornell_textured.obj"), []),
    "glass": ("scenes/glass.obj", []),
    "outdoor": ("scenes/outdoor.obj", []),
    "outdoor_env": ("scenes/outdoor.obj", ["--env", "scenes/env_sun.exr"]),
    "lamp_shaft": ("scenes/lamp_shaft.obj", []),
}


def rgb(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit(f"guide_equal_time: cannot read {path}: {buf.geterror()}")
    return buf.get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64), buf.spec()


def attribute(spec, name, default=0.0):
    v = spec.getattribute(name)
    return default if v is None else float(v)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", default="cornellbottle2,cornell_textured,glass,outdoor,outdoor_env,lamp_shaft")
    ap.add_argument("--time", default="20,60")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--res", default="256x256")
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--pt", default=os.path.join(ROOT, "build", "pt"))
    ap.add_argument("--csv", default=os.path.join(ROOT, "bench", "charts", "guide.csv"))
    ap.add_argument("--chart", default=os.path.join(ROOT, "bench", "charts", "guide.png"))
    a = ap.parse_args()
    times = [float(t) for t in a.time.split(",")]
    names = a.scenes.split(",")
    for n in names:
        if n not in SCENES:
            sys.exit(f"guide_equal_time: no scene {n} (known: {', '.join(SCENES)})")
    refs = os.path.join(ROOT, "bench", "results", "guide")
    os.makedirs(refs, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "x.exr")
        for name in names:
            scene, extra = SCENES[name]
            if not os.path.exists(os.path.join(ROOT, scene)):
                print(f"guide_equal_time: skipping {name} ({scene} not found)", file=sys.stderr)
                continue
            common = [a.pt, "render", scene, "--res", a.res, "-q"] + extra
            ref_path = os.path.join(refs, f"ref_{name}_{a.res}.exr")
            if not os.path.exists(ref_path):
                print(f"{name}: rendering the reference ({a.reference_spp} spp)", flush=True)
                subprocess.run(common + ["-spp", str(a.reference_spp), "--seed", "1000", "-o", ref_path], cwd=ROOT,
                               check=True, stdout=subprocess.DEVNULL)
            ref, _ = rgb(ref_path)
            rel = lambda x: float(np.mean((x - ref) ** 2 / (ref * ref + 0.01)))
            for t in times if name == "cornellbottle2" else times[:1]:
                err = {False: [], True: []}
                spp = {False: [], True: []}
                trained = []
                for seed in range(1, a.seeds + 1):
                    for guided in (False, True):  # alternating, so that both see the same machine
                        cmd = common + ["--time", str(t), "-spp", "100000", "--seed", str(seed), "-o", out]
                        subprocess.run(cmd + (["--guide"] if guided else []), cwd=ROOT, check=True,
                                       stdout=subprocess.DEVNULL)
                        img, spec = rgb(out)
                        err[guided].append(rel(img))
                        spp[guided].append(attribute(spec, "pt:spp"))
                        if guided:
                            trained.append(attribute(spec, "pt:guideTrained"))
                plain, guided = float(np.mean(err[False])), float(np.mean(err[True]))
                row = (name, t, plain, guided, guided / plain, float(np.mean(spp[False])), float(np.mean(spp[True])),
                       float(np.mean(trained)))
                rows.append(row)
                print(f"{name:18s} {t:4g} s  relMSE unguided {plain:.5f} guided {guided:.5f}  ratio {guided / plain:.2f}  "
                      f"spp {row[5]:.0f} / {row[6]:.0f} (+{row[7]:.0f} learning)  "
                      f"per seed {' '.join(f'{g / p:.2f}' for p, g in zip(err[False], err[True]))}", flush=True)
    with open(a.csv, "w") as f:
        f.write("scene,seconds,relmse_unguided,relmse_guided,ratio,spp_unguided,spp_guided,spp_learning\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(8, 4))
    labels = [f"{r[0]}\n{r[1]:g} s" for r in rows]
    ax.bar(range(len(rows)), [r[4] for r in rows], color=["tab:green" if r[4] < 1 else "tab:red" for r in rows])
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels(labels, fontsize=7)
    ax.axhline(1.0, color="k", lw=0.8)
    ax.axhline(0.5, color="tab:blue", lw=0.8, ls=":", label="issue 38's goal on cornellbottle2")
    ax.axhline(1.1, color="tab:orange", lw=0.8, ls=":", label="no worse than 1.1x elsewhere")
    ax.set_ylabel("relative MSE, guided / unguided")
    ax.set_title(f"--guide at equal time ({a.res}, {a.seeds} seeds; below 1: guiding pays)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.chart, dpi=100)


if __name__ == "__main__":
    main()
