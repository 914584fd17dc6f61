"""The lab scene format (OBJ + extended MTL), read as issue 2 defines it, for the cross-checks.

Only what the three lab scenes use is modelled; any other keyword stops the reader rather than
being rendered differently from pt. Shared by mitsuba_lab.py and cycles_lab.py.
"""
import os
import sys

import numpy as np

SKY = (0.5, 0.6, 0.7)
GROUND = (0.05, 0.025, 0.001)


def fail(msg):
    sys.exit(f"crosscheck: {msg}")


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
            cur = {"kd": [0.7] * 3, "ks": [1.0] * 3, "r0": [0.0] * 3, "w": 0.0, "t": 0.0, "eta": 1.0, "pm": None,
                   "map_kd": None, "alpha": 0.001}
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
            r0 = num()
            cur["r0"] = r0 * 3 if len(r0) == 1 else r0
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
        elif key == "specularroughness":  # GGX alpha, as is
            cur["alpha"] = num()[0]
        elif key == "pr":  # perceptual roughness: alpha = Pr^2
            cur["alpha"] = num()[0] ** 2
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
            m.update(r0=r0, w=1.0, ks=[1.0] * 3, kd=[k * (1 - m["pm"]) for k in m["kd"]])
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
