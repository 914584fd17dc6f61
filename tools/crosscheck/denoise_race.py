#!/usr/bin/python3
"""Denoised pt against denoised Cycles at a low sample count (issue 49, item 12).

    denoise_race.py FILE --env MAP [--res 256x256] [--spp 16] [--seeds 32] [--reference-spp 2048]
                    [--variants LIST] [--pt-variant NAME=SETTINGS]... [--orientations 1|2|4|8]
                    [--name NAME] [--reuse]

A glTF asset under an environment map is rendered by pt (`pt render FILE --env MAP --res WxH -spp
N --seed S --denoise --aov albedo,normal,depth`, its raw estimate kept as the layer noisy) and by
Blender 5.0.1's Cycles (cycles_denoise.py: cycles_gltf.py's scene, Cycles' own denoiser as
Blender sets it up for final renders: OIDN 2.3.3, prefilter Accurate, quality High, albedo and
normal), at N spp with seeds 1..K, 2 threads each. Each renderer is held against its OWN
reference, the mean of two renders of reference-spp/2 samples (seeds 900001 and 900002),
rendered once and cached in build-crosscheck/denoise_race/NAME_RES/: this measures what the
denoiser makes of each renderer's samples, not whether the renderers agree (tools/crosscheck/run
checks that).

The filter is not the same function of an image turned over: Cycles hands OIDN its render buffer
bottom row first, pt top row first, and the same noisy image and features give different errors
the two ways round (DamagedHelmet: Cycles' own 0.0075 against 0.0109 top row first, with the
same call, bit for bit the same library). So beside each renderer's own denoised image the
variants refilter the noisy images with `pt denoise` (the call Cycles makes: prefiltered albedo
and normal, cleanAux, quality high, HDR) in named orientations, each renderer's noisy image with
its own or the other's features:
  pt                    pt render --denoise (OIDN 2.5.1 in .deps/, top row first); "raw" is its
                        noisy layer
  cycles                Cycles denoised (bottom row first); "raw" is its Noisy Image
  pt@bottom-up          pt's noisy image and features, filtered bottom row first (as Cycles does)
  cycles@top-down       Cycles' noisy image and features, filtered top row first (as pt does)
  pt+cycles-features    pt's noisy image with the same seed's Cycles albedo and normal (camera
                        space, Cycles' convention), top row first
  cycles+pt-features    Cycles' noisy image with the same seed's pt albedo and normal, top row first
  pt-oidn2.3.3          pt's own, filtered by the bpy wheel's libOpenImageDenoise (2.3.3) through
                        PT_OIDN_LIBRARY (the filter's version)
  cycles-bluenoise      Cycles with its blue-noise pattern (AUTOMATIC, a new file's default; the
                        crosscheck's scene gets Classic, TABULATED_SOBOL)
  pt@DN, cycles@DN, pt+cycles-features@DN, cycles+pt-features@DN
                        with --orientations N > 1: the same, each error the mean over N
                        orientations of the image (identity, vertical flip, horizontal flip, both;
                        with 8 also the four transposes), the orientation's luck taken out
and any --pt-variant NAME=SETTINGS: pt render --denoise with SETTINGS, space-separated words,
each VAR=VALUE an environment variable for pt (an experiment's switch) and the others extra
options (--sampler random), or PT=PATH another pt binary; held against pt's reference.

Errors, each the mean over the K seeds (and orientations):
- relative MSE: mean over pixels and channels of (x - r)^2 / (r^2 + 0.01), as race.py, with its
  standard error over seeds and the median over seeds (a single firefly left by the filter next to
  a highlight can be a third of an image's error: the mean is heavy-tailed);
- "ref": what the reference's own noise adds to it, from its two halves h1, h2:
  mean((h1 - h2)^2 / 4 / (r^2 + 0.01)); "corr" is the error less it, and the ratios to Cycles
  are of "corr", against the Cycles row filtered the same way round (pt and pt+cycles-features
  against cycles@top-down, pt@bottom-up against cycles, @DN against cycles@DN);
- near highlights: the share of the relative MSE in the pixels within 2 pixels of one whose
  reference is brighter than 1 (either renderer's), where denoisers spread or lose light;
- background: relative MSE over the pixels where pt's camera rays all miss (seed 1's depth);
- displayed-image MSE: mean squared difference of clamped sRGB values, as denoise_against.py;
- mean: the image's mean relative to the reference's.

Times: pt's are the render and denoise seconds of its summary line; Cycles' its render_time (path
tracing and the denoiser, without synchronisation: the scene's export and BVH build), from each
file's metadata. Both on --threads threads; the machine's other load shows in them.

Run it with tools/crosscheck/denoise_race, which installs bpy into build-crosscheck/bpy-venv as
tools/crosscheck/run does. Writes build-crosscheck/denoise_race/NAME_RES/summary.json too.
"""
import argparse
import glob
import json
import os
import re
import shlex
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BPY_PYTHON = os.path.join(ROOT, "build-crosscheck", "bpy-venv", "bin", "python")
REF_SEEDS = (900001, 900002)
DEFAULT_VARIANTS = ["pt", "cycles", "pt@bottom-up", "cycles@top-down", "pt+cycles-features", "cycles+pt-features",
                    "pt-oidn2.3.3", "cycles-bluenoise"]
# Orientations of an image as (flip rows, flip columns, transpose): the dihedral group's 8.
ORIENTATIONS = [(False, False, False), (True, False, False), (False, True, False), (True, True, False),
                (False, False, True), (True, False, True), (False, True, True), (True, True, True)]


# ---------------------------------------------------------------- images
def read_layers(path):
    """Every channel of an EXR (all subimages of a multilayer one) by name, as float64 planes,
    Cycles' 'ViewLayer.' prefix dropped, and the metadata."""
    inp = oiio.ImageInput.open(path)
    if inp is None:
        sys.exit(f"denoise_race: cannot read {path}: {oiio.geterror()}")
    planes, meta = {}, {}
    sub = 0
    while inp.seek_subimage(sub, 0):
        spec = inp.spec()
        px = inp.read_image(sub, 0, 0, spec.nchannels, "float")
        for i, name in enumerate(spec.channelnames):
            planes[name.removeprefix("ViewLayer.")] = px[:, :, i].astype(np.float64)
        for attr in spec.extra_attribs:
            meta[attr.name] = attr.value
        sub += 1
    inp.close()
    return planes, meta


def rgb(planes, prefix, names="RGB"):
    return np.stack([planes[prefix + c] for c in names], axis=-1)


def write_for_denoise(path, color, albedo, normal):
    """An EXR `pt denoise` reads: R, G, B and the albedo.R/G/B, normal.X/Y/Z layers."""
    px = np.ascontiguousarray(np.concatenate([color, albedo, normal], axis=2), dtype=np.float32)
    spec = oiio.ImageSpec(px.shape[1], px.shape[0], 9, oiio.FLOAT)
    spec.channelnames = ("R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z")
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, spec) or not out.write_image(px):
        sys.exit(f"denoise_race: cannot write {path}")
    out.close()


def turn(img, o, back=False):
    """The image in orientation o (rows flipped, columns flipped, transposed), or back from it."""
    flip_rows, flip_cols, transpose = o
    if back and transpose:
        img = img.transpose(1, 0, 2)
    if flip_rows:
        img = img[::-1]
    if flip_cols:
        img = img[:, ::-1]
    if not back and transpose:
        img = img.transpose(1, 0, 2)
    return img


def displayed(x):
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def relative_mse_map(x, ref):
    return ((x - ref) ** 2 / (ref * ref + 0.01)).mean(axis=2)


def dilate(mask, r):
    out = mask.copy()
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            out |= np.roll(np.roll(mask, dy, 0), dx, 1)
    return out


# ---------------------------------------------------------------- renders
def run(cmd, env=None):
    done = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, **(env or {})))
    if done.returncode != 0:
        sys.exit(f"denoise_race: {shlex.join(cmd)} failed ({done.returncode}):\n{done.stdout}{done.stderr}")
    return done.stdout


def pt_render(a, out, spp, seed, settings, denoise=True):
    """One pt render; returns (render seconds, denoise seconds)."""
    cmd = [settings.get("pt", a.pt), "render", a.file, "--env", a.env, "--res", a.res, "-spp", str(spp),
           "--seed", str(seed), "--threads", str(a.threads), "-q", "-o", out] + settings.get("args", [])
    cmd += ["--denoise", "--aov", "albedo,normal,depth"] if denoise else []
    text = run(cmd, settings.get("env", {}))
    render = float(re.search(r"([0-9.]+) s render", text).group(1))
    m = re.search(r"denoised in ([0-9.]+) s", text)
    return render, float(m.group(1)) if m else 0.0


def pt_denoise(a, src, out, library=None):
    text = run([a.pt, "denoise", src, "--threads", str(a.threads), "-q", "-o", out],
               {"PT_OIDN_LIBRARY": library} if library else {})
    m = re.search(r", ([0-9.]+) s, ", text)
    return float(m.group(1)) if m else 0.0


def cycles_render(a, out_dir, spp, seeds, denoise, pattern="TABULATED_SOBOL"):
    run([a.bpy_python, os.path.join(HERE, "cycles_denoise.py"), a.file, "--out-dir", out_dir, "--env", a.env,
         "--res", a.res, "--spp", str(spp), "--seeds", ",".join(map(str, seeds)), "--threads", str(a.threads),
         "--pattern", pattern] + (["--denoise"] if denoise else []))


def cycles_seconds(meta):
    total = 0.0
    for part in str(meta.get("cycles.ViewLayer.render_time", "0")).split(":"):
        total = total * 60 + float(part)
    return total


def reference(a, cache, who):
    """The mean of two renders of reference-spp/2 (seeds REF_SEEDS), and per pixel what its own
    noise adds to the relative MSE, (h1 - h2)^2 / 4 / (r^2 + 0.01), and to the displayed MSE."""
    half = a.reference_spp // 2
    d = os.path.join(cache, f"{who}-ref{a.reference_spp}")
    os.makedirs(d, exist_ok=True)
    halves = []
    for seed in REF_SEEDS:
        path = os.path.join(d, f"seed{seed}.exr")
        if not os.path.exists(path):
            print(f"denoise_race: {who} reference, seed {seed}, {half} spp", file=sys.stderr)
            if who == "cycles":
                cycles_render(a, d, half, [seed], False)
            else:
                tmp = path + ".tmp.exr"
                pt_render(a, tmp, half, seed, {}, denoise=False)
                os.replace(tmp, path)
        planes, _ = read_layers(path)
        halves.append(rgb(planes, "Combined." if "Combined.R" in planes else ""))
    r = (halves[0] + halves[1]) / 2
    noise = ((halves[0] - halves[1]) ** 2 / 4 / (r * r + 0.01)).mean(axis=2)
    shown = ((displayed(halves[0]) - displayed(halves[1])) ** 2 / 4).mean(axis=2)
    return r, noise, shown


def parse_pt_variant(text):
    name, _, words = text.partition("=")
    settings = {"env": {}, "args": []}
    for w in shlex.split(words):
        key, eq, value = w.partition("=")
        if eq and key == "PT":
            settings["pt"] = value
        elif eq and re.fullmatch(r"[A-Z_][A-Z0-9_]*", key):
            settings["env"][key] = value
        else:
            settings["args"].append(w)
    return name, settings


def stats(values):
    v = np.asarray(values, dtype=float)
    return float(v.mean()), float(v.std(ddof=1) / np.sqrt(len(v))) if len(v) > 1 else 0.0


# ---------------------------------------------------------------- the race
def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--env", required=True)
    ap.add_argument("--res", default="256x256")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--seeds", type=int, default=32, help="seeds 1..K of each variant [32]")
    ap.add_argument("--reference-spp", type=int, default=2048)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--variants", default=",".join(DEFAULT_VARIANTS))
    ap.add_argument("--pt-variant", action="append", default=[], metavar="NAME=SETTINGS")
    ap.add_argument("--orientations", type=int, default=4, choices=(1, 2, 4, 8),
                    help="also refilter each renderer's noisy image, with either's features, in this many "
                         "orientations and average the errors [4]")
    ap.add_argument("--name", help="the cache's name [the file's]")
    ap.add_argument("--pt", default=os.path.join(ROOT, "build", "pt"))
    ap.add_argument("--bpy-python", default=BPY_PYTHON)
    ap.add_argument("--reuse", action="store_true", help="reuse the low-spp renders a previous run left in the cache")
    a = ap.parse_args()
    a.file, a.env = os.path.abspath(a.file), os.path.abspath(a.env)
    name = a.name or os.path.splitext(os.path.basename(a.file))[0]
    cache = os.path.join(ROOT, "build-crosscheck", "denoise_race", f"{name}_{a.res}")
    runs = os.path.join(cache, f"runs{a.spp}")
    os.makedirs(runs, exist_ok=True)
    seeds = list(range(1, a.seeds + 1))
    variants = [v for v in a.variants.split(",") if v]
    pt_variants = dict(parse_pt_variant(t) for t in a.pt_variant)
    variants += [v for v in pt_variants if v not in variants]
    if a.orientations > 1:
        variants += [f"{v}@D{a.orientations}" for v in ("pt", "cycles", "pt+cycles-features", "cycles+pt-features")]
    # The bpy wheel's own OIDN (2.3.3 in bpy 5.0.1), which `pt denoise` loads through PT_OIDN_LIBRARY.
    wheel_oidn = (glob.glob(os.path.join(os.path.dirname(os.path.dirname(a.bpy_python)), "lib", "python3*",
                                         "site-packages", "bpy", "lib", "libOpenImageDenoise.so.2")) or [None])[0]

    refs = {"pt": reference(a, cache, "pt"), "cycles": reference(a, cache, "cycles")}
    bright = dilate((refs["pt"][0].max(axis=2) > 1) | (refs["cycles"][0].max(axis=2) > 1), 2)

    def have(path):
        return a.reuse and os.path.exists(path)

    # The renders the variants are made of: Cycles' (own denoiser, its passes kept), pt's.
    cy_dir, bn_dir = os.path.join(runs, "cycles"), os.path.join(runs, "cycles-bluenoise")
    if not all(have(os.path.join(cy_dir, f"seed{s}.exr")) for s in seeds):
        print(f"denoise_race: Cycles, {a.spp} spp, seeds {seeds[0]}..{seeds[-1]}", file=sys.stderr)
        cycles_render(a, cy_dir, a.spp, seeds, True)
    if "cycles-bluenoise" in variants and not all(have(os.path.join(bn_dir, f"seed{s}.exr")) for s in seeds):
        print(f"denoise_race: Cycles, blue-noise pattern, {a.spp} spp", file=sys.stderr)
        cycles_render(a, bn_dir, a.spp, seeds, True, "AUTOMATIC")
    timing = {}
    for v, s in [("pt", {})] + list(pt_variants.items()):
        d = os.path.join(runs, v.replace("/", "_"))
        os.makedirs(d, exist_ok=True)
        for seed in seeds:
            out = os.path.join(d, f"seed{seed}.exr")
            if have(out) and os.path.exists(out + ".json"):
                with open(out + ".json") as f:
                    timing[(v, seed)] = tuple(json.load(f))
                continue
            timing[(v, seed)] = pt_render(a, out, a.spp, seed, s)
            with open(out + ".json", "w") as f:
                json.dump(timing[(v, seed)], f)
        print(f"denoise_race: pt {v} rendered", file=sys.stderr)
    first, _ = read_layers(os.path.join(runs, "pt", "seed1.exr"))
    background = ~np.isfinite(first["depth.Z"])

    def inputs(who, seed):
        """(noisy, albedo, normal) of one renderer's render of a seed."""
        if who == "cycles":
            p, _ = read_layers(os.path.join(cy_dir, f"seed{seed}.exr"))
            return rgb(p, "Noisy Image."), rgb(p, "Denoising Albedo."), rgb(p, "Denoising Normal.", "XYZ")
        p, _ = read_layers(os.path.join(runs, "pt", f"seed{seed}.exr"))
        return rgb(p, "noisy."), rgb(p, "albedo."), rgb(p, "normal.", "XYZ")

    def refilter(tag, noisy, albedo, normal, orientations, library=None):
        """`pt denoise` of the images in each orientation, each turned back; and the seconds."""
        outs, secs = [], 0.0
        for k, o in enumerate(orientations):
            src, out = os.path.join(runs, f"in-{tag}-{k}.exr"), os.path.join(runs, f"out-{tag}-{k}.exr")
            write_for_denoise(src, *(turn(x, o) for x in (noisy, albedo, normal)))
            secs += pt_denoise(a, src, out, library)
            outs.append(turn(rgb(read_layers(out)[0], ""), o, back=True))
        return outs, secs / len(orientations)

    rows = []
    for v in variants:
        base_v, _, orient = v.partition("@")
        side = "cycles" if base_v.startswith("cycles") else "pt"
        ref, ref_noise, ref_shown = refs[side]
        acc = {k: [] for k in ("raw", "den", "raw_shown", "den_shown", "mean", "sec", "dsec", "bg", "bright")}
        for seed in seeds:
            if v == "cycles" or v == "cycles-bluenoise":
                p, meta = read_layers(os.path.join(cy_dir if v == "cycles" else bn_dir, f"seed{seed}.exr"))
                raw, dens = rgb(p, "Noisy Image."), [rgb(p, "Combined.")]
                sec, dsec = cycles_seconds(meta), 0.0
            elif v == "pt" or v in pt_variants:
                p, _ = read_layers(os.path.join(runs, v.replace("/", "_"), f"seed{seed}.exr"))
                raw, dens = rgb(p, "noisy."), [rgb(p, "")]
                sec, dsec = timing[(v, seed)]
            else:
                noise_from = "cycles" if base_v.startswith("cycles") else "pt"
                raw, albedo, normal = inputs(noise_from, seed)
                if base_v.endswith("-features"):
                    _, albedo, normal = inputs("pt" if noise_from == "cycles" else "cycles", seed)
                if orient.startswith("D"):
                    orientations = ORIENTATIONS[:a.orientations]
                else:
                    orientations = [ORIENTATIONS[1] if orient == "bottom-up" else ORIENTATIONS[0]]
                dens, dsec = refilter(v.replace("/", "_").replace("@", "-"), raw, albedo, normal, orientations,
                                      wheel_oidn if v == "pt-oidn2.3.3" else None)
                sec = 0.0
            acc["raw"].append(float(relative_mse_map(raw, ref).mean()))
            acc["raw_shown"].append(float(((displayed(raw) - displayed(ref)) ** 2).mean()))
            maps = [relative_mse_map(d, ref) for d in dens]
            acc["den"].append(float(np.mean([m.mean() for m in maps])))
            acc["bg"].append(float(np.mean([m[background].mean() for m in maps])) if background.any() else 0.0)
            acc["bright"].append(float(np.mean([m[bright].sum() / m.sum() for m in maps])))
            acc["den_shown"].append(float(np.mean([((displayed(d) - displayed(ref)) ** 2).mean() for d in dens])))
            acc["mean"].append(float(np.mean([d.mean() / ref.mean() - 1 for d in dens])))
            acc["sec"].append(sec)
            acc["dsec"].append(dsec)
        own_cycles = v in ("cycles", "cycles-bluenoise")  # Cycles' own denoiser: its buffer bottom row first
        row = {"variant": v, "orientation": orient or ("bottom-up" if own_cycles else "top-down"),
               "seeds": len(seeds), "ref_noise": float(ref_noise.mean()), "ref_noise_shown": float(ref_shown.mean()),
               "den_median": float(np.median(acc["den"])), "den_per_seed": acc["den"]}
        for k in acc:
            row[k], row[k + "_se"] = stats(acc[k])
        row["den_corr"] = row["den"] - row["ref_noise"]
        row["bg_corr"] = row["bg"] - float(ref_noise[background].mean()) if background.any() else 0.0
        rows.append(row)
        print(f"denoise_race: {v} measured", file=sys.stderr)

    by = {r["variant"]: r for r in rows}

    def baseline(r):
        o = r["orientation"]
        return by.get(f"cycles@{o}") if o.startswith("D") else by.get("cycles" if o == "bottom-up" else "cycles@top-down")

    print(f"{name} {a.res}, {a.spp} spp, seeds 1..{len(seeds)}, each against its own {a.reference_spp}-spp reference "
          f"(background {100 * background.mean():.1f} %, near highlights {100 * bright.mean():.1f} % of the pixels); "
          f"reference noise in relMSE: pt {refs['pt'][1].mean():.3g}, Cycles {refs['cycles'][1].mean():.3g}")
    print(f"{'variant':28s} {'orient':9s} {'raw':>8s} {'denoised':>9s} {'± se':>8s} {'median':>8s} {'corr':>8s} "
          f"{'ratio':>6s} {'± se':>5s} {'hilite':>6s} {'bg corr':>8s} {'shown raw':>9s} {'shown den':>9s} "
          f"{'mean':>7s} {'render s':>8s} {'denoise s':>9s}")
    for r in rows:
        b = baseline(r)
        ratio = ratio_se = float("nan")
        if b:
            ratio = r["den_corr"] / b["den_corr"]
            ratio_se = 0.0 if b is r else ratio * np.hypot(r["den_se"] / r["den_corr"], b["den_se"] / b["den_corr"])
        r["ratio"], r["ratio_se"] = ratio, ratio_se
        print(f"{r['variant']:28s} {r['orientation']:9s} {r['raw']:8.4f} {r['den']:9.5f} {r['den_se']:8.5f} "
              f"{r['den_median']:8.5f} {r['den_corr']:8.5f} {ratio:6.3f} {ratio_se:5.3f} {100 * r['bright']:5.1f}% "
              f"{r['bg_corr']:8.2e} {r['raw_shown']:9.3e} {r['den_shown']:9.3e} {100 * r['mean']:+6.2f}% "
              f"{r['sec']:8.3f} {r['dsec']:9.3f}")
    with open(os.path.join(cache, "summary.json"), "w") as f:
        json.dump({"file": a.file, "env": a.env, "res": a.res, "spp": a.spp, "seeds": seeds,
                   "reference_spp": a.reference_spp, "orientations": a.orientations, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
