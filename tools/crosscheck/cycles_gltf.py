#!/usr/bin/env python3
"""Renders a glTF 2.0 file with Blender's Cycles through Blender's own glTF importer (bpy from
PyPI), the independent check of pt's glTF support (issue 13).

Nothing of pt's reading of the file is reused: the importer builds the Principled BSDFs, the
lights (its default unit conversion, 683 lm/W, which pt follows) and the cameras. Set here only
what the file does not say, as pt does:
- A file without lights gets pt's default environment, uniform white of radiance 1; a file with
  lights a black one.
- The camera is the file's when it has one (or --camera NAME); without one, pt's framing: the
  bounds' bounding sphere seen from +z (glTF's; Blender's -y) with a vertical field of view of 45
  degrees.
- The Principled BSDF's multiple-scattering GGX is switched to single-scattering GGX, as in the
  glTF BRDF; the rest of the Principled BSDF is not the glTF BRDF (its dielectric Fresnel and
  layering differ), which is what the check measures first on simple cases.
- KHR_materials_volume: the importer gives Cycles' Volume Absorption the attenuation colour c as
  its colour and 1 / attenuationDistance d as its density, which absorbs (1 - c) / d; the
  extension's coefficient is -ln(c) / d (c is what is left after d). Reset here to the
  extension's: density max(-ln c) / d, colour 1 - (-ln c) / (d density), per channel.
Cycles' biasing defaults are off, as in cycles_lab.py; each pass goes to its own EXR.

    cycles_gltf.py FILE --out-dir DIR [--res WxH] [--spp N] [--passes P] [--camera NAME]
"""
import argparse
import math
import os
import sys

import bpy
import mathutils

sys.path.insert(0, os.path.dirname(__file__))
from cycles_lab import look_at, new_scene, render_passes, unbiased_cycles  # noqa: E402
from lab_scene import fail  # noqa: E402


def frame_bounds(scene):
    """pt's camera for a file without one (renderer/scene/scene_loader.cpp, frameScene)."""
    bpy.context.view_layer.update()  # children's world matrices are stale until the scene is evaluated
    lo = mathutils.Vector((math.inf,) * 3)
    hi = mathutils.Vector((-math.inf,) * 3)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for obj in scene.objects:
        if obj.type != "MESH":
            continue
        mesh = obj.evaluated_get(depsgraph).to_mesh()
        for v in mesh.vertices:
            p = obj.matrix_world @ v.co
            lo = mathutils.Vector(map(min, lo, p))
            hi = mathutils.Vector(map(max, hi, p))
    center = (lo + hi) / 2
    print(f"framing: bounds {tuple(lo)} to {tuple(hi)}", file=sys.stderr)
    radius = max((hi - lo).length / 2, 1e-6)
    distance = radius / math.sin(math.radians(22.5))
    data = bpy.data.cameras.new("framing")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(45.0)
    # pt has no near plane; Blender's default of 0.1 would clip away a small model (this one of
    # the Khronos models is 7 mm across).
    data.clip_start = distance * 1e-4
    data.clip_end = distance * 1e4
    obj = bpy.data.objects.new("framing", data)
    scene.collection.objects.link(obj)
    look_at(obj, center + mathutils.Vector((0, -distance, 0)), center, (0, 0, 1))  # glTF +z is Blender -y
    return obj


def to_extension_absorption(node):
    """Cycles absorbs density * (1 - colour) per unit length; make that -ln(c) / d."""
    c = list(node.inputs["Color"].default_value)[:3]
    per_distance = node.inputs["Density"].default_value  # 1 / d as imported
    sigma = [-math.log(max(x, 1e-6)) * per_distance for x in c]
    density = max(sigma)
    node.inputs["Density"].default_value = density
    if density > 0:
        node.inputs["Color"].default_value = [*(1 - s / density for s in sigma), 1.0]
    print(f"volume absorption: colour {c}, 1/d {per_distance} -> sigma {sigma}", file=sys.stderr)


def build(path, width, height, camera_name, max_depth):
    scene = new_scene(width, height)
    unbiased_cycles(scene, max_depth)
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(path))
    scene = bpy.context.scene
    for mat in bpy.data.materials:
        for n in mat.node_tree.nodes if mat.node_tree else []:
            if n.type == "BSDF_PRINCIPLED":
                n.distribution = "GGX"
            if n.type == "VOLUME_ABSORPTION":
                to_extension_absorption(n)
    lights = [o for o in scene.objects if o.type == "LIGHT"]
    world = bpy.data.worlds.new("pt-default")
    if not world.node_tree:
        world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0) if not lights else (0.0, 0.0, 0.0, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    scene.world = world
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if camera_name:
        match = [o for o in cameras if o.name == camera_name or o.data.name == camera_name]
        scene.camera = match[0] if match else fail(f"no camera {camera_name!r}: {[o.name for o in cameras]}")
    elif len(cameras) == 1:
        scene.camera = cameras[0]
    elif not cameras:
        scene.camera = frame_bounds(scene)
    else:
        fail(f"the file has {len(cameras)} cameras; name one with --camera ({[o.name for o in cameras]})")
    # The importer sets the render size from a camera's aspect ratio: the check's size wins.
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    cam = scene.camera.data  # the importer keeps yfov as a vertical angle, as pt does
    print(f"camera {scene.camera.name}: {cam.type}, sensor fit {cam.sensor_fit}, "
          f"vertical angle {math.degrees(cam.angle_y):.3f} degrees", file=sys.stderr)
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--camera", default="")
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=256, help="samples per pixel of each pass")
    ap.add_argument("--passes", type=int, default=16)
    ap.add_argument("--max-depth", type=int, default=16)
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    scene = build(a.file, width, height, a.camera, a.max_depth)
    render_passes(scene, a.spp, a.passes, a.out_dir)

if __name__ == "__main__":
    main()
