#!/usr/bin/env python3
"""Renders a lab scene (OBJ + extended MTL) with Mitsuba 3, as an independent check of pt.

The lab semantics are rebuilt from the text of issue 2, not from pt's code: sphere lights of
radiance I / (pi r^2), the two-colour sky and ground, a pinhole camera with a vertical field of
view and a box pixel filter, and the lab material tree as a Mitsuba BSDF written here in Python:

    f  = w * FresnelBlend(R0)[Spec(Ks), B1] + (1 - w) * B1,  B1 = T * Refr(eta) + (1 - T) * Lambert(Kd)

with Schlick's F = R0 + (1 - R0)(1 - |cos|)^5. Only what the three lab scenes use is read; any
other keyword stops the script rather than being rendered differently from pt.

The image is the mean of PASSES independent renders; the spread between passes gives the
variance of that mean, written as the `variance` layer pt diff reads. Run it with
tools/crosscheck/run, which installs Mitsuba into a virtual environment.
"""
import argparse
import math
import os
import sys
import tempfile

import numpy as np

import drjit as dr
import mitsuba as mi

mi.set_variant("llvm_ad_rgb")

SKY = (0.5, 0.6, 0.7)
GROUND = (0.05, 0.025, 0.001)


def fail(msg):
    sys.exit(f"mitsuba_lab: {msg}")


# ---------------------------------------------------------------- scene text
def parse_mtl(path):
    materials, lights, cameras = {}, [], []
    cur = None
    for lineno, raw in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
        t = raw.split("#", 1)[0].split()
        if not t:
            continue
        key, vals = t[0].lower(), t[1:]
        num = lambda: [float(v) for v in vals]
        if key == "newmtl":
            cur = {"kd": [0.7] * 3, "ks": [1.0] * 3, "r0": 0.0, "w": 0.0, "t": 0.0, "eta": 1.0, "pm": None,
                   "map_kd": None}
            materials[vals[0]] = cur
        elif key == "newlight":
            cur = {"pos": None, "color": [1, 1, 1], "radius": 0.0, "intensity": 1.0}
            lights.append(cur)
        elif key == "newcamera":
            cur = {"name": vals[0]}
            cameras.append(cur)
        elif key in ("kd", "diffusereflectance"):
            cur["kd"] = num()
        elif key in ("ks", "specularreflectance"):
            cur["ks"] = num()
        elif key == "reflat0deg":
            cur["r0"] = num()[0]
        elif key == "reflat90deg":
            cur["w"] = num()[0]
        elif key in ("transparency", "tr"):
            cur["t"] = num()[0]
        elif key == "d":
            cur["t"] = 1.0 - num()[0]
        elif key in ("indexofrefraction", "ni"):
            cur["eta"] = num()[0]
        elif key == "pm":
            cur["pm"] = num()[0]
        elif key in ("map_kd", "diffusereflectancemap"):
            cur["map_kd"] = os.path.join(os.path.dirname(path), vals[-1])
        elif key == "specularroughness":
            if num()[0] > 0.001:
                fail(f"{path}:{lineno}: rough lobes are outside what this check models")
        elif key == "lightposition":
            cur["pos"] = num()
        elif key == "lightcolor":
            cur["color"] = num()
        elif key == "lightradius":
            cur["radius"] = num()[0]
        elif key == "lightintensity":
            cur["intensity"] = num()[0]
        elif key in ("cameraposition", "cameratarget", "cameraup"):
            cur[key[6:]] = num()
        elif key == "camerafov":
            cur["fov"] = num()[0]
        else:
            fail(f"{path}:{lineno}: keyword {t[0]!r} is outside what this check models")
    for m in materials.values():  # the Pm rule of issue 2
        if m["pm"] is not None:
            f0 = ((m["eta"] - 1) / (m["eta"] + 1)) ** 2
            r0 = [f0 + (k - f0) * m["pm"] for k in m["ks"]]
            if max(r0) - min(r0) > 1e-6:
                fail("a coloured R0 is outside what this check models")
            m.update(r0=r0[0], w=1.0, ks=[1.0] * 3, kd=[k * (1 - m["pm"]) for k in m["kd"]])
    return materials, lights, cameras


def parse_obj(path):
    """Returns the mtllib path and, per material, flat arrays of corner positions, normals and uvs."""
    v, vt, vn, groups, mtllib, mat = [], [], [], {}, None, None
    index = lambda i, n: i - 1 if i > 0 else n + i
    for lineno, raw in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
        t = raw.split("#", 1)[0].split()
        if not t:
            continue
        if t[0] == "v":
            v.append([float(x) for x in t[1:4]])
        elif t[0] == "vt":
            vt.append([float(x) for x in t[1:3]])
        elif t[0] == "vn":
            vn.append([float(x) for x in t[1:4]])
        elif t[0] == "f":
            corners = []
            for c in t[1:]:
                parts = c.split("/")
                ti = int(parts[1]) if len(parts) > 1 and parts[1] else 0
                ni = int(parts[2]) if len(parts) > 2 and parts[2] else 0
                corners.append((index(int(parts[0]), len(v)), index(ti, len(vt)) if ti else None,
                                index(ni, len(vn)) if ni else None))
            g = groups.setdefault(mat, ([], [], []))
            p = [np.array(v[c[0]]) for c in corners]
            face_n = np.cross(p[1] - p[0], p[2] - p[0])
            face_n = face_n / (np.linalg.norm(face_n) or 1.0)
            for k in range(1, len(corners) - 1):  # fan triangulation
                for c in (corners[0], corners[k], corners[k + 1]):
                    g[0].append(v[c[0]])
                    g[1].append(vn[c[2]] if c[2] is not None else face_n.tolist())
                    g[2].append(vt[c[1]] if c[1] is not None else [0.0, 0.0])
        elif t[0] == "usemtl":
            mat = t[1]
        elif t[0] == "mtllib":
            mtllib = os.path.join(os.path.dirname(path), t[1])
        elif t[0] in ("g", "o", "s"):
            pass
        else:
            fail(f"{path}:{lineno}: {t[0]!r} is outside what this check models")
    return mtllib, groups


def write_ply(path, positions, normals, uvs):
    pos = np.asarray(positions, dtype="<f4")
    # OBJ puts v = 0 at the bottom of the image, Mitsuba's bitmaps at the top.
    uv = np.asarray(uvs, dtype="<f4") * [1, -1] + [0, 1]
    nrm = np.asarray(normals, dtype="<f4")
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    n = len(pos)
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {n}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "property float nx\nproperty float ny\nproperty float nz\n"
                 "property float u\nproperty float v\n"
                 f"element face {n // 3}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        f.write(np.hstack([pos, nrm, uv]).astype("<f4").tobytes())
        faces = np.zeros(n // 3, dtype=[("c", "u1"), ("i", "<i4", 3)])
        faces["c"] = 3
        faces["i"] = np.arange(n, dtype="<i4").reshape(-1, 3)
        f.write(faces.tobytes())


# ---------------------------------------------------------------- the lab BSDF
class LabBsdf(mi.BSDF):
    """The lab tree with gray lobe weights; two-sided: the frame is mirrored to wi's side."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.kd = mi.Color3f(props["kd_r"], props["kd_g"], props["kd_b"])
        self.ks = mi.Color3f(props["ks_r"], props["ks_g"], props["ks_b"])
        self.r0, self.w, self.t, self.eta = props["r0"], props["w"], props["t"], props["eta"]
        self.kd_map = props["kd_map"] if "kd_map" in props else None
        self.pt_normals = bool(props["pt_normals"])
        both = mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide
        self.m_components = [mi.BSDFFlags.DeltaReflection | both,
                             mi.BSDFFlags.DeltaTransmission | mi.BSDFFlags.DeltaReflection | both,
                             mi.BSDFFlags.DiffuseReflection | both]
        flags = mi.BSDFFlags.DeltaReflection | both
        if self.t > 0:
            flags |= mi.BSDFFlags.DeltaTransmission
        if self.t < 1:
            flags |= mi.BSDFFlags.DiffuseReflection
        self.m_flags = flags

    def lobe_probs(self, cos_i):
        f = self.w * (self.r0 + (1 - self.r0) * dr.power(1 - cos_i, 5))
        return f, (1 - f) * self.t, (1 - f) * (1 - self.t)

    def kd_at(self, si, active):
        return self.kd if self.kd_map is None else self.kd * self.kd_map.eval(si, active)

    def frame(self, si):
        """The scattering frame, in Mitsuba's shading-frame coordinates, and the geometric normal.

        Plain Mitsuba scatters about the interpolated normal, whatever the geometry says. With
        pt_normals, pt's two rules for smooth meshes: where the viewer is behind the shading
        normal's side of the geometric surface, scatter about the geometric normal; and a
        direction whose side differs between the two normals carries nothing.
        """
        n = dr.select(dr.dot(si.n, si.sh_frame.n) < 0, -si.n, si.n)
        ng = si.to_local(n)
        ident = mi.Frame3f(mi.Vector3f(1, 0, 0), mi.Vector3f(0, 1, 0), mi.Vector3f(0, 0, 1))
        if not self.pt_normals:
            return ident, ng
        use_ng = si.wi.z * dr.dot(si.wi, ng) <= 0
        fg = mi.Frame3f(ng)
        return mi.Frame3f(dr.select(use_ng, fg.s, ident.s), dr.select(use_ng, fg.t, ident.t),
                          dr.select(use_ng, fg.n, ident.n)), ng

    def consistent(self, w_local, w_frame_z, ng):
        return ~mi.Bool(self.pt_normals) | ((dr.dot(w_local, ng) > 0) == (w_frame_z > 0))

    def sample(self, ctx, si, sample1, sample2, active):
        frame, ng = self.frame(si)
        wi = frame.to_local(si.wi)
        side = dr.select(wi.z >= 0, 1.0, -1.0)
        cos_i = dr.abs(wi.z)
        p_spec, p_refr, p_diff = self.lobe_probs(cos_i)
        pick_spec = sample1 < p_spec
        pick_refr = ~pick_spec & (sample1 < p_spec + p_refr)
        pick_diff = ~pick_spec & ~pick_refr

        mirror = mi.Vector3f(-wi.x, -wi.y, wi.z)
        # Refraction: entering when wi is on the normal's side; TIR reflects with reflectance 1.
        eta_rel = dr.select(wi.z >= 0, self.eta, 1.0 / self.eta)
        sin2_t = (1 - cos_i * cos_i) / (eta_rel * eta_rel)
        tir = sin2_t >= 1
        cos_t = dr.sqrt(dr.maximum(0.0, 1 - sin2_t))
        refracted = mi.Vector3f(-wi.x / eta_rel, -wi.y / eta_rel, -side * cos_t)
        diffuse = mi.warp.square_to_cosine_hemisphere(sample2)
        diffuse = mi.Vector3f(diffuse.x, diffuse.y, side * diffuse.z)

        wo = dr.select(pick_spec | (pick_refr & tir), mirror, dr.select(pick_refr, refracted, diffuse))
        bs = dr.zeros(mi.BSDFSample3f)
        bs.wo = frame.to_world(wo)
        bs.pdf = dr.select(pick_spec, p_spec, dr.select(pick_refr, p_refr, p_diff * dr.abs(diffuse.z) / math.pi))
        bs.eta = dr.select(pick_refr & ~tir, eta_rel, 1.0)
        bs.sampled_type = dr.select(pick_spec, mi.UInt32(+mi.BSDFFlags.DeltaReflection),
                                    dr.select(pick_refr & ~tir, mi.UInt32(+mi.BSDFFlags.DeltaTransmission),
                                              dr.select(pick_refr, mi.UInt32(+mi.BSDFFlags.DeltaReflection),
                                                        mi.UInt32(+mi.BSDFFlags.DiffuseReflection))))
        bs.sampled_component = dr.select(pick_spec, mi.UInt32(0), dr.select(pick_refr, mi.UInt32(1), mi.UInt32(2)))
        # value = f cos / pdf: Ks for the mirror, the radiance scale for refraction, Kd for Lambert.
        refr_weight = dr.select(tir, 1.0, 1.0 / (eta_rel * eta_rel))
        value = dr.select(pick_spec, self.ks, dr.select(pick_refr, mi.Color3f(refr_weight), self.kd_at(si, active)))
        ok = active & (wi.z != 0) & (bs.pdf > 0) & ~(pick_diff & (diffuse.z == 0)) & self.consistent(bs.wo, wo.z, ng)
        return bs, dr.select(ok, value, 0.0)

    def diffuse_part(self, si, wo):
        """The Lambert lobe's probability and cosine for wo, zero where no path can use it."""
        frame, ng = self.frame(si)
        wi, wo_f = frame.to_local(si.wi), frame.to_local(wo)
        _, _, p_diff = self.lobe_probs(dr.abs(wi.z))
        usable = (wi.z * wo_f.z > 0) & self.consistent(wo, wo_f.z, ng)
        return dr.select(usable, p_diff * dr.abs(wo_f.z) / math.pi, 0.0)

    def eval(self, ctx, si, wo, active):
        return dr.select(active, self.kd_at(si, active) * self.diffuse_part(si, wo), 0.0)

    def pdf(self, ctx, si, wo, active):
        return dr.select(active, self.diffuse_part(si, wo), 0.0)

    def eval_pdf(self, ctx, si, wo, active):
        return self.eval(ctx, si, wo, active), self.pdf(ctx, si, wo, active)

    def to_string(self):
        return "LabBsdf"


mi.register_bsdf("lab", lambda props: LabBsdf(props))


# ---------------------------------------------------------------- scene dict
def build_scene(obj_path, camera_index, width, height, max_depth, pt_normals, tmp, rr_depth=5):
    mtllib, groups = parse_obj(obj_path)
    materials, lights, cameras = parse_mtl(mtllib)
    if not cameras:
        fail("the scene has no camera")
    cam = cameras[camera_index]
    scene = {
        "type": "scene",
        # pt's --max-depth D counts scattering events; Mitsuba's max_depth counts path vertices.
        "integrator": {"type": "path", "max_depth": max_depth + 1, "rr_depth": rr_depth},
        "sensor": {
            "type": "perspective",
            "fov": cam["fov"], "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["position"], target=cam["target"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb",
                     "component_format": "float32", "rfilter": {"type": "box"}},
            "sampler": {"type": "independent"},
        },
    }
    # The environment: sky above the horizon, ground below. A tall lat-long map keeps the
    # bilinear seam at the horizon within 1/4096 of a half-turn.
    rows = 4096
    env = np.zeros((rows, 4, 3), dtype=np.float32)
    env[: rows // 2] = SKY
    env[rows // 2:] = GROUND
    scene["env"] = {"type": "envmap", "bitmap": mi.Bitmap(env)}
    for i, light in enumerate(lights):
        intensity = [c * light["intensity"] for c in light["color"]]
        if light["radius"] > 0:
            radiance = [c / (math.pi * light["radius"] ** 2) for c in intensity]
            scene[f"light{i}"] = {
                "type": "sphere", "center": light["pos"], "radius": light["radius"],
                "emitter": {"type": "area", "radiance": {"type": "rgb", "value": radiance}},
                "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}},
            }
        else:
            scene[f"light{i}"] = {"type": "point", "position": light["pos"],
                                  "intensity": {"type": "rgb", "value": intensity}}
    for k, (name, (pos, nrm, uv)) in enumerate(groups.items()):
        m = materials.get(name) or fail(f"usemtl {name!r} names no material")
        ply = os.path.join(tmp, f"group{k}.ply")
        write_ply(ply, pos, nrm, uv)
        bsdf = {"type": "lab", "r0": m["r0"], "w": m["w"], "t": m["t"], "eta": m["eta"], "pt_normals": pt_normals}
        if m["map_kd"]:  # an sRGB texture, bilinear, repeating
            bsdf["kd_map"] = {"type": "bitmap", "filename": m["map_kd"], "raw": False,
                              "filter_type": "bilinear", "wrap_mode": "repeat"}
        for c, kd, ks in zip("rgb", m["kd"], m["ks"]):
            bsdf[f"kd_{c}"], bsdf[f"ks_{c}"] = kd, ks
        scene[f"shape{k}"] = {"type": "ply", "filename": ply, "face_normals": False, "bsdf": bsdf}
    return mi.load_dict(scene)


def write_exr(path, mean, var, spp, seconds):
    import OpenImageIO as oiio
    h, w, _ = mean.shape
    spec = oiio.ImageSpec(w, h, 6, oiio.FLOAT)
    spec.channelnames = ("R", "G", "B", "variance.R", "variance.G", "variance.B")
    spec.attribute("pt:renderer", f"mitsuba {mi.__version__} llvm_ad_rgb path")
    spec.attribute("pt:spp", int(spp))
    spec.attribute("pt:seconds", float(seconds))
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, spec):
        fail(f"cannot write {path}: {oiio.geterror()}")
    out.write_image(np.concatenate([mean, var], axis=2).astype(np.float32))
    out.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--camera", type=int, default=0)
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=64, help="samples per pixel of each pass")
    ap.add_argument("--passes", type=int, default=64)
    ap.add_argument("--max-depth", type=int, default=16)
    ap.add_argument("--rr-depth", type=int, default=5, help="Mitsuba's depth at which Russian roulette starts [5]")
    ap.add_argument("--pt-normals", action="store_true",
                    help="apply pt's rules where interpolated normals disagree with the geometry")
    ap.add_argument("--bench", type=int, default=0, metavar="K",
                    help="instead: time K frames of --spp after one warm-up frame (which compiles the kernel)")
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    import time
    with tempfile.TemporaryDirectory() as tmp:
        scene = build_scene(a.scene, a.camera, width, height, a.max_depth, a.pt_normals, tmp, a.rr_depth)
        if a.bench:
            times = []
            for k in range(a.bench + 1):
                t0 = time.perf_counter()
                np.array(mi.render(scene, spp=a.spp, seed=k))  # the copy waits for the kernel
                times.append(time.perf_counter() - t0)
            runs = sorted(times[1:])
            print(f"mitsuba {mi.__version__} llvm_ad_rgb: {width}x{height}, {a.spp} spp, warm-up {times[0]:.3f} s, "
                  f"median {runs[len(runs) // 2]:.3f} s per frame ({runs[0]:.3f} to {runs[-1]:.3f}) over {a.bench} frames")
            return
        start = time.time()
        total = np.zeros((height, width, 3))
        total_sq = np.zeros((height, width, 3))
        for p in range(a.passes):
            img = np.array(mi.render(scene, spp=a.spp, seed=p + 1), dtype=np.float64)[:, :, :3]
            total += img
            total_sq += img * img
            print(f"\rpass {p + 1}/{a.passes}  {time.time() - start:.0f} s", end="", file=sys.stderr)
        print(file=sys.stderr)
    n = a.passes
    mean = total / n
    var_of_mean = np.maximum(total_sq / n - mean * mean, 0) * n / (n - 1) / n
    write_exr(a.out, mean, var_of_mean, a.spp * n, time.time() - start)
    print(f"{a.out}: {width}x{height}, {a.spp * n} spp, {time.time() - start:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
