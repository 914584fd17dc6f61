#!/usr/bin/python3
"""Writes the small glTF 2.0 files of scenes/gltf/ that tests and golden cases use (issue 13).

Every file is self-contained (buffers and images as data URIs) except bin_and_image.gltf, which
keeps its .bin and .png beside it, as exported files do. Run from anywhere; rewrites the files.

  spheres.gltf        five spheres from dielectric to metal, rough to smooth, on a ground plane,
                      lit by a spot light and a directional light; a perspective camera
  textured.gltf       a tile with every map: base colour (sRGB, with alpha for MASK), a
                      metallic-roughness map (B metal stripes, G roughness ramp), a normal map of
                      bumps, an emissive square; a point light
  plane_lights.gltf   a white plane under a point light at height 2 (683 cd, so I = 1 W/sr), for
                      the analytic test; variants with a spot, a directional light and a range
  transforms.gltf     one mesh placed by two nodes (TRS, and a child of a rotated parent) and the
  transforms_flat.gltf  same triangles written in world space: they must load equal; transforms.glb
                      is the first as a binary container
  alpha_modes.gltf    OPAQUE, MASK and BLEND quads in front of a red wall
  cameras.gltf        a perspective camera with aspect ratio 2 and an orthographic one
  bin_and_image.gltf  a quad whose buffer and base colour texture are files beside it
  texture_transform.gltf  one image through five sampler wraps and KHR_texture_transforms
  clearcoat.gltf      KHR_materials_clearcoat: smooth, rough, over black, and textured coats;
  clearcoat_white.gltf  the same spheres under the default white environment (crosscheck)
  metallic_glass_white.gltf  smooth glass spheres of metallic 0, 0.5 and 1 before a striped wall,
                      under the default white environment (the Cycles crosscheck of issue 49)
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gltf")

FLOAT, USHORT, UINT = 5126, 5123, 5125


class Gltf:
    def __init__(self):
        self.d = {"asset": {"version": "2.0", "generator": "pt scenes/make_gltf.py"}, "scenes": [{"nodes": []}],
                  "scene": 0, "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": [],
                  "buffers": []}
        self.blob = bytearray()

    def view(self, data):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.d["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)})
        self.blob += data
        return len(self.d["bufferViews"]) - 1

    def accessor(self, values, kind, n):
        """values: flat list; kind: 'VEC3', 'VEC2', 'SCALAR' (indices as UNSIGNED_INT)."""
        if kind == "SCALAR":
            data = struct.pack(f"<{len(values)}I", *values)
            acc = {"componentType": UINT, "count": len(values), "type": "SCALAR"}
        else:
            data = struct.pack(f"<{len(values)}f", *values)
            acc = {"componentType": FLOAT, "count": len(values) // n, "type": kind}
            if kind == "VEC3":
                xs = [values[i::3] for i in range(3)]
                acc["min"], acc["max"] = [min(x) for x in xs], [max(x) for x in xs]
        acc["bufferView"] = self.view(data)
        self.d["accessors"].append(acc)
        return len(self.d["accessors"]) - 1

    def mesh(self, positions, normals, uvs, indices, material):
        attrs = {"POSITION": self.accessor(positions, "VEC3", 3)}
        if normals:
            attrs["NORMAL"] = self.accessor(normals, "VEC3", 3)
        if uvs:
            attrs["TEXCOORD_0"] = self.accessor(uvs, "VEC2", 2)
        prim = {"attributes": attrs, "indices": self.accessor(indices, "SCALAR", 1), "material": material}
        self.d["meshes"].append({"primitives": [prim]})
        return len(self.d["meshes"]) - 1

    def material(self, **m):
        self.d["materials"].append(m)
        return len(self.d["materials"]) - 1

    def node(self, root=True, **n):
        self.d["nodes"].append(n)
        i = len(self.d["nodes"]) - 1
        if root:
            self.d["scenes"][0]["nodes"].append(i)
        return i

    def image(self, png, sampler=None):
        self.d.setdefault("images", []).append({"uri": "data:image/png;base64," + base64.b64encode(png).decode()})
        tex = {"source": len(self.d["images"]) - 1}
        if sampler is not None:
            tex["sampler"] = sampler
        self.d.setdefault("textures", []).append(tex)
        return len(self.d["textures"]) - 1

    def light(self, **l):
        ext = self.d.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
        ext["lights"].append(l)
        used = self.d.setdefault("extensionsUsed", [])
        if "KHR_lights_punctual" not in used:
            used.append("KHR_lights_punctual")
        return len(ext["lights"]) - 1

    def camera(self, **c):
        self.d.setdefault("cameras", []).append(c)
        return len(self.d["cameras"]) - 1

    def write_glb(self, name):
        """The binary container: a JSON chunk and a BIN chunk, each padded to 4 bytes."""
        self.d["buffers"] = [{"byteLength": len(self.blob)}]
        text = json.dumps(self.d).encode()
        text += b" " * (-len(text) % 4)
        blob = bytes(self.blob) + b"\0" * (-len(self.blob) % 4)
        body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)

    def write(self, name, external=False):
        path = os.path.join(HERE, name)
        if external:
            bin_name = os.path.splitext(name)[0] + ".bin"
            with open(os.path.join(HERE, bin_name), "wb") as f:
                f.write(self.blob)
            self.d["buffers"] = [{"uri": bin_name, "byteLength": len(self.blob)}]
        else:
            self.d["buffers"] = [{"uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode(),
                                  "byteLength": len(self.blob)}]
        with open(path, "w") as f:
            json.dump(self.d, f, indent=1)
            f.write("\n")


def png(width, height, channels, pixel):
    """An 8-bit PNG (channels 3 or 4) whose pixel (x, y) (row 0 at the top) is pixel(x, y)."""
    raw = b"".join(b"\x00" + bytes(v for x in range(width) for v in pixel(x, y)) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    color = 2 if channels == 3 else 6
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def quad(g, corners, normal, material, uv=True):
    """Counter-clockwise corners seen from the side `normal` faces."""
    pos = [c for p in corners for c in p]
    nrm = list(normal) * 4
    uvs = [0, 1, 1, 1, 1, 0, 0, 0] if uv else None  # glTF's v runs down the image
    return g.mesh(pos, nrm, uvs, [0, 1, 2, 0, 2, 3], material)


def sphere(g, radius, material, rings=24, segments=48, uv=False):
    """A UV sphere; spheres of one radius share their accessors, as exporters write instances.
    With uv, TEXCOORD_0 runs u = 0..1 around (from +x) and v = 0..1 from the top pole down."""
    key = ("sphere", radius, rings, segments, uv)
    cache = g.__dict__.setdefault("shared", {})
    if key not in cache:
        pos, nrm, idx, uvs = [], [], [], []
        for i in range(rings + 1):
            t = math.pi * i / rings
            for j in range(segments + 1):
                p = 2 * math.pi * j / segments
                n = (math.sin(t) * math.cos(p), math.cos(t), -math.sin(t) * math.sin(p))
                nrm += n
                pos += [radius * c for c in n]
                uvs += [j / segments, i / rings]
        for i in range(rings):
            for j in range(segments):
                a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
                if i > 0:  # the first ring's other triangle would have two corners on the pole
                    idx += [a, b, a + 1]
                if i < rings - 1:
                    idx += [a + 1, b, b + 1]
        cache[key] = {"POSITION": g.accessor(pos, "VEC3", 3), "NORMAL": g.accessor(nrm, "VEC3", 3),
                      "indices": g.accessor(idx, "SCALAR", 1)}
        if uv:
            cache[key]["TEXCOORD_0"] = g.accessor(uvs, "VEC2", 2)
    acc = cache[key]
    attrs = {"POSITION": acc["POSITION"], "NORMAL": acc["NORMAL"]}
    if uv:
        attrs["TEXCOORD_0"] = acc["TEXCOORD_0"]
    prim = {"attributes": attrs, "indices": acc["indices"], "material": material}
    g.d["meshes"].append({"primitives": [prim]})
    return len(g.d["meshes"]) - 1


def ground(g, size, material, y=0.0):
    s = size
    return quad(g, [(-s, y, s), (s, y, s), (s, y, -s), (-s, y, -s)], (0, 1, 0), material, uv=False)


def look_at_quaternion(eye, target):
    """Rotation taking the camera's -z to (target - eye), keeping +y up; (x, y, z, w)."""
    f = [t - e for t, e in zip(target, eye)]
    ln = math.sqrt(sum(c * c for c in f))
    f = [c / ln for c in f]
    r = [-f[2], 0.0, f[0]]  # f x up
    lr = math.sqrt(sum(c * c for c in r))
    r = [c / lr for c in r]
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    m = [[r[0], u[0], -f[0]], [r[1], u[1], -f[1]], [r[2], u[2], -f[2]]]  # columns r, u, -f
    w = math.sqrt(max(0.0, 1 + m[0][0] + m[1][1] + m[2][2])) / 2
    x = (m[2][1] - m[1][2]) / (4 * w)
    y = (m[0][2] - m[2][0]) / (4 * w)
    z = (m[1][0] - m[0][1]) / (4 * w)
    return [x, y, z, w]


def camera_node(g, eye, target, yfov_deg=40.0, aspect=None, name="Front"):
    persp = {"yfov": math.radians(yfov_deg), "znear": 0.01}
    if aspect:
        persp["aspectRatio"] = aspect
    c = g.camera(type="perspective", perspective=persp, name=name)
    return g.node(camera=c, translation=list(eye), rotation=look_at_quaternion(eye, target), name=name)


def spheres():
    g = Gltf()
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.9})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    looks = [("RedPlastic", [0.8, 0.1, 0.1], 0.0, 0.3), ("WhiteMatte", [0.8, 0.8, 0.8], 0.0, 1.0),
             ("Gold", [1.0, 0.78, 0.34], 1.0, 0.25), ("MirrorSteel", [0.9, 0.9, 0.9], 1.0, 0.0),
             ("HalfMetal", [0.3, 0.6, 0.9], 0.5, 0.5)]
    for k, (name, color, metal, rough) in enumerate(looks):
        m = g.material(name=name, pbrMetallicRoughness={"baseColorFactor": color + [1], "metallicFactor": metal,
                                                          "roughnessFactor": rough})
        g.node(mesh=sphere(g, 0.45, m), translation=[-2.0 + k, 0.45, 0.0], name=name)
    spot = g.light(type="spot", color=[1.0, 0.9, 0.8], intensity=2500.0,
                   spot={"innerConeAngle": 0.3, "outerConeAngle": 0.6}, name="Spot")
    g.node(extensions={"KHR_lights_punctual": {"light": spot}}, translation=[-1.5, 4.0, 2.5],
           rotation=look_at_quaternion([-1.5, 4.0, 2.5], [0.0, 0.0, 0.0]), name="SpotNode")
    sun = g.light(type="directional", color=[0.7, 0.8, 1.0], intensity=300.0, name="Sun")
    g.node(extensions={"KHR_lights_punctual": {"light": sun}}, rotation=look_at_quaternion([0, 0, 0], [1.0, -2.0, -1.5]),
           name="SunNode")
    camera_node(g, [0.0, 1.6, 5.0], [0.0, 0.4, 0.0], 36.0)
    g.write("spheres.gltf")


def dome_normal(x, y, sign):
    """Tangent-space normal map texel of domes (sign 1) or dimples (-1) of radius 6 on a 16-texel
    grid; +y up the image."""
    cx, cy = (x % 16) - 7.5, (y % 16) - 7.5
    r2 = cx * cx + cy * cy
    if r2 > 36:
        return (128, 128, 255)
    h = math.sqrt(36 - r2)
    nx, ny, nz = sign * cx / 6, -sign * cy / 6, h / 6
    ln = math.sqrt(nx * nx + ny * ny + nz * nz)
    return tuple(int(round(127.5 + 127.5 * c / ln)) for c in (nx, ny, nz))


def textured():
    g = Gltf()
    n = 64
    base = png(n, n, 4, lambda x, y: ((40, 120, 200, 255) if (x // 8 + y // 8) % 2 else (230, 200, 60, 255))
               if 6 <= x < 58 and 6 <= y < 58 else (200, 200, 200, 0))  # a clear frame: cut by MASK
    mr = png(n, n, 3, lambda x, y: (0, int(255 * x / (n - 1)), 255 if (y // 16) % 2 else 0))  # G ramp, B stripes
    normal = png(n, n, 3, lambda x, y: dome_normal(x, y, 1.0))
    emissive = png(n, n, 3, lambda x, y: (255, 140, 40) if 24 <= x < 40 and 24 <= y < 40 else (0, 0, 0))
    tb, tmr, tn, te = g.image(base), g.image(mr), g.image(normal), g.image(emissive)
    m = g.material(name="Tile", alphaMode="MASK", alphaCutoff=0.5,
                   pbrMetallicRoughness={"baseColorTexture": {"index": tb}, "metallicRoughnessTexture": {"index": tmr},
                                         "metallicFactor": 1.0, "roughnessFactor": 1.0},
                   normalTexture={"index": tn, "scale": 1.0}, emissiveTexture={"index": te},
                   emissiveFactor=[1.0, 1.0, 1.0], extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}})
    g.d["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    g.node(mesh=quad(g, [(-1, 0, 1), (1, 0, 1), (1, 0, -1), (-1, 0, -1)], (0, 1, 0), m), translation=[0, 0.3, 0],
           rotation=[math.sin(math.radians(20)), 0, 0, math.cos(math.radians(20))], name="Tile")
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 1.0})
    g.node(mesh=ground(g, 10, floor), name="Ground")
    point = g.light(type="point", color=[1, 1, 1], intensity=1500.0, name="Lamp")
    g.node(extensions={"KHR_lights_punctual": {"light": point}}, translation=[1.5, 3.0, 2.0], name="LampNode")
    camera_node(g, [0.0, 2.6, 2.8], [0.0, 0.3, 0.0], 45.0)
    g.write("textured.gltf")


def plane_lights():
    for name, light, extra in [
        ("plane_point.gltf", {"type": "point", "intensity": 683.0}, {}),
        ("plane_range.gltf", {"type": "point", "intensity": 683.0, "range": 3.0}, {}),
        ("plane_spot.gltf", {"type": "spot", "intensity": 683.0, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
         {"rotation": [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)]}),  # -z turned to -y: straight down
        ("plane_directional.gltf", {"type": "directional", "intensity": 683.0},
         {"rotation": [-math.sin(math.radians(60) / 2), 0, 0, math.cos(math.radians(60) / 2)]}),  # 30 degrees from the normal
    ]:
        g = Gltf()
        white = g.material(name="White", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0.0,
                                                                "roughnessFactor": 1.0})
        g.node(mesh=ground(g, 50, white), name="Plane")
        l = g.light(**light)
        g.node(extensions={"KHR_lights_punctual": {"light": l}}, translation=[0.0, 2.0, 0.0], **extra)
        c = g.camera(type="orthographic", orthographic={"xmag": 2.0, "ymag": 2.0, "znear": 0.01, "zfar": 100.0}, name="Down")
        g.node(camera=c, translation=[0.0, 10.0, 0.0], rotation=[-math.sqrt(0.5), 0, 0, math.sqrt(0.5)], name="Down")
        g.write(name)


BOX = ([-0.5, -0.5, 0.5, 0.5, -0.5, 0.5, 0.5, 0.5, 0.5, -0.5, 0.5, 0.5,   # +z face, then +y, +x
        -0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, -0.5, -0.5, 0.5, -0.5,
        0.5, -0.5, 0.5, 0.5, -0.5, -0.5, 0.5, 0.5, -0.5, 0.5, 0.5, 0.5],
       [0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11])


def mat4_of(t, q, s):
    x, y, z, w = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][j] * s[j] for j in range(3)] + [t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def apply(m, p):
    return [sum(m[i][j] * p[j] for j in range(3)) + m[i][3] for i in range(3)]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def transforms():
    qa = [0.0, math.sin(0.35), 0.0, math.cos(0.35)]               # 40 degrees about y
    qb = [math.sin(0.25), 0.0, 0.0, math.cos(0.25)]               # 28.6 degrees about x
    qc = [0.0, 0.0, math.sin(-0.4), math.cos(-0.4)]               # -45.8 degrees about z
    a = ([1.0, 0.2, -0.5], qa, [1.5, 0.5, 2.0])
    parent = ([-1.0, 0.5, 0.0], qb, [1.0, 1.0, 1.0])
    child = ([0.3, 0.0, 0.4], qc, [0.8, -1.2, 0.8])                 # a mirroring scale
    g = Gltf()
    m = g.material(name="Grey", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.7, 0.7, 1]})
    mesh = g.mesh(BOX[0], None, None, BOX[1], m)
    g.node(mesh=mesh, translation=a[0], rotation=a[1], scale=a[2], name="A")
    c = g.node(root=False, mesh=mesh, translation=child[0], rotation=child[1], scale=child[2], name="Child")
    g.node(children=[c], translation=parent[0], rotation=parent[1], name="Parent")
    g.write("transforms.gltf")
    g.write_glb("transforms.glb")
    flat = Gltf()
    m = flat.material(name="Grey", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.7, 0.7, 1]})
    for world, mirrored in [(mat4_of(*a), False), (matmul(mat4_of(*parent), mat4_of(*child)), True)]:
        pos = [c for i in range(0, len(BOX[0]), 3) for c in apply(world, BOX[0][i:i + 3])]
        idx = list(BOX[1])
        if mirrored:  # keep the winding counter-clockwise seen from outside
            for k in range(0, len(idx), 3):
                idx[k + 1], idx[k + 2] = idx[k + 2], idx[k + 1]
        flat.node(mesh=flat.mesh(pos, None, None, idx, m))
    flat.write("transforms_flat.gltf")


def alpha_modes():
    g = Gltf()
    red = g.material(name="Wall", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.1, 0.1, 1], "metallicFactor": 0.0})
    g.node(mesh=quad(g, [(-3, -1, -1), (3, -1, -1), (3, 2, -1), (-3, 2, -1)], (0, 0, 1), red), name="Wall")
    ramp = g.image(png(32, 4, 4, lambda x, y: (255, 255, 255, int(255 * x / 31))))  # alpha 0 -> 1 across u
    for k, (mode, extra) in enumerate([("OPAQUE", {}), ("MASK", {"alphaCutoff": 0.5}), ("BLEND", {})]):
        m = g.material(name=mode, alphaMode=mode, **extra,
                       pbrMetallicRoughness={"baseColorTexture": {"index": ramp}, "baseColorFactor": [1, 1, 1, 1],
                                             "metallicFactor": 0.0})
        x = -2.0 + 1.6 * k
        g.node(mesh=quad(g, [(x - 0.7, 0, 0), (x + 0.7, 0, 0), (x + 0.7, 1, 0), (x - 0.7, 1, 0)], (0, 0, 1), m), name=mode)
    half = g.material(name="HalfBlend", alphaMode="BLEND", pbrMetallicRoughness={"baseColorFactor": [1, 1, 1, 0.5]})
    g.node(mesh=quad(g, [(-0.5, 1.2, 0), (0.5, 1.2, 0), (0.5, 1.8, 0), (-0.5, 1.8, 0)], (0, 0, 1), half), name="HalfBlend")
    camera_node(g, [0.0, 0.8, 4.0], [0.0, 0.8, 0.0], 40.0)
    g.write("alpha_modes.gltf")


def cameras():
    g = Gltf()
    m = g.material(name="Grey", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.7, 0.7, 1]})
    g.node(mesh=g.mesh(BOX[0], None, None, BOX[1], m), name="Box")
    camera_node(g, [2.0, 1.5, 3.0], [0.0, 0.0, 0.0], 30.0, aspect=2.0, name="Wide")
    c = g.camera(type="orthographic", orthographic={"xmag": 1.5, "ymag": 1.0, "znear": 0.01, "zfar": 100}, name="Ortho")
    g.node(camera=c, translation=[0.0, 0.0, 5.0], name="Ortho")
    g.write("cameras.gltf")


def texture_transform():
    """Five emissive quads, each drawing one 128 x 128 image (quadrants red, green, blue, yellow
    from the top left, each with a white F) through a different sampler or KHR_texture_transform:
    as it is; the extension's own example (offset [0, 1], rotation pi/2, scale 0.5: the lower-left,
    blue quadrant turned clockwise); rotation pi/2 alone (the image turned clockwise); offset
    [0, 1] with scale [1, -1] (upside down); MIRRORED_REPEAT at scale 2 (four copies, mirrored)."""
    g = Gltf()
    colours = [[(200, 40, 40), (40, 160, 40)], [(40, 60, 200), (220, 200, 40)]]
    def pixel(x, y):  # 4 x 4 texels a cell: the quads minify it, where 8-bit filtering orders agree
        x, y = x // 4, y // 4
        qx, qy = x % 16, y % 16
        f = 4 <= qx < 6 and 3 <= qy < 13 or 3 <= qy < 5 and 4 <= qx < 12 or 7 <= qy < 9 and 4 <= qx < 10
        return (255, 255, 255) if f else colours[y // 16][x // 16]
    image = g.image(png(128, 128, 3, pixel))
    mirrored = g.image(png(128, 128, 3, pixel), sampler=0)
    g.d["samplers"] = [{"wrapS": 33648, "wrapT": 33648}]
    looks = [("AsItIs", image, None), ("SpecExample", image, {"offset": [0, 1], "rotation": math.pi / 2, "scale": [0.5, 0.5]}),
             ("Rotated", image, {"rotation": math.pi / 2}), ("UpsideDown", image, {"offset": [0, 1], "scale": [1, -1]}),
             ("Mirrored", mirrored, {"scale": [2, 2]})]
    for i, (name, tex, transform) in enumerate(looks):
        info = {"index": tex}
        if transform:
            info["extensions"] = {"KHR_texture_transform": transform}
        m = g.material(name=name, pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0},
                       emissiveTexture=info, emissiveFactor=[1.0, 1.0, 1.0])
        x = 1.2 * (i - 2)
        g.node(mesh=quad(g, [(x - 0.5, -0.5, 0), (x + 0.5, -0.5, 0), (x + 0.5, 0.5, 0), (x - 0.5, 0.5, 0)], (0, 0, 1), m),
               name=name)
    g.d["extensionsUsed"] = ["KHR_texture_transform"]
    camera_node(g, [0.0, 0.0, 6.0], [0.0, 0.0, 0.0], 12.0, aspect=5.0)
    g.write("texture_transform.gltf")


def bin_and_image():
    g = Gltf()
    with open(os.path.join(HERE, "checker.png"), "wb") as f:
        f.write(png(8, 8, 3, lambda x, y: (255, 255, 255) if (x // 4 + y // 4) % 2 else (20, 20, 20)))
    g.d["images"] = [{"uri": "checker.png"}]
    g.d["textures"] = [{"source": 0}]
    m = g.material(name="Checker", pbrMetallicRoughness={"baseColorTexture": {"index": 0}, "metallicFactor": 0.0})
    g.node(mesh=quad(g, [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], (0, 0, 1), m), name="Quad")
    g.write("bin_and_image.gltf", external=True)


def vertex_colors():
    """Two unit quads side by side under the default white environment, Lambert (specularFactor
    0) so that each point's radiance is its base colour. Left: COLOR_0 as normalized unsigned
    bytes (VEC4) red, green, blue and white at the corners, from the bottom left
    counter-clockwise. Right: a 2 x 2 texture (red, green / blue, white, top row first) read
    through TEXCOORD_1, with TEXCOORD_0 all zeros (a loader that reads set 0 sees one texel)."""
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_specular"]
    lambert = {"KHR_materials_specular": {"specularFactor": 0.0}}
    plain = g.material(name="VertexColored", pbrMetallicRoughness={"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0},
                       extensions=lambert)
    pos = [-1.1, -0.5, 0, -0.1, -0.5, 0, -0.1, 0.5, 0, -1.1, 0.5, 0]
    colors = bytes([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255])
    col = g.view(colors)
    g.d["accessors"].append({"bufferView": col, "componentType": 5121, "normalized": True, "count": 4, "type": "VEC4"})
    color_accessor = len(g.d["accessors"]) - 1
    prim = {"attributes": {"POSITION": g.accessor(pos, "VEC3", 3), "COLOR_0": color_accessor},
            "indices": g.accessor([0, 1, 2, 0, 2, 3], "SCALAR", 1), "material": plain}
    g.d["meshes"].append({"primitives": [prim]})
    g.node(mesh=len(g.d["meshes"]) - 1, name="Colored")
    texels = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]
    tex = g.image(png(2, 2, 3, lambda x, y: texels[2 * y + x]), sampler=0)
    g.d["samplers"] = [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}]
    textured = g.material(name="SecondSet", pbrMetallicRoughness={"baseColorTexture": {"index": tex, "texCoord": 1},
                                                                  "metallicFactor": 0.0}, extensions=lambert)
    pos = [0.1, -0.5, 0, 1.1, -0.5, 0, 1.1, 0.5, 0, 0.1, 0.5, 0]
    prim = {"attributes": {"POSITION": g.accessor(pos, "VEC3", 3), "TEXCOORD_0": g.accessor([0.0] * 8, "VEC2", 2),
                           "TEXCOORD_1": g.accessor([0, 1, 1, 1, 1, 0, 0, 0], "VEC2", 2)},
            "indices": g.accessor([0, 1, 2, 0, 2, 3], "SCALAR", 1), "material": textured}
    g.d["meshes"].append({"primitives": [prim]})
    g.node(mesh=len(g.d["meshes"]) - 1, name="SecondSet")
    c = g.camera(type="orthographic", orthographic={"xmag": 1.2, "ymag": 0.6, "znear": 0.01, "zfar": 100}, name="Front")
    g.node(camera=c, translation=[0.0, 0.0, 2.0], name="Front")
    g.write("vertex_colors.gltf")


def tangents():
    """A normal-mapped quad whose TANGENT attribute (0, 1, 0, -1) is not what the uvs would give,
    under a node turned 90 degrees about +z: pt must use the file's tangent, turned, (-1, 0, 0)."""
    g = Gltf()
    normal = g.image(png(1, 1, 3, lambda x, y: (128, 128, 255)))
    m = g.material(name="Mapped", pbrMetallicRoughness={"metallicFactor": 0.0}, normalTexture={"index": normal})
    pos = [-0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0]
    prim = {"attributes": {"POSITION": g.accessor(pos, "VEC3", 3), "NORMAL": g.accessor([0, 0, 1] * 4, "VEC3", 3),
                           "TEXCOORD_0": g.accessor([0, 1, 1, 1, 1, 0, 0, 0], "VEC2", 2)},
            "indices": g.accessor([0, 1, 2, 0, 2, 3], "SCALAR", 1), "material": m}
    data = struct.pack("<16f", *([0.0, 1.0, 0.0, -1.0] * 4))
    g.d["accessors"].append({"bufferView": g.view(data), "componentType": FLOAT, "count": 4, "type": "VEC4"})
    prim["attributes"]["TANGENT"] = len(g.d["accessors"]) - 1
    g.d["meshes"].append({"primitives": [prim]})
    g.node(mesh=len(g.d["meshes"]) - 1, rotation=[0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4)], name="Turned")
    g.write("tangents.gltf")


def materials():
    """The Cycles check's simple cases (tools/crosscheck/cycles_gltf.py): five spheres on a floor
    under the default white environment (no lights), from the left a
    rough white dielectric (roughness 1), red dielectric at roughness 0.3, blue at 0.6, gold
    metal at 0.3 and silver metal at 0.6."""
    g = Gltf()
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 1.0})
    g.node(mesh=quad(g, [(-3, 0, 1.5), (3, 0, 1.5), (3, 0, -1.5), (-3, 0, -1.5)], (0, 1, 0), floor, uv=False), name="Floor")
    looks = [("White", [0.8, 0.8, 0.8], 0.0, 1.0), ("Red", [0.8, 0.1, 0.1], 0.0, 0.3), ("Blue", [0.1, 0.2, 0.8], 0.0, 0.6),
             ("Gold", [1.0, 0.78, 0.34], 1.0, 0.3), ("Silver", [0.9, 0.9, 0.9], 1.0, 0.6)]
    for k, (name, color, metal, rough) in enumerate(looks):
        m = g.material(name=name, pbrMetallicRoughness={"baseColorFactor": color + [1], "metallicFactor": metal,
                                                          "roughnessFactor": rough})
        g.node(mesh=sphere(g, 0.45, m), translation=[-2.2 + 1.1 * k, 0.45, 0.0], name=name)
    camera_node(g, [0.0, 1.5, 4.5], [0.0, 0.35, 0.0], 24.0, aspect=2.5)
    g.write("materials.gltf")


def sphere_row_scene(extensions_used):
    """The start of the clear-coat and sheen scenes: a grey rough floor."""
    g = Gltf()
    g.d["extensionsUsed"] = extensions_used
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.9})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    return g


def sphere_row(g, looks):
    """Five spheres of radius 0.45 in a row along x, one per (name, pbrMetallicRoughness,
    extensions), with texture coordinates."""
    for k, (name, pbr, ext) in enumerate(looks):
        m = g.material(name=name, pbrMetallicRoughness=pbr, extensions=ext)
        g.node(mesh=sphere(g, 0.45, m, uv=True), translation=[-2.0 + k, 0.45, 0.0], name=name)


def light_and_write(g, lit, name, strength, sun_color, lux, sun_towards, sun_name="Sun"):
    """Writes NAME.gltf lit by an emissive panel above and in front of the spheres (emissive
    strength `strength`) and a directional light travelling towards `sun_towards`; or, unlit,
    NAME_white.gltf, which pt and Cycles light with a uniform white environment."""
    if not lit:
        camera_node(g, [0.0, 1.2, 5.0], [0.0, 0.45, 0.0], 30.0, aspect=2.0)
        g.write(name + "_white.gltf")
        return
    panel = g.material(name="Panel", pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0},
                       emissiveFactor=[1.0, 0.95, 0.85],
                       extensions={"KHR_materials_emissive_strength": {"emissiveStrength": strength}})
    g.d["extensionsUsed"].append("KHR_materials_emissive_strength")
    g.node(mesh=quad(g, [(-2.5, 2.5, 1.0), (2.5, 2.5, 1.0), (2.5, 2.5, 2.5), (-2.5, 2.5, 2.5)], (0, -1, 0), panel, uv=False),
           name="Panel")
    sun = g.light(type="directional", color=sun_color, intensity=lux, name=sun_name)
    g.node(extensions={"KHR_lights_punctual": {"light": sun}}, rotation=look_at_quaternion([0, 0, 0], sun_towards),
           name=sun_name + "Node")
    camera_node(g, [0.0, 1.2, 5.0], [0.0, 0.45, 0.0], 30.0, aspect=2.0)
    g.write(name + ".gltf")


def clearcoat(lit=True):
    """KHR_materials_clearcoat (issue 28) on five spheres over a floor, under an emissive panel
    and a directional light (lit), or under the default white environment (clearcoat_white.gltf,
    the Cycles crosscheck's case, where only the materials differ): from the left a red dielectric (roughness 0.6) without a coat, the same
    under a smooth coat, under a coat of roughness 0.4, a black base (specularFactor 0) under a
    smooth coat (the coat's Fresnel alone), and a coat whose weight (R stripes), roughness (G
    ramp) and normal (dimples) come from textures over a blue base."""
    g = sphere_row_scene(["KHR_materials_clearcoat", "KHR_materials_specular"])
    n = 64
    weight = g.image(png(n, n, 3, lambda x, y: (255 if (x // 8) % 2 else 40, int(255 * y / (n - 1)), 0)))
    normal = g.image(png(n, n, 3, lambda x, y: dome_normal(x, y, -1.0)))  # dimples
    red = {"baseColorFactor": [0.8, 0.1, 0.1, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6}
    looks = [("Red", red, {}),
             ("RedSmoothCoat", red, {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.0}}),
             ("RedRoughCoat", red, {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.4}}),
             ("BlackCoat", {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0},
              {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0}, "KHR_materials_specular": {"specularFactor": 0.0}}),
             ("TexturedCoat", {"baseColorFactor": [0.1, 0.2, 0.8, 1], "metallicFactor": 0.0, "roughnessFactor": 0.8},
              {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatTexture": {"index": weight},
                                           "clearcoatRoughnessFactor": 0.5, "clearcoatRoughnessTexture": {"index": weight},
                                           "clearcoatNormalTexture": {"index": normal, "scale": 1.0}}})]
    sphere_row(g, looks)
    # The smooth coats mirror the panel (a point light they cannot).
    light_and_write(g, lit, "clearcoat", 6.0, [0.8, 0.85, 1.0], 300.0, [1.0, -2.0, -1.5])


def cornell_box():
    """scenes/cornell_box.obj as glTF: the same triangles (read from the OBJ, quads split as pt
    splits them), Lambert walls through KHR_materials_specular's specularFactor 0, the lamp's Ke
    as emissiveFactor times KHR_materials_emissive_strength, and the MTL's camera. The OBJ's
    TallBox has a Fresnel-blended mirror that glTF cannot say; here it is Lambert only."""
    obj = os.path.join(HERE, "..", "cornell_box.obj")
    verts, groups, current = [], {}, None
    for line in open(obj):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            verts.append([float(x) for x in t[1:4]])
        elif t[0] == "usemtl":
            current = groups.setdefault(t[1], [])
        elif t[0] == "f":
            idx = [int(x.split("/")[0]) - 1 for x in t[1:]]
            for k in range(1, len(idx) - 1):
                current.append((idx[0], idx[k], idx[k + 1]))
    colors = {"Floor": [0.75] * 3, "Ceiling": [0.75] * 3, "BackWall": [0.75] * 3, "LeftWall": [0.63, 0.065, 0.05],
              "RightWall": [0.14, 0.45, 0.091], "Lamp": [0.0] * 3, "TallBox": [0.72] * 3, "ShortBox": [0.72] * 3}
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_specular", "KHR_materials_emissive_strength"]
    for name, tris in groups.items():
        ext = {"KHR_materials_specular": {"specularFactor": 0.0}}
        # doubleSided: the OBJ's surfaces have two sides, and its winding says nothing of which is
        # the front (glTF's default would make every wall vanish seen from behind).
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": colors[name] + [1], "metallicFactor": 0.0,
                                                       "roughnessFactor": 1.0}, "extensions": ext, "doubleSided": True}
        if name == "Lamp":
            mat["emissiveFactor"] = [1.0, 12.0 / 17.0, 4.0 / 17.0]
            ext["KHR_materials_emissive_strength"] = {"emissiveStrength": 17.0}
        used = sorted({i for tri in tris for i in tri})
        local = {v: k for k, v in enumerate(used)}
        pos = [c for v in used for c in verts[v]]
        mesh = g.mesh(pos, None, None, [local[i] for tri in tris for i in tri], g.material(**mat))
        g.node(mesh=mesh, name=name)
    g.node(camera=g.camera(type="perspective", perspective={"yfov": math.radians(45.0), "znear": 0.01}, name="Front"),
           translation=[0.0, 0.0, 3.0], name="Front")
    g.write("cornell_box.gltf")


def striped_wall(g):
    """A blue wall behind the glass scenes' spheres with yellow stripes, to show what refraction
    does to them."""
    wall = g.material(name="Wall", pbrMetallicRoughness={"baseColorFactor": [0.2, 0.3, 0.6, 1], "metallicFactor": 0.0,
                                                          "roughnessFactor": 1.0})
    stripe = g.material(name="Stripe", pbrMetallicRoughness={"baseColorFactor": [0.9, 0.8, 0.2, 1], "metallicFactor": 0.0,
                                                              "roughnessFactor": 1.0})
    g.node(mesh=quad(g, [(-6, 0, -1.5), (6, 0, -1.5), (6, 3, -1.5), (-6, 3, -1.5)], (0, 0, 1), wall, uv=False), name="Wall")
    for k in range(-5, 6):
        x = 0.5 * k
        g.node(mesh=quad(g, [(x - 0.08, 0, -1.49), (x + 0.08, 0, -1.49), (x + 0.08, 3, -1.49), (x - 0.08, 3, -1.49)],
                         (0, 0, 1), stripe, uv=False), name=f"Stripe{k + 5}")


def lamp_and_sun(g):
    """The glass scenes' lights: a point lamp above and in front, a directional light from the front left."""
    lamp = g.light(type="point", color=[1.0, 0.95, 0.9], intensity=6000.0, name="Lamp")
    g.node(extensions={"KHR_lights_punctual": {"light": lamp}}, translation=[1.0, 3.0, 2.0], name="LampNode")
    sun = g.light(type="directional", color=[0.8, 0.85, 1.0], intensity=1000.0, name="Sun")
    g.node(extensions={"KHR_lights_punctual": {"light": sun}}, rotation=look_at_quaternion([0, 0, 0], [-1.0, -2.0, -1.5]),
           name="SunNode")


def glass():
    """KHR_materials_transmission, _volume, _ior and _specular on spheres over a floor, under a
    point light and a white-ish sky of directional light: from the left clear glass, rough glass
    (roughness 0.3), green-tinted glass of ior 1.33, a Lambert sphere (specularFactor 0) and a
    plastic with a blue specular colour."""
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior",
                             "KHR_materials_specular"]
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.8})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    striped_wall(g)
    volume = {"thicknessFactor": 1.0}
    looks = [("ClearGlass", [1, 1, 1], 0.0, {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                               "KHR_materials_volume": volume}),
             ("RoughGlass", [1, 1, 1], 0.3, {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                               "KHR_materials_volume": volume}),
             ("GreenWater", [0.5, 0.9, 0.6], 0.0, {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                                     "KHR_materials_volume": volume, "KHR_materials_ior": {"ior": 1.33}}),
             ("Lambert", [0.8, 0.8, 0.8], 0.5, {"KHR_materials_specular": {"specularFactor": 0.0}}),
             ("BlueSheen", [0.8, 0.3, 0.1], 0.2, {"KHR_materials_specular": {"specularFactor": 1.0,
                                                                             "specularColorFactor": [0.5, 1.0, 6.0]}})]
    for k, (name, color, rough, ext) in enumerate(looks):
        m = g.material(name=name, pbrMetallicRoughness={"baseColorFactor": color + [1], "metallicFactor": 0.0,
                                                          "roughnessFactor": rough}, extensions=ext)
        g.node(mesh=sphere(g, 0.45, m), translation=[-2.0 + k, 0.45, 0.0], name=name)
    lamp_and_sun(g)
    camera_node(g, [0.0, 1.2, 6.0], [0.0, 0.5, 0.0], 30.0, aspect=2.0)
    g.write("glass.gltf")


def volume(lit=True):
    """KHR_materials_volume's absorption and the specular and transmission textures (issue 28) on
    spheres over a floor, before a striped wall, under a point light and a directional light
    (lit), or under the default white environment (volume_white.gltf, the Cycles crosscheck's
    case): from the left clear glass, amber glass (attenuation colour (0.9, 0.5, 0.1) at 0.3),
    rough deep-green glass (0.2, 0.8, 0.4) at 0.2), glass whose transmission texture (R) cuts it
    into bands of glass and white Lambert, and a red plastic whose specularTexture (A, a ramp from
    the top) and specularColorTexture (cyan, white and blue bands) vary its reflection; lit, a
    thin-walled bubble (transmission without a volume) in front."""
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_specular"]
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.8})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    if lit:
        striped_wall(g)
    n = 64
    bands = g.image(png(n, n, 3, lambda x, y: (255 if (y // 8) % 2 else 0, 0, 0)))
    spec = g.image(png(n, n, 4, lambda x, y: (255, 255, 255, int(255 * y / (n - 1)))))
    spec_color = g.image(png(n, n, 3, lambda x, y: [(60, 255, 255), (255, 255, 255), (40, 80, 255)][(x // 16) % 3]))
    def glass(attenuation=None, **more):
        v = {"thicknessFactor": 1.0}
        if attenuation:
            v["attenuationColor"], v["attenuationDistance"] = attenuation
        return {"KHR_materials_transmission": dict({"transmissionFactor": 1.0}, **more), "KHR_materials_volume": v}
    looks = [("Clear", [1, 1, 1], 0.0, glass()),
             ("Amber", [1, 1, 1], 0.0, glass(([0.9, 0.5, 0.1], 0.3))),
             ("RoughGreen", [1, 1, 1], 0.2, glass(([0.2, 0.8, 0.4], 0.2))),
             ("BandedTransmission", [0.8, 0.8, 0.8], 0.0, glass(transmissionTexture={"index": bands})),
             ("SpecularMaps", [0.6, 0.05, 0.05], 0.25, {"KHR_materials_specular": {
                 "specularFactor": 1.0, "specularTexture": {"index": spec},
                 "specularColorFactor": [2.0, 2.0, 2.0], "specularColorTexture": {"index": spec_color}}})]
    for k, (name, color, rough, ext) in enumerate(looks):
        m = g.material(name=name, pbrMetallicRoughness={"baseColorFactor": color + [1], "metallicFactor": 0.0,
                                                          "roughnessFactor": rough}, extensions=ext)
        g.node(mesh=sphere(g, 0.45, m, uv=True), translation=[-2.0 + k, 0.45, 0.0], name=name)
    if lit:
        # A soap bubble before them: transmission without a volume is a thin wall (unbent).
        bubble = g.material(name="ThinBubble", pbrMetallicRoughness={"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0,
                                                                      "roughnessFactor": 0.0},
                            extensions={"KHR_materials_transmission": {"transmissionFactor": 1.0}})
        g.node(mesh=sphere(g, 0.3, bubble), translation=[-1.5, 0.3, 1.3], name="ThinBubble")
        lamp_and_sun(g)
    camera_node(g, [0.0, 1.2, 6.0], [0.0, 0.5, 0.0], 30.0, aspect=2.0)
    g.write("volume.gltf" if lit else "volume_white.gltf")


def metallic_glass():
    """KHR_materials_transmission with metallic (issue 49): from the left smooth, fully transmitting
    spheres of metallic 0, 0.5 and 1 (base colour a pale amber, so that the metal's tint shows)
    over a floor, before the striped wall, under the default white environment. The specification
    mixes a metal mirror and the glass by metallic: the middle one is half of each, clear."""
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_transmission", "KHR_materials_volume"]
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.8})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    striped_wall(g)
    for k, metallic in enumerate([0.0, 0.5, 1.0]):
        m = g.material(name=f"Metallic{metallic}", pbrMetallicRoughness={"baseColorFactor": [1.0, 0.85, 0.6, 1],
                                                                         "metallicFactor": metallic, "roughnessFactor": 0.0},
                       extensions={"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                   "KHR_materials_volume": {"thicknessFactor": 1.0}})
        g.node(mesh=sphere(g, 0.45, m), translation=[-1.1 + 1.1 * k, 0.45, 0.0], name=f"Globe{k}")
    camera_node(g, [0.0, 1.2, 6.0], [0.0, 0.5, 0.0], 30.0, aspect=2.0)
    g.write("metallic_glass_white.gltf")


def sheen(lit=True):
    """KHR_materials_sheen (issue 28) on five spheres over a floor, under an emissive panel and a
    directional light from behind (the sheen shows at grazing angles), or under the default white
    environment (sheen_white.gltf, the Cycles crosscheck's case): from the left a red rough
    dielectric without sheen, the same under a white sheen of roughness 0.3, a dark blue base
    under a pink velvet sheen (roughness 0.8), a black base under a white sheen of roughness 0.5
    (the sheen alone), and a sheen whose colour (bands) and roughness (A, a ramp from the top)
    come from textures over a grey base."""
    g = sphere_row_scene(["KHR_materials_sheen", "KHR_materials_specular"])
    n = 64
    colour = g.image(png(n, n, 3, lambda x, y: [(255, 230, 120), (120, 200, 255)][(x // 8) % 2]))
    rough = g.image(png(n, n, 4, lambda x, y: (255, 255, 255, 20 + int(235 * y / (n - 1)))))
    red = {"baseColorFactor": [0.6, 0.08, 0.08, 1], "metallicFactor": 0.0, "roughnessFactor": 0.8}
    sheen = lambda ext: {"KHR_materials_sheen": ext}
    sphere_row(g, [("Red", red, {}),
                   ("RedSheen", red, sheen({"sheenColorFactor": [1.0, 1.0, 1.0], "sheenRoughnessFactor": 0.3})),
                   ("Velvet", {"baseColorFactor": [0.05, 0.05, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0},
                    sheen({"sheenColorFactor": [1.0, 0.4, 0.7], "sheenRoughnessFactor": 0.8})),
                   ("SheenAlone", {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0.0, "roughnessFactor": 1.0},
                    dict(sheen({"sheenColorFactor": [1.0, 1.0, 1.0], "sheenRoughnessFactor": 0.5}),
                         KHR_materials_specular={"specularFactor": 0.0})),
                   ("TexturedSheen", {"baseColorFactor": [0.3, 0.3, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 0.9},
                    sheen({"sheenColorFactor": [1.0, 1.0, 1.0], "sheenColorTexture": {"index": colour},
                           "sheenRoughnessFactor": 1.0, "sheenRoughnessTexture": {"index": rough}}))])
    light_and_write(g, lit, "sheen", 3.0, [1.0, 0.95, 0.9], 600.0, [0.4, -0.6, 1.5], sun_name="BackLight")  # from behind


def unlit():
    """KHR_materials_unlit (issue 28): an unlit checker billboard and an unlit orange sphere beside a
    lit grey sphere and a mirror sphere, over a floor under a point light. Only camera rays see an
    unlit surface (as Blender's importer makes it): it shows its base colour flat, casts no shadow
    and is missing from the mirror."""
    g = Gltf()
    g.d["extensionsUsed"] = ["KHR_materials_unlit"]
    floor = g.material(name="Floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0.0,
                                                            "roughnessFactor": 0.8})
    g.node(mesh=ground(g, 20, floor), name="Ground")
    n = 64
    checker = g.image(png(n, n, 3, lambda x, y: (40, 120, 200) if (x // 8 + y // 8) % 2 else (230, 200, 60)))
    billboard = g.material(name="UnlitBillboard", pbrMetallicRoughness={"baseColorTexture": {"index": checker}},
                           extensions={"KHR_materials_unlit": {}})
    g.node(mesh=quad(g, [(-2.4, 0.1, -0.5), (-1.2, 0.1, -0.5), (-1.2, 1.3, -0.5), (-2.4, 1.3, -0.5)], (0, 0, 1), billboard),
           name="UnlitBillboard")
    orange = g.material(name="UnlitOrange", pbrMetallicRoughness={"baseColorFactor": [1.0, 0.45, 0.1, 1]},
                        extensions={"KHR_materials_unlit": {}})
    grey = g.material(name="Grey", pbrMetallicRoughness={"baseColorFactor": [0.7, 0.7, 0.7, 1], "metallicFactor": 0.0,
                                                          "roughnessFactor": 0.5})
    mirror = g.material(name="Mirror", pbrMetallicRoughness={"baseColorFactor": [0.95, 0.95, 0.95, 1], "metallicFactor": 1.0,
                                                              "roughnessFactor": 0.0})
    for k, (name, m) in enumerate([("UnlitOrange", orange), ("Grey", grey), ("Mirror", mirror)]):
        g.node(mesh=sphere(g, 0.45, m), translation=[-0.4 + 1.1 * k, 0.45, 0.0], name=name)
    lamp = g.light(type="point", color=[1.0, 0.95, 0.9], intensity=4000.0, name="Lamp")
    g.node(extensions={"KHR_lights_punctual": {"light": lamp}}, translation=[-1.0, 3.0, 2.0], name="LampNode")
    camera_node(g, [0.0, 1.2, 5.0], [0.0, 0.5, 0.0], 35.0, aspect=2.0)
    g.write("unlit.gltf")


if __name__ == "__main__":
    os.makedirs(HERE, exist_ok=True)
    spheres()
    textured()
    plane_lights()
    transforms()
    alpha_modes()
    cameras()
    bin_and_image()
    texture_transform()
    vertex_colors()
    tangents()
    materials()
    cornell_box()
    glass()
    clearcoat()
    clearcoat(lit=False)
    volume()
    volume(lit=False)
    metallic_glass()
    sheen()
    sheen(lit=False)
    unlit()
