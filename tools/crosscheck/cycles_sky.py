#!/usr/bin/env python3
"""Renders Blender Cycles' own Preetham sky texture, as an independent check of pt's sky (issue 12).

Cycles' legacy Preetham sky (still in Blender 5.0, marked for removal) evaluates the same paper:
0.06 x the zenith luminance in kcd/m^2 times Perez's distributions, normalised at the zenith, in
Rec.709. It has no sun disk and mirrors the horizon downwards, so only the sky itself is compared:
a pinhole camera at the origin looking up into it, no geometry, the sun out of view. pt's scene is
y-up and Blender's z-up: a direction (x, y, z) of pt is (x, -z, y) in the sky texture.

    cycles_sky.py --out OUT.exr --res WxH --spp N --view-elevation DEG --view-azimuth DEG
                  --sun-elevation DEG --sun-azimuth DEG --turbidity T --fov DEG
"""
import argparse
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_lab import add_camera, new_scene  # noqa: E402
from lab_scene import sun_direction  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--res", default="96x64")
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--fov", type=float, default=50.0)
    ap.add_argument("--view-elevation", type=float, default=25.0)
    ap.add_argument("--view-azimuth", type=float, default=0.0)
    ap.add_argument("--sun-elevation", type=float, default=45.0)
    ap.add_argument("--sun-azimuth", type=float, default=135.0)
    ap.add_argument("--turbidity", type=float, default=3.0)
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))

    scene = new_scene(width, height)
    scene.cycles.samples = a.spp

    world = bpy.data.worlds.new("sky")
    scene.world = world
    world.use_nodes = True
    tree = world.node_tree
    tree.nodes.clear()
    coords = tree.nodes.new("ShaderNodeTexCoord")  # Generated: the ray direction, pt's frame
    xyz = tree.nodes.new("ShaderNodeSeparateXYZ")
    tree.links.new(coords.outputs["Generated"], xyz.inputs[0])
    flip = tree.nodes.new("ShaderNodeMath")
    flip.operation = "MULTIPLY"
    tree.links.new(xyz.outputs["Z"], flip.inputs[0])
    flip.inputs[1].default_value = -1.0
    turned = tree.nodes.new("ShaderNodeCombineXYZ")  # (x, -z, y): the sky texture's z-up frame
    tree.links.new(xyz.outputs["X"], turned.inputs["X"])
    tree.links.new(flip.outputs[0], turned.inputs["Y"])
    tree.links.new(xyz.outputs["Y"], turned.inputs["Z"])
    sky = tree.nodes.new("ShaderNodeTexSky")
    sky.sky_type = "PREETHAM"
    s = sun_direction(a.sun_elevation, a.sun_azimuth)
    sky.sun_direction = (s[0], -s[2], s[1])
    sky.turbidity = a.turbidity
    tree.links.new(turned.outputs[0], sky.inputs["Vector"])
    bg = tree.nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    tree.links.new(sky.outputs["Color"], bg.inputs["Color"])
    out = tree.nodes.new("ShaderNodeOutputWorld")
    tree.links.new(bg.outputs[0], out.inputs["Surface"])

    add_camera(scene, [0, 0, 0], sun_direction(a.view_elevation, a.view_azimuth).tolist(), [0, 1, 0], a.fov)
    scene.render.filepath = a.out
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    main()
