#!/usr/bin/env python3
"""Renders a glTF 2.0 file with Blender's Cycles through Blender's own glTF importer (bpy from
PyPI), the independent check of pt's glTF support (issue 13).

Nothing of pt's reading of the file is reused: the importer builds the Principled BSDFs, the
lights (its default unit conversion, 683 lm/W, which pt follows) and the cameras. Set here only
what the file does not say, as pt does:
- A file without lights gets pt's default environment, uniform white of radiance 1; a file with
  lights a black one. With --env MAP (issue 35) the world is that map instead, and the file's
  lights stay: an Environment Texture, equirectangular, bilinear, in pt's layout (+y up, laid out
  as in Blender; the importer's y-up to z-up turn, Blender (x, y, z) = glTF (x, -z, y), makes
  pt's layout Blender's own, so the map needs no turn of its own), --env-rotate DEG turned about
  glTF's +y (Blender's +z) right-handed, so that at 90 what was along +x comes from -z, and
  --env-scale S the Background's strength.
- The cameras are chosen as pt chooses them (issue 35): pt lists a file's cameras in the order
  it meets them walking the default scene (each root in the scene's order, depth first, a
  node's children last to first), each named by its camera's name or "camera N" (N its index in
  the file's cameras). --camera takes a name or a 0-based index in that list, with pt's rules.
  The list is read here from the file's JSON; the camera rendered is the importer's object whose
  position and view direction are that node's (names do not identify it: the importer names a
  camera object after its node, or its camera where the node has a mesh too, and Blender
  renames duplicates). pt has no near or far plane, so neither has the camera here; a
  perspective camera keeps yfov as a vertical angle and an orthographic one ymag as its
  half-height, whatever the image's shape, as pt does.
- A file without cameras: pt's framing, its one camera ("auto", index 0): the bounding box of
  the triangles' vertices (meshes only; pt's punctual lights have no size) seen through its
  bounding sphere from +z (glTF's; Blender's -y) with a vertical field of view of 45 degrees.
- The default scene alone, as pt renders it: other scenes and nodes in no scene are left out.
- A primitive without a material gets the specification's default (white, metallic 1, roughness
  1), as in pt; the importer leaves it none (Cycles' grey diffuse) or Blender's default.
- The Principled BSDF's multiple-scattering GGX is switched to single-scattering GGX, as in the
  glTF BRDF; the rest of the Principled BSDF is not the glTF BRDF (its dielectric Fresnel and
  layering differ), which is what the check measures first on simple cases.
- KHR_materials_volume: the importer gives Cycles' Volume Absorption the attenuation colour c as
  its colour and 1 / attenuationDistance d as its density, which absorbs (1 - c) / d; the
  extension's coefficient is -ln(c) / d (c is what is left after d). Reset here to the
  extension's: density max(-ln c) / d, colour 1 - (-ln c) / (d density), per channel.
Cycles' biasing defaults are off, as in cycles_lab.py; each pass goes to its own EXR. Cycles
filters 8-bit sRGB textures before decoding them, pt after; --decode-textures (a diagnostic)
decodes them first, to tell that difference from others.

    cycles_gltf.py FILE --out-dir DIR [--res WxH] [--spp N] [--passes P] [--camera NAME|INDEX]
                   [--env MAP [--env-rotate DEG] [--env-scale S]] [--decode-textures]
"""
import argparse
import json
import math
import os
import struct
import sys

import bpy
import mathutils
import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from cycles_lab import decoded_copy, look_at, new_scene, render_passes, unbiased_cycles  # noqa: E402
from lab_scene import fail  # noqa: E402

# Blender's axes from glTF's, as the importer turns them: Blender (x, y, z) = glTF (x, -z, y).
GLTF_TO_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


# ---------------------------------------------------------------- the file's cameras, pt's way
def gltf_json(path):
    """The JSON of a .gltf, or of a .glb's first chunk."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        length, kind = struct.unpack_from("<II", data, 12)
        if kind != 0x4E4F534A:  # "JSON"
            fail(f"{path}: the first chunk of a .glb is its JSON")
        data = data[20:20 + length]
    return json.loads(data)


def local_matrix(node):
    """A node's transform in glTF's space: its matrix (column-major) or T * R * S."""
    if "matrix" in node:
        return np.array(node["matrix"], dtype=float).reshape(4, 4).T
    t = node.get("translation", [0.0, 0.0, 0.0])
    x, y, z, w = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
    sx, sy, sz = node.get("scale", [1.0, 1.0, 1.0])
    r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    m = np.identity(4)
    m[:3, :3] = r @ np.diag([sx, sy, sz])
    m[:3, 3] = t
    return m


def pt_cameras(doc):
    """The file's cameras in pt's order (renderer/gltf/gltf_loader.cpp, GltfReader::read and
    visitTree): the default scene's roots in order (without scenes, every node no other node
    lists as a child), each walked depth first with a stack, so a node's children last to first.
    Each: its name as pt gives it, the node and camera indices and the node's world matrix."""
    nodes = doc.get("nodes", [])
    if doc.get("scenes"):
        roots = doc["scenes"][doc.get("scene", 0)].get("nodes", [])
    else:
        children = {c for n in nodes for c in n.get("children", [])}
        roots = [i for i in range(len(nodes)) if i not in children]
    found = []
    for root in roots:
        stack = [(root, np.identity(4))]
        while stack:
            index, parent = stack.pop()
            node = nodes[index]
            world = parent @ local_matrix(node)
            if "camera" in node:
                c = node["camera"]
                found.append({"name": doc["cameras"][c].get("name") or f"camera {c}", "node": index, "camera": c,
                              "world": world})
            stack.extend((c, world) for c in node.get("children", []))
    return found


def pick_camera(cameras, spec):
    """pt's --camera (cli/render_command.cpp, pickCamera): a name, or a 0-based index."""
    if spec == "":
        return 0
    named = [i for i, c in enumerate(cameras) if c["name"] == spec]
    index = int(spec) if spec.isdigit() and spec.isascii() and len(spec) < 9 else len(cameras)
    is_index = index < len(cameras)
    if len(named) > 1:
        fail(f"--camera {spec}: cameras {named[0]} and {named[1]} are both named {spec!r}; give the index")
    if len(named) == 1 and is_index and named[0] != index:
        fail(f"--camera {spec}: camera {named[0]} is named {spec!r}, and camera {spec} is another")
    if named:
        return named[0]
    if is_index:
        return index
    fail(f"--camera {spec}: no such camera; the scene has " +
         ", ".join(f'{i} "{c["name"]}"' for i, c in enumerate(cameras)))


def importer_camera(scene, cam):
    """The importer's camera object for pt's camera `cam`: the one at the node's position,
    looking along the node's -z."""
    world = cam["world"]
    eye = GLTF_TO_BLENDER @ world[:3, 3]
    ahead = GLTF_TO_BLENDER @ world[:3, :3] @ np.array([0.0, 0.0, -1.0])
    ahead /= np.linalg.norm(ahead)
    scale = max(1.0, float(np.linalg.norm(eye)))
    matches = []
    for obj in scene.objects:
        if obj.type != "CAMERA":
            continue
        m = np.array(obj.matrix_world)
        d = -m[:3, 2] / np.linalg.norm(m[:3, 2])
        if np.linalg.norm(m[:3, 3] - eye) <= 1e-4 * scale and d @ ahead >= 1 - 1e-6:
            matches.append(obj)
    if not matches:
        fail(f"camera {cam['name']!r} (node {cam['node']}): no imported camera at {tuple(eye)} looking along "
             f"{tuple(ahead)}: " + ", ".join(f"{o.name} at {tuple(o.matrix_world.translation)}"
                                            for o in scene.objects if o.type == "CAMERA"))
    # Two cameras in one place looking one way are alike but for their projection: the camera's
    # name breaks the tie.
    name = cam["gltf"].get("name") or "Camera"  # the importer's name for the camera's data
    same = [o for o in matches if o.data.name == name or o.data.name.startswith(name + ".")]
    return (same or matches)[0]


# ---------------------------------------------------------------- framing, pt's way
def frame_bounds(scene):
    """pt's camera for a file without one (renderer/load/scene_loader.cpp, frameScene): the
    bounds of the vertices of faces (pt skips point and line primitives), meshes alone."""
    bpy.context.view_layer.update()  # children's world matrices are stale until the scene is evaluated
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for obj in scene.objects:
        if obj.type != "MESH":
            continue
        mesh = obj.evaluated_get(depsgraph).to_mesh()
        co = np.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", co)
        used = np.empty(len(mesh.loops), dtype=np.int64)
        mesh.loops.foreach_get("vertex_index", used)
        if used.size == 0:
            continue
        m = np.array(obj.matrix_world)
        p = co.reshape(-1, 3)[np.unique(used)] @ m[:3, :3].T + m[:3, 3]
        lo, hi = np.minimum(lo, p.min(axis=0)), np.maximum(hi, p.max(axis=0))
    if not lo[0] <= hi[0]:
        fail("the file has no faces to frame")
    center = (lo + hi) / 2
    print(f"framing: bounds {tuple(lo)} to {tuple(hi)}", file=sys.stderr)
    radius = max(float(np.linalg.norm(hi - lo)) / 2, 1e-6 * max(1.0, float(np.linalg.norm(center))))
    distance = radius / math.sin(math.radians(22.5))
    data = bpy.data.cameras.new("framing")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(45.0)
    # pt has no near plane; Blender's default of 0.1 would clip away a small model (one of the
    # Khronos models is 7 mm across).
    data.clip_start = distance * 1e-4
    data.clip_end = distance * 1e4
    obj = bpy.data.objects.new("framing", data)
    scene.collection.objects.link(obj)
    center = mathutils.Vector(center)
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


def default_materials(doc):
    """The specification's default material (white, metallic 1, roughness 1) where a primitive
    names none, as pt gives it. The importer leaves such faces without a material (Cycles then
    shades them grey diffuse), or, with COLOR_0, gives them Blender's default Principled BSDF
    (metallic 0, roughness 0.5) over the vertex colour."""
    ours = None

    def default():
        nonlocal ours
        if ours is None:
            ours = bpy.data.materials.new("gltf-default")
            tree = ours.node_tree
            tree.nodes.clear()
            bsdf = tree.nodes.new("ShaderNodeBsdfPrincipled")
            tree.links.new(bsdf.outputs[0], tree.nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
        return ours

    for mesh in bpy.data.meshes:
        for i, m in enumerate(mesh.materials):
            if m is None:
                mesh.materials[i] = default()
        if len(mesh.materials) == 0 and len(mesh.polygons) > 0:
            mesh.materials.append(default())
    file_names = {m.get("name") for m in doc.get("materials", [])}
    for mat in bpy.data.materials:
        importer_default = mat.name.split(".")[0] == "DefaultMaterial" and mat.name not in file_names
        if mat is not ours and not importer_default:
            continue
        for n in mat.node_tree.nodes:
            if n.type == "BSDF_PRINCIPLED":
                if not n.inputs["Base Color"].is_linked:
                    n.inputs["Base Color"].default_value = (1.0, 1.0, 1.0, 1.0)
                n.inputs["Metallic"].default_value = 1.0
                n.inputs["Roughness"].default_value = 1.0
                print(f"material {mat.name}: the specification's default (white, metallic 1, roughness 1)",
                      file=sys.stderr)


def decode_textures():
    """A diagnostic (--decode-textures): each 8-bit sRGB texture decoded to linear floats before
    Cycles filters it, as pt does. Cycles keeps such images as bytes and decodes after bilinear
    filtering, which is darker between unlike texels (the decoding is convex); cycles_lab.py does
    this always, the glTF check only when asked, to tell that difference from others."""
    done = {}
    for mat in bpy.data.materials:
        for n in mat.node_tree.nodes if mat.node_tree else []:
            img = n.image if n.type == "TEX_IMAGE" else None
            if img is None or img.is_float or img.colorspace_settings.name != "sRGB":
                continue
            if img.name not in done:
                done[img.name] = decoded_copy(img, img.name + ".linear", keep_alpha=True)
                print(f"texture {img.name}: decoded to linear before filtering", file=sys.stderr)
            n.image = done[img.name]


def set_world(scene, lights, env):
    """pt's environment: its map with --env (rotation, scale), else white without lights, black with."""
    world = bpy.data.worlds.new("pt-environment")
    world.use_nodes = True
    tree = world.node_tree
    tree.nodes.clear()
    bg = tree.nodes.new("ShaderNodeBackground")
    out = tree.nodes.new("ShaderNodeOutputWorld")
    tree.links.new(bg.outputs[0], out.inputs["Surface"])
    if env:
        path, rotate, scale = env
        image = bpy.data.images.load(os.path.abspath(path))
        if not image.is_float:
            fail(f"{path}: an environment map holds float or half values")
        image.colorspace_settings.name = "Linear Rec.709"  # radiance as stored, as pt reads it
        tex = tree.nodes.new("ShaderNodeTexEnvironment")
        tex.image = image
        tex.projection = "EQUIRECTANGULAR"
        tex.interpolation = "Linear"  # pt's bilinear lookup
        coords = tree.nodes.new("ShaderNodeTexCoord")  # in the world, Generated is the ray direction
        turn = tree.nodes.new("ShaderNodeMapping")
        turn.vector_type = "VECTOR"
        # pt looks the map up at the direction turned back by ROTATE about its +y (Blender's +z).
        turn.inputs["Rotation"].default_value = (0.0, 0.0, -math.radians(rotate))
        tree.links.new(coords.outputs["Generated"], turn.inputs["Vector"])
        tree.links.new(turn.outputs["Vector"], tex.inputs["Vector"])
        tree.links.new(tex.outputs["Color"], bg.inputs["Color"])
        bg.inputs["Strength"].default_value = scale
        print(f"environment: {path} {image.size[0]}x{image.size[1]}, turned {rotate} degrees, scale {scale}; "
              f"{len(lights)} lights of the file kept", file=sys.stderr)
    else:
        bg.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0) if not lights else (0.0, 0.0, 0.0, 1.0)
        bg.inputs["Strength"].default_value = 1.0
    scene.world = world


def build(path, width, height, camera_spec, max_depth, env, decode=False):
    scene = new_scene(width, height)
    unbiased_cycles(scene, max_depth)
    doc = gltf_json(path)
    cameras = pt_cameras(doc)
    for c in cameras:
        c["gltf"] = doc["cameras"][c["camera"]]
    if not cameras:
        cameras = [{"name": "auto"}]  # pt's framing camera (scene_loader.cpp, completeScene)
    index = pick_camera(cameras, camera_spec)
    chosen = cameras[index]
    print("pt's cameras: " + ", ".join(f'{i} "{c["name"]}"' + (f' (node {c["node"]})' if "node" in c else "")
                                      for i, c in enumerate(cameras)) + f"; rendering {index}", file=sys.stderr)
    # pt renders the default scene alone (the file's "scene", else its first), or every root node
    # of a file without scenes. The importer puts the default scene's objects in this Blender scene
    # (other scenes in scenes of their own, not rendered, once it does not make collections of
    # them), and nodes of no scene in an "Orphan Nodes" collection here, unlinked below.
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(path), import_scene_as_collection=False)
    scene = bpy.context.scene
    if doc.get("scenes"):
        for parent in [scene.collection, *scene.collection.children_recursive]:
            for child in list(parent.children):
                if child.name.split(".")[0] == "Orphan Nodes":
                    print(f"leaving out {len(child.all_objects)} objects of nodes in no scene", file=sys.stderr)
                    parent.children.unlink(child)
    default_materials(doc)
    for mat in bpy.data.materials:
        for n in mat.node_tree.nodes if mat.node_tree else []:
            if n.type == "BSDF_PRINCIPLED":
                n.distribution = "GGX"
            if n.type == "VOLUME_ABSORPTION":
                to_extension_absorption(n)
    if decode:
        decode_textures()
    lights = [o for o in scene.objects if o.type == "LIGHT"]
    set_world(scene, lights, env)
    bpy.context.view_layer.update()
    if "node" in chosen:
        scene.camera = importer_camera(scene, chosen)
        cam = scene.camera.data
        g = chosen["gltf"]
        if g["type"] == "orthographic":
            # pt: ymag is the half-height of the view whatever the image's shape (the importer
            # spans max(xmag, ymag) across the longer side, right only at the file's aspect).
            cam.sensor_fit = "VERTICAL"
            cam.ortho_scale = 2 * abs(g["orthographic"]["ymag"])
        else:
            cam.sensor_fit = "VERTICAL"  # the importer's already; yfov is its angle_y
        # pt has no near or far plane: only a sliver before the lens, as the framing camera.
        eye = np.array(scene.camera.matrix_world)[:3, 3]
        cam.clip_start = max(1e-6, 1e-6 * float(np.linalg.norm(eye)))
        cam.clip_end = 1e12
    else:
        scene.camera = frame_bounds(scene)
    # The importer sets the render size from a camera's aspect ratio: the check's size wins.
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    cam = scene.camera.data
    print(f"camera {scene.camera.name}: {cam.type}, sensor fit {cam.sensor_fit}, "
          f"vertical angle {math.degrees(cam.angle_y):.3f} degrees, ortho scale {cam.ortho_scale}, "
          f"clip {cam.clip_start} to {cam.clip_end}, at {tuple(scene.camera.matrix_world.translation)}",
          file=sys.stderr)
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--camera", default="0", help="a name or a 0-based index, as pt render --camera [0]")
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=256, help="samples per pixel of each pass")
    ap.add_argument("--passes", type=int, default=16)
    ap.add_argument("--max-depth", type=int, default=16)
    ap.add_argument("--env", help="an environment map, as pt render --env")
    ap.add_argument("--env-rotate", type=float, default=0.0)
    ap.add_argument("--env-scale", type=float, default=1.0)
    ap.add_argument("--decode-textures", action="store_true",
                    help="a diagnostic: decode 8-bit sRGB textures before Cycles filters them, as pt does")
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    env = (a.env, a.env_rotate, a.env_scale) if a.env else None
    scene = build(a.file, width, height, a.camera, a.max_depth, env, a.decode_textures)
    render_passes(scene, a.spp, a.passes, a.out_dir)


if __name__ == "__main__":
    main()
