#!/usr/bin/env python3
"""Writes the repository's own scenes (OBJ + lab MTL). Run from anywhere: python3 make_scenes.py

cornell_box: the lab's box dimensions ([-1, 1]^3, open towards the camera at z = 3) lit by an
             emissive ceiling quad (Ke) instead of a sphere light, with a tall and a short box.
glass:       the same room with a glass sphere (Fresnel-blended refraction) on a textured floor, a
             metal sphere (Pm 1), and a small sphere light that throws a caustic.
mis_lights:  where each direct-light strategy fails somewhere: a large emissive panel standing on
             a diffuse floor (light sampling by area is noisy next to it, BSDF sampling is not), a
             tiny bright sphere light (BSDF sampling almost never finds it), and a mirror sphere
             and a Fresnel-reflective floor that show both lights.
rough:       rows of spheres, rough metal (Pm 1), plastic and glass, at GGX alpha 0.01, 0.05, 0.2
             and 0.5 from the left, under a small sphere light.
textured:    every texture map of issue 11, one per object so that each can be checked on its
             own, in the same room under a small sphere light (radius 0.05) just in front of it,
             near the ceiling. Camera 0 (Front) looks from higher up than the others, so that the
             floor shows; camera 1 (Shadows) looks down at the cutouts' shadows on the floor. The
             textures are written by this script (tex_*.png, 8 bits, 8 to 16 texels across an
             object, so that a 128x128 render magnifies every texel, 1.5 to 2.2 pixels each).
             Top row, each quad turned to face the half vector between the camera and the light
             so that its highlight sits in its middle, from the left:
               TexKdKs      map_Kd (colour tiles) and map_Ks (white and blue stripes) on a
                            Fresnel-blended plastic (R0 0.1), Pr 0.3;
               TexPr        map_Pr (stripes of Pr 0.15, 0.35, 0.6, 0.85) on a metal (Pm 1);
                            its Pr 0.5 is replaced by the map;
               TexPm        map_Pm (a 0/1 checker) between a red plastic and gold, Pr 0.45; its
                            Pm 0.5 is replaced by the map;
               TexPmChannel the same with map_Pm -imfchan g of tex_channels.png, whose red,
                            green and blue are vertical stripes, horizontal stripes and a checker
                            (green: horizontal stripes of gold).
             Middle row, facing the camera:
               TexNormal    norm: a tangent-space normal map (green up) of 2x2 domes on a white
                            Lambert slab (its sides and back are PanelBack);
               TexBump      bump -bm 0.03: a height map of 2x2 raised tiles on the same slab;
               TexClamp     map_Kd -s 2 2 -o -0.5 -0.5 -clamp on: the colour tiles at half size
                            in the middle, their border texels stretched around them.
             Front, floating above the floor so that their shadows on it show below them
             (the light, in front, is above the objects: shadows fall behind them):
               TexCutout    map_d from the PNG's alpha: a frame with bars and holes;
               TexVeil      d 0.8 with map_d from the alpha: a frame of coverage 0.8, a window
                            of 0.8 * 160/255 = 0.50, an empty window with an opaque dot.
outdoor:     objects on a large ground plane with no light of their own, lit by an environment
             (pt render scenes/outdoor.obj --env scenes/env_sun.exr): from the left a white
             Lambert sphere, a rough gold sphere (Pm 1, alpha 0.05), a glass sphere and a
             red rough plastic box.
sunlit:      outdoor without the glass sphere, lit by its MTL's Preetham sky (an envsky block, sun 30
             degrees high), for the convergence study: a sun seen through glass
             is a caustic that only BSDF sampling finds, and its fireflies would swamp the
             difference that importance sampling the map makes on the other objects.
env_sun.exr: a 256x128 lat-long sky: a gradient from blue at the zenith to pale at the horizon,
             a dim brown ground below it, and a one-texel sun of radiance 6,000 at elevation
             35 degrees towards -z rotated 40 degrees about +y (u = 0.25 + 40/360).
env_marker.exr: a 64x32 black map with marker texels (see ENV_MARKERS) for the convention test.
many_lights: a night square lit by 4,096 small lamps (8,192 emissive triangles, 0.1 wide) in a 64 x 64
             grid 1.2 above a 40 x 40 ground, facing down, in four colours and powers that vary
             across the grid; boxes stand among them and cast shadows, and two rough spheres
             reflect them. Any one point sees a few lamps near it; choosing a lamp by power
             alone wastes nearly every shadow ray on far ones (the light-tree study).
env_probe:   a mirror ball right of centre, for looking at a map: the camera looks along -z, so the
             background in the middle of the image is -z (the red marker of env_marker.exr),
             and the ball reflects +x on its right and +z (behind the camera) near its middle.
"""
import math
import os
import subprocess

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))


class Obj:
    def __init__(self):
        self.v, self.vn, self.vt, self.lines = [], [], [], []

    def use(self, material):
        self.lines.append(f"usemtl {material}")

    def quad(self, a, b, c, d, uv=False):
        """A planar quad with corners in counter-clockwise order seen from the side its normal faces."""
        base = len(self.v)
        self.v += [a, b, c, d]
        if uv:
            tb = len(self.vt)
            self.vt += [(0, 0), (1, 0), (1, 1), (0, 1)]
            self.lines.append("f " + " ".join(f"{base + i + 1}/{tb + i + 1}" for i in range(4)))
        else:
            self.lines.append("f " + " ".join(str(base + i + 1) for i in range(4)))

    def box(self, lo, hi):
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        self.quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1))  # +z
        self.quad((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0))  # -z
        self.quad((x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1))  # +x
        self.quad((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0))  # -x
        self.quad((x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0))  # +y
        self.quad((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1))  # -y

    def sphere(self, center, radius, rings=48, segments=96):
        """UV sphere with smooth vertex normals; quads in the middle, triangles at the poles."""
        cx, cy, cz = center
        base, nbase = len(self.v), len(self.vn)
        for i in range(rings + 1):
            theta = math.pi * i / rings
            for j in range(segments):
                phi = 2 * math.pi * j / segments
                n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
                self.v.append((cx + radius * n[0], cy + radius * n[1], cz + radius * n[2]))
                self.vn.append(n)

        def idx(i, j):
            k = i * segments + (j % segments)
            return f"{base + k + 1}//{nbase + k + 1}"

        for i in range(rings):
            for j in range(segments):
                a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
                if i == 0:
                    self.lines.append(f"f {a} {c} {d}")
                elif i == rings - 1:
                    self.lines.append(f"f {a} {b} {c}")
                else:
                    self.lines.append(f"f {a} {b} {c} {d}")

    def write(self, path, mtllib, header):
        with open(path, "w") as f:
            f.write(f"# {header}\n# Generated by scenes/make_scenes.py; edit that, not this.\n")
            f.write(f"mtllib {mtllib}\n")
            for p in self.v:
                f.write("v %.6f %.6f %.6f\n" % p)
            for n in self.vn:
                f.write("vn %.6f %.6f %.6f\n" % n)
            for t in self.vt:
                f.write("vt %.6f %.6f\n" % t)
            f.write("\n".join(self.lines) + "\n")


def room(o, floor_uv=False):
    """The lab's room: walls at +-1, open at z = +1."""
    o.use("Floor")
    o.quad((-1, -1, 1), (1, -1, 1), (1, -1, -1), (-1, -1, -1), uv=floor_uv)
    o.use("Ceiling")
    o.quad((-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1))
    o.use("BackWall")
    o.quad((-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1))
    o.use("LeftWall")
    o.quad((-1, -1, 1), (-1, -1, -1), (-1, 1, -1), (-1, 1, 1))
    o.use("RightWall")
    o.quad((1, -1, -1), (1, -1, 1), (1, 1, 1), (1, 1, -1))


CAMERA = """newcamera Front
\tcameraposition 0.0 0.0 3.0
\tcameratarget 0.0 0.0 0.0
\tcameraup 0.0 1.0 0.0
\tcamerafov 45.0
"""


def cornell_box():
    o = Obj()
    room(o)
    o.use("Lamp")  # slightly below the ceiling so it does not share its plane
    o.quad((-0.25, 0.999, -0.25), (-0.25, 0.999, 0.25), (0.25, 0.999, 0.25), (0.25, 0.999, -0.25))
    o.use("TallBox")
    o.box((-0.65, -1.0, -0.6), (-0.15, 0.2, -0.1))
    o.use("ShortBox")
    o.box((0.15, -1.0, -0.1), (0.65, -0.45, 0.4))
    o.write(os.path.join(HERE, "cornell_box.obj"), "cornell_box.mtl",
            "Cornell box in the lab's dimensions, lit by an emissive ceiling quad")
    with open(os.path.join(HERE, "cornell_box.mtl"), "w") as f:
        f.write("# Materials in the lab's long keywords; the lamp uses the standard Ke.\n\n")
        f.write(CAMERA + "\n")
        f.write("newmtl Floor\n\tdiffuseReflectance 0.75 0.75 0.75\n\n")
        f.write("newmtl Ceiling\n\tdiffuseReflectance 0.75 0.75 0.75\n\n")
        f.write("newmtl BackWall\n\tdiffuseReflectance 0.75 0.75 0.75\n\n")
        f.write("newmtl LeftWall\n\tdiffuseReflectance 0.63 0.065 0.05\n\n")
        f.write("newmtl RightWall\n\tdiffuseReflectance 0.14 0.45 0.091\n\n")
        f.write("newmtl Lamp\n\tdiffuseReflectance 0.0 0.0 0.0\n\temittance 17.0 12.0 4.0\n\n")
        f.write("newmtl TallBox\n\tdiffuseReflectance 0.72 0.72 0.72\n"
                "\tspecularReflectance 1.0 1.0 1.0\n\treflat0deg 0.05\n\treflat90deg 1.0\n\n")
        f.write("newmtl ShortBox\n\tdiffuseReflectance 0.72 0.72 0.72\n")


def glass():
    o = Obj()
    room(o, floor_uv=True)
    o.use("Glass")
    o.sphere((-0.35, -0.6, 0.1), 0.4)
    o.use("Metal")
    o.sphere((0.5, -0.75, -0.45), 0.25, rings=32, segments=64)
    o.write(os.path.join(HERE, "glass.obj"), "glass.mtl",
            "Glass and metal spheres in the lab's room, lit by a small sphere light")
    with open(os.path.join(HERE, "glass.mtl"), "w") as f:
        f.write("# Materials in the standard short keywords plus the lab's extensions.\n\n")
        f.write("newlight Lamp\n\tlightposition 0.2 0.75 0.3\n\tlightcolor 1.0 0.95 0.85\n"
                "\tlightradius 0.08\n\tlightintensity 2.5\n\n")
        f.write(CAMERA + "\n")
        f.write("newmtl Floor\n\tKd 0.8 0.8 0.8\n\tmap_Kd checker.png\n\n")
        f.write("newmtl Ceiling\n\tKd 0.8 0.8 0.8\n\n")
        f.write("newmtl BackWall\n\tKd 0.7 0.7 0.7\n\n")
        f.write("newmtl LeftWall\n\tKd 0.65 0.25 0.2\n\n")
        f.write("newmtl RightWall\n\tKd 0.2 0.3 0.65\n\n")
        f.write("newmtl Glass\n\tKs 1 1 1\n\treflat0deg 0.04\n\treflat90deg 1.0\n\tTr 1.0\n\tNi 1.5\n\n")
        f.write("newmtl Metal\n\tKd 0.5 0.5 0.5\n\tKs 0.95 0.75 0.45\n\tNi 1.5\n\tPm 1.0\n")
    subprocess.run(["oiiotool", "--pattern", "checker:width=16:height=16:color1=0.9,0.9,0.9:color2=0.25,0.25,0.3",
                    "128x128", "3", "-d", "uint8", "-o", os.path.join(HERE, "checker.png")], check=True)


def mis_lights():
    o = Obj()
    o.use("Floor")
    o.quad((-2, -1, 4), (2, -1, 4), (2, -1, -1.5), (-2, -1, -1.5))
    o.use("BackWall")
    o.quad((-2, -1, -1.5), (2, -1, -1.5), (2, 1.5, -1.5), (-2, 1.5, -1.5))
    o.use("Room")  # closed, so only the two lights light it
    o.quad((-2, 1.5, -1.5), (2, 1.5, -1.5), (2, 1.5, 4), (-2, 1.5, 4))
    o.quad((-2, -1, 4), (-2, -1, -1.5), (-2, 1.5, -1.5), (-2, 1.5, 4))
    o.quad((2, -1, -1.5), (2, -1, 4), (2, 1.5, 4), (2, 1.5, -1.5))
    o.quad((2, -1, 4), (-2, -1, 4), (-2, 1.5, 4), (2, 1.5, 4))
    o.use("Panel")  # facing +x, standing on the floor
    o.quad((-1.1, -1, 0.7), (-1.1, -1, -1.3), (-1.1, 0.6, -1.3), (-1.1, 0.6, 0.7))
    o.use("Mirror")
    o.sphere((0.3, -0.55, -0.5), 0.45)
    o.write(os.path.join(HERE, "mis_lights.obj"), "mis_lights.mtl",
            "A large and a tiny light over diffuse and mirror surfaces: each strategy fails somewhere")
    with open(os.path.join(HERE, "mis_lights.mtl"), "w") as f:
        f.write("# Lab keywords. The room is closed: only the panel and the spark light it.\n\n")
        f.write("newlight Spark\n\tlightposition 1.0 0.2 0.2\n\tlightcolor 1.0 0.9 0.7\n"
                "\tlightradius 0.08\n\tlightintensity 1.5\n\n")
        f.write("newcamera Front\n\tcameraposition 0.0 0.4 3.4\n\tcameratarget 0.0 -0.4 -0.3\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 45.0\n\n")
        f.write("newmtl Floor\n\tdiffuseReflectance 0.6 0.6 0.6\n\treflat0deg 0.04\n\treflat90deg 1.0\n\n")
        f.write("newmtl BackWall\n\tdiffuseReflectance 0.5 0.55 0.6\n\n")
        f.write("newmtl Room\n\tdiffuseReflectance 0.4 0.4 0.4\n\n")
        f.write("newmtl Panel\n\tdiffuseReflectance 0.0 0.0 0.0\n\temittance 1.2 1.1 0.9\n\n")
        f.write("newmtl Mirror\n\tdiffuseReflectance 0.0 0.0 0.0\n\tspecularReflectance 0.9 0.9 0.9\n"
                "\treflat0deg 1.0\n\treflat90deg 1.0\n")


ROUGH_ALPHAS = (0.01, 0.05, 0.2, 0.5)


def rough():
    o = Obj()
    room(o)
    rows = (("Metal", 0.5), ("Plastic", 0.0), ("Glass", -0.5))  # (material family, height)
    for family, y in rows:
        for k, alpha in enumerate(ROUGH_ALPHAS):
            o.use("%s%d" % (family, k))
            o.sphere((-0.66 + 0.44 * k, y, -0.3), 0.19, rings=24, segments=48)
    o.write(os.path.join(HERE, "rough.obj"), "rough.mtl",
            "Rough metal, plastic and glass at alpha 0.01, 0.05, 0.2 and 0.5 under a small sphere light")
    with open(os.path.join(HERE, "rough.mtl"), "w") as f:
        f.write("# Rows from the top: metal (Pm 1), plastic (a Fresnel-blended Lambert), glass; columns\n"
                "# from the left: specularroughness (GGX alpha) 0.01, 0.05, 0.2, 0.5.\n\n")
        f.write("newlight Lamp\n\tlightposition 0.0 0.7 0.7\n\tlightcolor 1.0 0.95 0.85\n"
                "\tlightradius 0.06\n\tlightintensity 2.0\n\n")
        f.write(CAMERA + "\n")
        f.write("newmtl Floor\n\tKd 0.7 0.7 0.7\n\n")
        f.write("newmtl Ceiling\n\tKd 0.8 0.8 0.8\n\n")
        f.write("newmtl BackWall\n\tKd 0.6 0.6 0.6\n\n")
        f.write("newmtl LeftWall\n\tKd 0.65 0.25 0.2\n\n")
        f.write("newmtl RightWall\n\tKd 0.2 0.3 0.65\n\n")
        for k, alpha in enumerate(ROUGH_ALPHAS):
            f.write("newmtl Metal%d\n\tKd 0 0 0\n\tKs 0.95 0.75 0.45\n\tNi 1.5\n\tPm 1.0\n"
                    "\tspecularroughness %g\n\n" % (k, alpha))
            f.write("newmtl Plastic%d\n\tKd 0.6 0.15 0.1\n\treflat0deg 0.05\n\treflat90deg 1.0\n"
                    "\tspecularroughness %g\n\n" % (k, alpha))
            f.write("newmtl Glass%d\n\tKs 1 1 1\n\treflat0deg 0.04\n\treflat90deg 1.0\n\tTr 1.0\n"
                    "\tNi 1.5\n\tspecularroughness %g\n\n" % (k, alpha))


TEXTURED_HEADER = """# Texture maps of issue 11, one per object. Top row (facing the camera-light half vector):
# TexKdKs (map_Kd + map_Ks), TexPr (map_Pr), TexPm (map_Pm), TexPmChannel (map_Pm -imfchan g).
# Middle row: TexNormal (norm), TexBump (bump -bm), TexClamp (map_Kd -s -o -clamp on).
# Front: TexCutout (map_d, binary alpha), TexVeil (d 0.8 times map_d, with a 0.5 window).
"""


def write_png(name, pixels):
    """An 8-bit PNG next to this script from a (height, width, channels) uint8 array, row 0 on top."""
    pixels = np.ascontiguousarray(pixels, dtype=np.uint8)
    h, w, c = pixels.shape
    path = os.path.join(HERE, name)
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, oiio.ImageSpec(w, h, c, oiio.UINT8)) or not out.write_image(pixels):
        raise SystemExit(f"make_scenes: cannot write {path}: {out.geterror() if out else oiio.geterror()}")
    out.close()


def texel_uv(w, h):
    """The uv of each texel's centre, v = 0 at the bottom row as in OBJ: arrays of shape (h, w)."""
    u = (np.arange(w) + 0.5) / w
    v = 1.0 - (np.arange(h) + 0.5) / h
    return np.meshgrid(u, v)


def textured_textures():
    # Colour tiles: 4x4 cells of 2x2 texels, each its own colour (sRGB-encoded values).
    palette = np.array([[230, 60, 50], [250, 200, 40], [60, 170, 70], [40, 110, 220],
                        [240, 240, 240], [30, 30, 35], [200, 90, 200], [90, 220, 220],
                        [150, 90, 40], [250, 140, 170], [120, 120, 120], [20, 80, 40],
                        [255, 120, 0], [100, 60, 180], [200, 230, 120], [10, 40, 110]])
    y, x = np.mgrid[0:8, 0:8]
    write_png("tex_albedo.png", palette[(y // 2) * 4 + x // 2])
    # Specular colour: horizontal stripes of white and blue, 2 texels each.
    stripes = np.where(((y // 2) % 2 == 0)[..., None], [255, 255, 255], [40, 80, 230])
    write_png("tex_spec.png", stripes)
    # Perceptual roughness: vertical stripes of Pr 0.15, 0.35, 0.6, 0.85 (GGX alpha 0.02 to 0.72).
    pr = np.round(np.array([0.15, 0.35, 0.6, 0.85]) * 255)[x // 2]
    write_png("tex_rough.png", pr[..., None])
    # Metallic: a checker of 2x2-texel cells, 0 and 1.
    checker = ((x // 2 + y // 2) % 2) * 255
    write_png("tex_metal.png", checker[..., None])
    # Three different data channels: red vertical stripes, green horizontal stripes, blue checker.
    write_png("tex_channels.png", np.stack([((x // 2) % 2) * 255, ((y // 2) % 2) * 255, checker], axis=-1))
    # Normal map: 2x2 domes h = A cos^2(pi r / 2R) per cell (cell units), tilting up to 40 degrees;
    # n = normalize(-dh/du, -dh/dv, 1), x along +u, y along +v (green up), stored as (n + 1) / 2.
    u, v = texel_uv(16, 16)
    fx, fy = (u * 2) % 1 - 0.5, (v * 2) % 1 - 0.5
    r, radius = np.hypot(fx, fy), 0.42
    amp = math.tan(math.radians(40)) * 2 * radius / math.pi
    dhdr = np.where(r < radius, -amp * math.pi / (2 * radius) * np.sin(math.pi * r / radius), 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        gx = np.where(r > 0, dhdr * fx / r, 0.0)
        gy = np.where(r > 0, dhdr * fy / r, 0.0)
    n = np.stack([-gx, -gy, np.ones_like(gx)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    write_png("tex_normal.png", np.round((n + 1) / 2 * 255))
    # Height map: 2x2 raised tiles (1) with one-texel grout lines (0) at texels 0 and 8.
    y, x = np.mgrid[0:16, 0:16]
    write_png("tex_height.png", (np.where((x % 8 == 0) | (y % 8 == 0), 0, 255))[..., None])
    # Cutouts, 16x10 texels, coverage in the alpha channel.
    y, x = np.mgrid[0:10, 0:16]
    frame = (x <= 1) | (x >= 14) | (y <= 1) | (y >= 8)
    bars = frame | (x == 7) | (x == 8)
    grid = np.where(bars, 255, 0)
    green = [np.full_like(grid, c) for c in (70, 150, 60)]
    write_png("tex_grid.png", np.stack(green + [grid], -1))
    veil = np.where(bars, 255, np.where(x < 7, 160, np.where((x >= 11) & (x <= 12) & (y >= 4) & (y <= 5), 255, 0)))
    write_png("tex_veil.png", np.stack([np.full_like(veil, 230)] * 3 + [veil], -1))


def facing_quad(o, center, normal, width, height):
    """A quad with uvs (u to the right, v up) centred on `center`, facing `normal`."""
    c, n = np.array(center, dtype=float), np.array(normal, dtype=float)
    n /= np.linalg.norm(n)
    u = np.cross([0.0, 1.0, 0.0], n)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    du, dv = u * width / 2, v * height / 2
    o.quad(*(tuple(p) for p in (c - du - dv, c + du - dv, c + du + dv, c - du + dv)), uv=True)


def slab(o, material, lo, hi):
    """A thin box whose front (+z) face has uvs and `material`; the other faces are PanelBack."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    o.use(material)
    o.quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1), uv=True)
    o.use("PanelBack")
    o.quad((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0))
    o.quad((x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1))
    o.quad((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0))
    o.quad((x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0))
    o.quad((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1))


TEXTURED_LIGHT = (-0.1, 0.9, 1.1)
TEXTURED_CAMERA = ((0.0, 0.6, 3.0), (0.0, -0.25, 0.0))  # position, target: the floor in view


def textured():
    textured_textures()
    o = Obj()
    room(o)
    camera, light = np.array(TEXTURED_CAMERA[0]), np.array(TEXTURED_LIGHT)
    for k, name in enumerate(("TexKdKs", "TexPr", "TexPm", "TexPmChannel")):
        center = np.array([-0.72 + 0.48 * k, 0.62, -0.75])
        to_cam, to_light = camera - center, light - center
        half = to_cam / np.linalg.norm(to_cam) + to_light / np.linalg.norm(to_light)
        o.use(name)
        facing_quad(o, center, half, 0.44, 0.44)
    slab(o, "TexNormal", (-0.94, -0.14, -0.77), (-0.34, 0.34, -0.75))
    slab(o, "TexBump", (-0.3, -0.14, -0.77), (0.3, 0.34, -0.75))
    o.use("TexClamp")
    o.quad((0.34, -0.14, -0.75), (0.94, -0.14, -0.75), (0.94, 0.34, -0.75), (0.34, 0.34, -0.75), uv=True)
    o.use("TexCutout")
    o.quad((-0.66, -0.42, 0.15), (-0.04, -0.42, 0.15), (-0.04, 0.0, 0.15), (-0.66, 0.0, 0.15), uv=True)
    o.use("TexVeil")
    o.quad((0.04, -0.42, 0.15), (0.66, -0.42, 0.15), (0.66, 0.0, 0.15), (0.04, 0.0, 0.15), uv=True)
    o.write(os.path.join(HERE, "textured.obj"), "textured.mtl",
            "One object per texture map of issue 11 in the lab's room, under a sphere light")
    with open(os.path.join(HERE, "textured.mtl"), "w") as f:
        f.write(TEXTURED_HEADER + "\n")
        f.write("newlight Lamp\n\tlightposition %g %g %g\n\tlightcolor 1.0 0.95 0.85\n"
                "\tlightradius 0.05\n\tlightintensity 2.0\n\n" % TEXTURED_LIGHT)
        f.write("newcamera Front\n\tcameraposition %g %g %g\n\tcameratarget %g %g %g\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 45.0\n\n" % (*TEXTURED_CAMERA[0], *TEXTURED_CAMERA[1]))
        # Looking down from behind the cutouts at their shadows on the floor.
        f.write("newcamera Shadows\n\tcameraposition 0.0 0.2 -0.45\n\tcameratarget 0.0 -1.0 -0.4\n"
                "\tcameraup 0.0 0.0 -1.0\n\tcamerafov 70.0\n\n")
        f.write("newmtl Floor\n\tKd 0.7 0.7 0.7\n\n")
        f.write("newmtl Ceiling\n\tKd 0.8 0.8 0.8\n\n")
        f.write("newmtl BackWall\n\tKd 0.6 0.6 0.6\n\n")
        f.write("newmtl LeftWall\n\tKd 0.65 0.25 0.2\n\n")
        f.write("newmtl RightWall\n\tKd 0.2 0.3 0.65\n\n")
        f.write("newmtl PanelBack\n\tKd 0.5 0.5 0.5\n\n")
        f.write("newmtl TexKdKs\n\tKd 0.7 0.7 0.7\n\tmap_Kd tex_albedo.png\n\tKs 1 1 1\n"
                "\tmap_Ks tex_spec.png\n\treflat0deg 0.1\n\treflat90deg 1.0\n\tPr 0.3\n\n")
        f.write("newmtl TexPr\n\tKd 0 0 0\n\tKs 0.9 0.9 0.9\n\tNi 1.5\n\tPm 1.0\n\tPr 0.5\n"
                "\tmap_Pr tex_rough.png\n\n")
        f.write("newmtl TexPm\n\tKd 0.6 0.15 0.1\n\tKs 0.95 0.75 0.45\n\tNi 1.5\n\tPr 0.45\n\tPm 0.5\n"
                "\tmap_Pm tex_metal.png\n\n")
        f.write("newmtl TexPmChannel\n\tKd 0.6 0.15 0.1\n\tKs 0.95 0.75 0.45\n\tNi 1.5\n\tPr 0.45\n"
                "\tmap_Pm -imfchan g tex_channels.png\n\n")
        f.write("newmtl TexNormal\n\tKd 0.75 0.75 0.75\n\tnorm tex_normal.png\n\n")
        f.write("newmtl TexBump\n\tKd 0.75 0.75 0.75\n\tbump -bm 0.03 tex_height.png\n\n")
        f.write("newmtl TexClamp\n\tKd 1 1 1\n\tmap_Kd -s 2 2 -o -0.5 -0.5 -clamp on tex_albedo.png\n\n")
        f.write("newmtl TexCutout\n\tKd 0.25 0.55 0.2\n\tmap_d tex_grid.png\n\n")
        f.write("newmtl TexVeil\n\tKd 0.8 0.75 0.6\n\td 0.8\n\tmap_d tex_veil.png\n")


def write_exr(name, pixels):
    """A half-float EXR next to this script from a (height, width, 3) array, row 0 on top."""
    pixels = np.ascontiguousarray(pixels, dtype=np.float32)
    h, w, c = pixels.shape
    path = os.path.join(HERE, name)
    out = oiio.ImageOutput.create(path)
    spec = oiio.ImageSpec(w, h, c, oiio.HALF)
    spec.attribute("compression", "zip")
    spec.attribute("DateTime", "2026:01:01 00:00:00")  # a fixed stamp: rerunning the script changes no file
    if not out or not out.open(path, spec) or not out.write_image(pixels):
        raise SystemExit(f"make_scenes: cannot write {path}: {out.geterror() if out else oiio.geterror()}")
    out.close()


# Texels (columns x and x + 1, row y) of each marker of env_marker.exr and its colour. With the
# convention of renderer/environment/environment_map.h, the edge between columns x and x + 1 of 64 looks
# along phi = 2 pi ((x + 1) / 64 - 0.5) from +x towards +z, and row y of 32 at
# theta = pi (y + 0.5) / 32 from +y.
ENV_MARKERS = (
    (15, 15, (8.0, 0.0, 0.0)),   # red: just above the horizon, a quarter of the way across: -z
    (31, 15, (0.0, 8.0, 0.0)),   # green: the centre: +x
    (47, 15, (0.0, 0.0, 8.0)),   # blue: three quarters across: +z
    (31, 4, (8.0, 8.0, 0.0)),    # yellow: high above +x
)


def env_maps():
    w, h = 256, 128
    theta = (np.arange(h) + 0.5) / h * np.pi
    up = np.cos(theta)[:, None, None] * np.ones((1, w, 1))
    zenith, horizon, ground = np.array([0.25, 0.4, 0.9]), np.array([0.9, 0.95, 1.0]), np.array([0.12, 0.09, 0.06])
    t = np.clip(up, 0.0, 1.0) ** 0.5
    sky = horizon * (1 - t) + zenith * t
    img = np.where(up > 0, sky, ground * np.ones((h, w, 3)))
    elevation, azimuth = 35.0, 40.0
    sx = int((0.25 + azimuth / 360.0) * w)
    sy = int((90.0 - elevation) / 180.0 * h)
    img[sy, sx] = (6000.0, 5600.0, 4800.0)
    write_exr("env_sun.exr", img)
    marker = np.zeros((32, 64, 3))
    for x, y, c in ENV_MARKERS:
        marker[y, x] = marker[y, x + 1] = c
    write_exr("env_marker.exr", marker)


def env_probe():
    o = Obj()
    o.use("Mirror")
    o.sphere((1.1, 0.0, 0.0), 0.7, rings=48, segments=96)
    o.write(os.path.join(HERE, "env_probe.obj"), "env_probe.mtl",
            "A mirror ball for looking at environment maps (pt render --env)")
    with open(os.path.join(HERE, "env_probe.mtl"), "w") as f:
        f.write("newcamera AlongMinusZ\n\tcameraposition 0.0 0.0 4.0\n\tcameratarget 0.0 0.0 0.0\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 60.0\n\n")
        f.write("newmtl Mirror\n\tKd 0 0 0\n\tKs 1 1 1\n\treflat0deg 1.0\n\treflat90deg 1.0\n")


def outdoor(name="outdoor", glass=True, sky=None):
    o = Obj()
    o.use("Ground")
    o.quad((-30, 0, 30), (30, 0, 30), (30, 0, -30), (-30, 0, -30))
    o.use("White")
    o.sphere((-1.5, 0.5, 0.0), 0.5, rings=24, segments=48)
    o.use("Gold")
    o.sphere((-0.4, 0.5, -0.6), 0.5, rings=24, segments=48)
    if glass:
        o.use("Glass")
        o.sphere((0.7, 0.5, 0.2), 0.5, rings=24, segments=48)
    o.use("RedBox")
    o.box((1.4, 0.0, -1.2), (2.2, 0.8, -0.4))
    o.write(os.path.join(HERE, name + ".obj"), name + ".mtl",
            "Objects on a ground plane, no lights: render with --env (scenes/env_sun.exr) or the lab sky")
    with open(os.path.join(HERE, name + ".mtl"), "w") as f:
        if sky:
            f.write("# No light sources: the Preetham sky and its sun light the scene (--env or --sky replace it).\n\n")
            f.write("newenvironment Afternoon\n\tenvsky\n" + "".join("\t%s %s\n" % kv for kv in sky) + "\n")
        else:
            f.write("# No light sources: an environment map lights the scene (pt render --env).\n\n")
        f.write("newcamera Front\n\tcameraposition 0.0 1.6 5.5\n\tcameratarget 0.2 0.4 0.0\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 40.0\n\n")
        f.write("newmtl Ground\n\tKd 0.5 0.5 0.5\n\n")
        f.write("newmtl White\n\tKd 0.8 0.8 0.8\n\n")
        f.write("newmtl Gold\n\tKd 0 0 0\n\tKs 0.95 0.75 0.45\n\tNi 1.5\n\tPm 1.0\n\tspecularroughness 0.05\n\n")
        f.write("newmtl Glass\n\tKs 1 1 1\n\treflat0deg 0.04\n\treflat90deg 1.0\n\tTr 1.0\n\tNi 1.5\n\n")
        f.write("newmtl RedBox\n\tKd 0.6 0.1 0.08\n\treflat0deg 0.05\n\treflat90deg 1.0\n"
                "\tspecularroughness 0.2\n")


def many_lights(n=64, size=40.0, lamp=0.1, height=1.2):
    o = Obj()
    o.use("Ground")
    h = size / 2
    o.quad((-h, 0, h), (h, 0, h), (h, 0, -h), (-h, 0, -h))
    o.use("Night")  # a black dome: the lamps are the only light
    o.quad((-h, 30, -h), (h, 30, -h), (h, 30, h), (-h, 30, h))
    for a, b in [((-h, -h), (h, -h)), ((h, -h), (h, h)), ((h, h), (-h, h)), ((-h, h), (-h, -h))]:
        o.quad((a[0], 0, a[1]), (b[0], 0, b[1]), (b[0], 30, b[1]), (a[0], 30, a[1]))
    o.use("Stone")
    for lo, hi in [((-1.0, 0, -2.0), (0.0, 0.8, -1.0)), ((1.5, 0, -4.0), (2.2, 2.0, -3.2)),
                   ((-3.0, 0, -6.0), (-2.0, 0.5, -3.0)), ((3.0, 0, 1.0), (3.6, 0.9, 1.6))]:
        o.box(lo, hi)
    o.use("RoughMetal")
    o.sphere((0.8, 0.5, -0.8), 0.5, rings=24, segments=48)
    o.use("RoughPlastic")
    o.sphere((-1.8, 0.4, 0.2), 0.4, rings=24, segments=48)
    step = size / n
    for i in range(n):
        for j in range(n):
            # Colours and powers in a pattern that does not repeat with the rows.
            o.use("Lamp%d" % ((i * 3 + j * 5 + (i * j) % 7) % 4))
            x, z, r = -h + (i + 0.5) * step, -h + (j + 0.5) * step, lamp / 2
            o.quad((x - r, height, z - r), (x + r, height, z - r), (x + r, height, z + r), (x - r, height, z + r))
    o.write(os.path.join(HERE, "many_lights.obj"), "many_lights.mtl",
            "A night square under 4,096 small lamps: the light-tree study")
    with open(os.path.join(HERE, "many_lights.mtl"), "w") as f:
        f.write("# 8,192 emissive triangles and no other light: a black box closes the scene.\n\n")
        f.write("newcamera Front\n\tcameraposition 0.0 2.2 5.0\n\tcameratarget 0.0 0.3 -2.0\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 50.0\n\n")
        f.write("newmtl Ground\n\tKd 0.5 0.5 0.5\n\n")
        f.write("newmtl Night\n\tKd 0 0 0\n\n")
        f.write("newmtl Stone\n\tKd 0.6 0.55 0.5\n\n")
        f.write("newmtl RoughMetal\n\tKd 0 0 0\n\tKs 0.9 0.9 0.9\n\tNi 1.5\n\tPm 1.0\n\tspecularroughness 0.15\n\n")
        f.write("newmtl RoughPlastic\n\tKd 0.1 0.3 0.6\n\treflat0deg 0.05\n\treflat90deg 1.0\n"
                "\tspecularroughness 0.1\n\n")
        for k, ke in enumerate([(12, 11, 9), (18, 9, 4), (6, 9, 15), (36, 33, 27)]):
            f.write("newmtl Lamp%d\n\tKd 0 0 0\n\tKe %d %d %d\n\n" % ((k,) + ke))


def lamp_shaft():
    """A closed room whose lamp sits at the bottom of a narrow shaft: the room is lit by the patch
    of ceiling the shaft throws light on, which next-event estimation cannot aim at and a
    cosine-weighted bounce finds by chance. Where path guiding (--guide) pays."""
    o = Obj()
    room(o)
    # The room is closed behind the camera, so that no sky comes in.
    o.use("BackWall")
    o.quad((-1, -1, 1.5), (-1, 1, 1.5), (1, 1, 1.5), (1, -1, 1.5))
    o.use("LeftWall")
    o.quad((-1, -1, 1.5), (-1, -1, 1), (-1, 1, 1), (-1, 1, 1.5))
    o.use("RightWall")
    o.quad((1, -1, 1), (1, -1, 1.5), (1, 1, 1.5), (1, 1, 1))
    o.use("Floor")
    o.quad((-1, -1, 1.5), (1, -1, 1.5), (1, -1, 1), (-1, -1, 1))
    o.use("Ceiling")
    o.quad((-1, 1, 1), (1, 1, 1), (1, 1, 1.5), (-1, 1, 1.5))
    # The shaft: four walls, both sides, 0.3 wide and 1.2 tall, open at the top.
    o.use("Shaft")
    x0, x1, y0, y1 = -0.15, 0.15, -1.0, 0.2
    corners = [(x0, x1), (x1, x1), (x1, x0), (x0, x0)]
    for i in range(4):
        (ax, az), (bx, bz) = corners[i], corners[(i + 1) % 4]
        o.quad((ax, y0, az), (bx, y0, bz), (bx, y1, bz), (ax, y1, az))
        o.quad((bx, y0, bz), (ax, y0, az), (ax, y1, az), (bx, y1, bz))
    o.write(os.path.join(HERE, "lamp_shaft.obj"), "lamp_shaft.mtl",
            "A room lit through a narrow shaft from a lamp at its bottom (path guiding's case)")
    with open(os.path.join(HERE, "lamp_shaft.mtl"), "w") as f:
        f.write("# Materials in the standard short keywords plus the lab's extensions.\n\n")
        f.write("newlight Lamp\n\tlightposition 0.0 -0.9 0.0\n\tlightcolor 1.0 0.95 0.85\n"
                "\tlightradius 0.03\n\tlightintensity 40\n\n")
        f.write("newcamera Inside\n\tcameraposition 0.0 0.0 1.45\n\tcameratarget 0.0 0.0 0.0\n"
                "\tcameraup 0.0 1.0 0.0\n\tcamerafov 70.0\n\n")
        f.write("newmtl Floor\n\tKd 0.7 0.7 0.7\n\n")
        f.write("newmtl Ceiling\n\tKd 0.8 0.8 0.8\n\n")
        f.write("newmtl BackWall\n\tKd 0.7 0.7 0.7\n\n")
        f.write("newmtl LeftWall\n\tKd 0.65 0.25 0.2\n\n")
        f.write("newmtl RightWall\n\tKd 0.2 0.3 0.65\n\n")
        f.write("newmtl Shaft\n\tKd 0.5 0.5 0.5\n")


if __name__ == "__main__":
    cornell_box()
    glass()
    mis_lights()
    rough()
    textured()
    env_maps()
    env_probe()
    outdoor()
    many_lights()
    lamp_shaft()
    outdoor("sunlit", glass=False, sky=(("sunelevation", 30), ("sunazimuth", 220), ("turbidity", 3)))
