#!/usr/bin/env python3
"""Renders a glTF file with Blender's Cycles at one sample count and several seeds, raw or
denoised by Cycles itself, for denoise_race.py (issue 49). Run with the bpy venv's python.

The scene is cycles_gltf.py's (Blender's importer, pt's camera, pt's environment map, Cycles'
biasing shortcuts off, a box filter of one pixel). With --denoise, Cycles' own denoiser runs as
Blender sets it up for final renders: OpenImageDenoise (the one in the bpy wheel, 2.3.3), prefilter
Accurate, quality High, input passes albedo and normal; the denoising data passes are kept.

Each seed's render goes to DIR/seedS.exr, a multilayer EXR: ViewLayer.Combined (the denoised image
with --denoise, else the raw one) and, with --denoise, ViewLayer.Noisy Image, ViewLayer.Denoising
Albedo, ViewLayer.Denoising Normal (camera space, Cycles' convention) and ViewLayer.Denoising Depth.
Cycles' own times (render_time, which includes the denoiser, and synchronization_time) are in
each file's metadata, cycles.ViewLayer.*; DIR/times.json has them per seed with the wall-clock
time of the whole call.

    cycles_denoise.py FILE --out-dir DIR --env MAP [--res WxH] [--spp N] [--seeds 1,2,3]
                      [--denoise] [--threads T] [--pattern TABULATED_SOBOL|AUTOMATIC|BLUE_NOISE]
"""
import argparse
import json
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_gltf  # noqa: E402


def seconds(text):
    """Blender's "MM:SS.ss" or "HH:MM:SS.ss" as seconds."""
    total = 0.0
    for part in text.split(":"):
        total = total * 60 + float(part)
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--env", required=True)
    ap.add_argument("--res", default="256x256")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--denoise", action="store_true")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--pattern", default="TABULATED_SOBOL",
                    help="Cycles' sampling pattern; the crosscheck's scene gets TABULATED_SOBOL (Classic) "
                         "[TABULATED_SOBOL]; AUTOMATIC is the blue-noise pattern of a new file")
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    scene = cycles_gltf.build(a.file, width, height, "0", 16, (a.env, 0.0, 1.0))
    c = scene.cycles
    c.sampling_pattern = a.pattern
    c.samples = a.spp
    c.use_denoising = a.denoise
    if a.denoise:  # Blender's defaults for a final render, said out loud
        c.denoiser = "OPENIMAGEDENOISE"
        c.denoising_prefilter = "ACCURATE"
        c.denoising_quality = "HIGH"
        c.denoising_input_passes = "RGB_ALBEDO_NORMAL"
        c.denoising_use_gpu = False
        scene.view_layers[0].cycles.denoising_store_passes = True
    scene.render.threads_mode = "FIXED"
    scene.render.threads = a.threads
    settings = scene.render.image_settings
    settings.media_type = "MULTI_LAYER_IMAGE"
    settings.color_depth = "32"
    os.makedirs(a.out_dir, exist_ok=True)
    times = {}
    for seed in (int(s) for s in a.seeds.split(",")):
        c.seed = seed
        path = os.path.join(a.out_dir, f"seed{seed}.exr")
        scene.render.filepath = path
        stats = []
        handler = lambda text, *rest: stats.append(text)  # noqa: E731
        bpy.app.handlers.render_stats.append(handler)
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        wall = time.perf_counter() - start
        bpy.app.handlers.render_stats.remove(handler)
        times[seed] = {"wall": wall, "stats": stats[-1] if stats else ""}
        print(f"cycles_denoise: seed {seed}: {wall:.2f} s", file=sys.stderr)
    with open(os.path.join(a.out_dir, "times.json"), "w") as f:
        json.dump({"spp": a.spp, "denoise": a.denoise, "pattern": a.pattern, "threads": a.threads,
                   "seeds": times}, f, indent=1)


if __name__ == "__main__":
    main()
