#!/usr/bin/env python3
"""Renders a lab scene with Blender's Cycles (bpy from PyPI), a second independent check of pt.

As in mitsuba_lab.py, the semantics come from the scene format's text:
- Sphere lights are emissive meshes of radiance I / (pi r^2). The sphere is finely tessellated
  and scaled so that its surface area, and so its mean projected area, is exactly 4 pi r^2.
- The world is the sky above y = 0 and the ground below.
- The camera is a pinhole with a vertical field of view and a box filter of one pixel.
- Each material is the lab tree as a node graph. The Schlick weight comes from Layer Weight's
  Facing output, which is 1 - |cos|. Total internal reflection is made explicit (Cycles' sharp
  refraction drops a path there; the lab reflects it).
- Cycles leaves out refraction's 1/eta^2 radiance scale. That cancels on the lab scenes, whose
  glass objects are closed, with the camera and the lights outside.
- Textures are decoded from sRGB to linear before Cycles filters them, as pt and Mitsuba do.
  Of issue 11's maps only a plain map_Kd is modelled: map_Ks, map_Pr, map_Pm, norm, bump,
  map_d and the -s, -o and -clamp options stop the script (the Mitsuba check has them).
- Only flat-shaded scenes are modelled. pt's rule for smooth normals that disagree with the
  geometry (see docs/validation.md) is not Cycles'.

Cycles' biasing defaults are turned off: light threshold, glossy filter, clamping, adaptive
sampling and denoising. Each pass goes to its own EXR; combine_passes.py makes the mean and its
variance. pt's --max-depth D scattering events are Cycles' D - 1 bounces: Cycles still adds
emission found by the last bounce's ray.

    cycles_lab.py SCENE --out-dir DIR [--res WxH] [--spp N] [--passes P] [--camera I]
"""
import argparse
import math
import os
import sys
import time

import bpy
import mathutils
import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from lab_scene import GROUND, SKY, fail, parse_mtl, parse_obj, pm_rule  # noqa: E402


def node(tree, kind, **inputs):
    n = tree.nodes.new(kind)
    for k, v in inputs.items():
        n.inputs[k].default_value = v
    return n


def math_node(tree, op, a=None, b=None):
    n = tree.nodes.new("ShaderNodeMath")
    n.operation = op
    for i, v in enumerate((a, b)):
        if isinstance(v, (int, float)):
            n.inputs[i].default_value = v
        elif v is not None:
            tree.links.new(v, n.inputs[i])
    return n.outputs[0]


def node_material(name):
    """A material with an empty node tree, for the caller to fill."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.node_tree.nodes.clear()
    return mat, mat.node_tree


def mix_shader(tree, fac, a, b):
    """(1 - fac) a + fac b, with fac a number or a socket."""
    mix = tree.nodes.new("ShaderNodeMixShader")
    if isinstance(fac, (int, float)):
        mix.inputs[0].default_value = fac
    else:
        tree.links.new(fac, mix.inputs[0])
    tree.links.new(a, mix.inputs[1])
    tree.links.new(b, mix.inputs[2])
    return mix.outputs[0]


def decoded_copy(src, name, keep_alpha=False):
    """A float copy of the 8-bit sRGB image `src`, decoded to linear, which Cycles then
    interpolates.

    Cycles keeps 8-bit sRGB images as bytes and decodes after bilinear interpolation, which is
    darker between unlike texels (the decoding is convex): on the lab's grid texture, 1 % on the
    floor. pt and Mitsuba decode each texel first; this makes Cycles do the same. A grey image's
    value serves as RGB; `keep_alpha` keeps the image's alpha and its alpha mode (glTF's coverage).
    """
    src.colorspace_settings.name = "Non-Color"  # raw encoded values
    w, h = src.size
    n = src.channels
    px = np.empty(w * h * n, dtype=np.float32)
    src.pixels.foreach_get(px)
    px = px.reshape(-1, n)
    if n < 4:
        px = np.concatenate([px, np.ones((px.shape[0], 4 - n), np.float32)], axis=1)
    if n < 3:
        px[:, 1] = px[:, 2] = px[:, 0]
    rgb = px[:, :3]
    px[:, :3] = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    img = bpy.data.images.new(name, w, h, alpha=keep_alpha, float_buffer=True)
    img.colorspace_settings.name = "Linear Rec.709"
    if keep_alpha:
        img.alpha_mode = src.alpha_mode
    img.pixels.foreach_set(px.ravel())
    return img


def linear_texture(path):
    """The 8-bit sRGB texture at `path` decoded to linear floats (decoded_copy)."""
    return decoded_copy(bpy.data.images.load(path), os.path.basename(path) + ".linear")


def lab_material(name, m):
    # Of issue 11's maps only a plain map_Kd (no -s, -o or -clamp) is modelled here.
    others = sorted(set(m["maps"]) - {"kd"})
    if others:
        keyword = {"ks": "map_Ks", "pr": "map_Pr", "pm": "map_Pm", "norm": "norm", "bump": "bump", "d": "map_d"}
        fail(f"material {name!r}: {', '.join(keyword[k] for k in others)} is outside what the Cycles check "
             "models; use --renderer mitsuba")
    kd_map = m["maps"].get("kd")
    if kd_map and (kd_map["s"] != [1.0, 1.0] or kd_map["o"] != [0.0, 0.0] or kd_map["clamp"]):
        fail(f"{kd_map['where']}: map_Kd with -s, -o or -clamp is outside what the Cycles check models; "
             "use --renderer mitsuba")
    m = {**m}
    m["kd"], m["ks"], m["r0"], m["w"] = pm_rule(m)
    mat, tree = node_material(name)
    link = tree.links.new
    out = tree.nodes.new("ShaderNodeOutputMaterial")

    diffuse = node(tree, "ShaderNodeBsdfDiffuse", Color=(*m["kd"], 1.0), Roughness=0.0)
    if kd_map:
        tex = tree.nodes.new("ShaderNodeTexImage")
        tex.image = linear_texture(kd_map["file"])
        tex.interpolation = "Linear"
        tex.extension = "REPEAT"
        mul = tree.nodes.new("ShaderNodeMix")
        mul.data_type = "RGBA"
        mul.blend_type = "MULTIPLY"
        mul.inputs["Factor"].default_value = 1.0
        link(tex.outputs["Color"], mul.inputs[6])
        mul.inputs[7].default_value = (*m["kd"], 1.0)
        link(mul.outputs[2], diffuse.inputs["Color"])

    facing = tree.nodes.new("ShaderNodeLayerWeight")
    facing.inputs["Blend"].default_value = 0.5  # Facing = 1 - |cos theta|
    one_minus_cos = facing.outputs["Facing"]

    # B1 = T Refr(eta) + (1 - T) Diffuse, with total internal reflection as a white mirror.
    b1 = diffuse.outputs[0]
    if m["t"] > 0:
        refr = node(tree, "ShaderNodeBsdfRefraction", Color=(1, 1, 1, 1), Roughness=0.0, IOR=m["eta"])
        tir_mirror = node(tree, "ShaderNodeBsdfGlossy", Color=(1, 1, 1, 1), Roughness=0.0)
        geometry = tree.nodes.new("ShaderNodeNewGeometry")
        # Leaving the glass (back face), sin^2 theta_t = eta^2 (1 - cos^2) > 1 reflects.
        cos_i = math_node(tree, "SUBTRACT", 1.0, one_minus_cos)
        sin2_t = math_node(tree, "MULTIPLY", math_node(tree, "SUBTRACT", 1.0, math_node(tree, "MULTIPLY", cos_i, cos_i)),
                           m["eta"] * m["eta"])
        tir = math_node(tree, "MULTIPLY", math_node(tree, "GREATER_THAN", sin2_t, 1.0), geometry.outputs["Backfacing"])
        glass = mix_shader(tree, tir, refr.outputs[0], tir_mirror.outputs[0])
        b1 = mix_shader(tree, m["t"], diffuse.outputs[0], glass)

    shader = b1
    if m["w"] > 0:
        # f = w F Spec(Ks) + (1 - w F) B1, F = R0 + (1 - R0)(1 - |cos|)^5.
        spec = node(tree, "ShaderNodeBsdfGlossy", Color=(*m["ks"], 1.0), Roughness=0.0)
        if max(m["r0"]) - min(m["r0"]) > 1e-6 or m["alpha"] > 0.001:
            fail("a coloured R0 or a rough lobe is outside what the Cycles check models")
        r0 = m["r0"][0]
        f = math_node(tree, "MULTIPLY_ADD", math_node(tree, "POWER", one_minus_cos, 5.0), 1.0 - r0)
        f.node.inputs[2].default_value = r0
        wf = math_node(tree, "MULTIPLY", f, m["w"])
        shader = mix_shader(tree, wf, b1, spec.outputs[0])
    link(shader, out.inputs["Surface"])
    return mat


def emission_material(name, radiance):
    mat, tree = node_material(name)
    strength = max(radiance)
    em = node(tree, "ShaderNodeEmission", Color=(*[c / strength for c in radiance], 1.0), Strength=strength)
    out = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(em.outputs[0], out.inputs["Surface"])
    return mat


def add_mesh(name, positions, uvs, material):
    corners = np.asarray(positions, dtype=np.float64)
    mesh = bpy.data.meshes.new(name)
    n = len(corners) // 3
    mesh.from_pydata(corners.tolist(), [], [(3 * i, 3 * i + 1, 3 * i + 2) for i in range(n)])
    uv = mesh.uv_layers.new()
    for loop in mesh.loops:
        uv.data[loop.index].uv = uvs[loop.vertex_index]
    for p in mesh.polygons:
        p.use_smooth = False
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)


def add_sphere_light(index, light):
    intensity = [c * light["intensity"] for c in light["color"]]
    r = light["radius"]
    if r <= 0:
        fail("point lights are outside what this check models")
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=r, location=light["pos"])
    obj = bpy.context.active_object
    area = sum(p.area for p in obj.data.polygons)
    obj.scale = [math.sqrt(4 * math.pi * r * r / area)] * 3  # the exact sphere's area
    obj.data.materials.append(emission_material(f"light{index}", [c / (math.pi * r * r) for c in intensity]))


def look_at(obj, position, target, up):
    p, t, u = (np.array(v, dtype=float) for v in (position, target, up))
    forward = (t - p) / np.linalg.norm(t - p)
    right = np.cross(forward, u)
    right /= np.linalg.norm(right)
    true_up = np.cross(right, forward)
    m = np.identity(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = right, true_up, -forward, p  # cameras look down -Z
    obj.matrix_world = mathutils.Matrix(m.tolist())  # rows; a nested list would be read as columns


def new_scene(width, height):
    """An empty Cycles scene on the CPU: no adaptive sampling or denoising, a box filter of one
    pixel, float RGB EXR output with the Standard view."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGB"
    scene.view_settings.view_transform = "Standard"
    return scene


def add_camera(scene, position, target, up, fov_y):
    """The lab's pinhole camera: a vertical field of view in degrees."""
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(fov_y)
    obj = bpy.data.objects.new("camera", data)
    scene.collection.objects.link(obj)
    look_at(obj, position, target, up)
    scene.camera = obj


def unbiased_cycles(scene, max_depth):
    """pt's --max-depth D as Cycles' D - 1 bounces, and Cycles' biasing shortcuts off."""
    c = scene.cycles
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = max_depth - 1
    c.transparent_max_bounces = max_depth
    c.volume_bounces = 0
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0


def build(scene_path, camera_index, width, height, max_depth):
    scene = new_scene(width, height)
    unbiased_cycles(scene, max_depth)

    mtllib, groups = parse_obj(scene_path)
    materials, lights, cameras, environment = parse_mtl(mtllib)
    if environment:
        fail("the Cycles check models only the lab's two-tone sky, not an MTL environment block")
    for k, (name, (pos, nrm, uv)) in enumerate(groups.items()):
        m = materials.get(name) or fail(f"usemtl {name!r} names no material")
        add_mesh(f"group{k}", pos, uv, lab_material(name, m))
    for i, light in enumerate(lights):
        add_sphere_light(i, light)

    world = bpy.data.worlds.new("lab")
    scene.world = world
    world.use_nodes = True
    tree = world.node_tree
    tree.nodes.clear()
    coords = tree.nodes.new("ShaderNodeTexCoord")  # in the world, Generated is the ray direction
    xyz = tree.nodes.new("ShaderNodeSeparateXYZ")
    tree.links.new(coords.outputs["Generated"], xyz.inputs[0])
    above = math_node(tree, "GREATER_THAN", xyz.outputs["Y"], 0.0)
    mix = tree.nodes.new("ShaderNodeMix")
    mix.data_type = "RGBA"
    tree.links.new(above, mix.inputs["Factor"])
    mix.inputs[6].default_value = (*GROUND, 1.0)
    mix.inputs[7].default_value = (*SKY, 1.0)
    bg = node(tree, "ShaderNodeBackground", Strength=1.0)
    tree.links.new(mix.outputs[2], bg.inputs["Color"])
    out = tree.nodes.new("ShaderNodeOutputWorld")
    tree.links.new(bg.outputs[0], out.inputs["Surface"])

    cam = cameras[camera_index]
    add_camera(scene, cam["position"], cam["target"], cam["up"], cam["fov"])
    return scene


def render_passes(scene, spp, passes, out_dir):
    """Independent passes of `spp` samples (seeds 1, 2, ...), each to out_dir/passNNNN.exr."""
    scene.cycles.samples = spp
    os.makedirs(out_dir, exist_ok=True)
    start = time.time()
    for p in range(passes):
        scene.cycles.seed = p + 1
        scene.render.filepath = os.path.join(out_dir, f"pass{p:04d}.exr")
        bpy.ops.render.render(write_still=True)
        print(f"pass {p + 1}/{passes}  {time.time() - start:.0f} s", file=sys.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--camera", type=int, default=0)
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=256, help="samples per pixel of each pass")
    ap.add_argument("--passes", type=int, default=64)
    ap.add_argument("--max-depth", type=int, default=16)
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    scene = build(a.scene, a.camera, width, height, a.max_depth)
    render_passes(scene, a.spp, a.passes, a.out_dir)

if __name__ == "__main__":
    main()
