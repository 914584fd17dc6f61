"""The lab scene format (OBJ + extended MTL), read as issue 2 defines it, for the cross-checks.

Only what the lab scenes use is modelled; any other keyword stops the reader rather than being
rendered differently from pt. Shared by mitsuba_lab.py and cycles_lab.py.

Texture maps follow issue 11 (the semantics pt implements; see parse_map): map_Kd, map_Ks,
map_Pr, map_Pm, norm, bump / map_bump and map_d, with the options -s, -o, -clamp, and -bm and
-imfchan where they have an effect. Each material keeps its keywords as written (kd, ks, r0, w,
pm, ...); the Pm rule is applied by the renderers, per hit where a map feeds it (pm_rule for
constant parameters).
"""
import os
import re
import sys

import numpy as np

SKY = (0.5, 0.6, 0.7)
GROUND = (0.05, 0.025, 0.001)

# Map keyword (lower case) -> (name in a material's "maps", options it takes besides -s -o -clamp).
MAPS = {
    "map_kd": ("kd", ()), "diffusereflectancemap": ("kd", ()),
    "map_ks": ("ks", ()), "specularreflectancemap": ("ks", ()),
    "map_pr": ("pr", ("-imfchan",)),
    "map_pm": ("pm", ("-imfchan",)),
    "norm": ("norm", ("-bm",)),
    "bump": ("bump", ("-bm", "-imfchan")), "map_bump": ("bump", ("-bm", "-imfchan")),
    "map_d": ("d", ("-imfchan",)),
}
COLOUR_MAPS = ("kd", "ks")  # sRGB-decoded colour; the others are data (linear values)
CHANNELS = ("r", "g", "b", "m", "l")


def fail(msg):
    sys.exit(f"crosscheck: {msg}")


def parse_map(line, key, where, mtl_dir):
    """One map line: options, then the file name, which is the rest of the line (it may hold
    spaces). -s and -o take one to three numbers (u [v [w]]; a missing v is 1 for -s and 0 for -o,
    w is ignored), the lookup is at uv * s + o; -clamp on|off; -bm a number (norm, bump); -imfchan
    r|g|b|m|l (map_Pr, map_Pm, bump, map_d). Any other option stops the check."""
    name, extra = MAPS[key]
    key = line.split()[0]  # as written, for messages
    m = {"kind": name, "s": [1.0, 1.0], "o": [0.0, 0.0], "clamp": False, "bm": 1.0, "imfchan": None, "where": where}
    words = [(w.group(), w.start()) for w in re.finditer(r"\S+", line)][1:]  # after the keyword
    is_number = lambda w: re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", w) is not None
    i = 0
    while i < len(words) and len(words[i][0]) >= 2 and words[i][0][0] == "-" and not is_number(words[i][0]):
        option = words[i][0]
        i += 1
        if option in ("-s", "-o"):
            v = []
            while i < len(words) and len(v) < 3 and is_number(words[i][0]):
                v.append(float(words[i][0]))
                i += 1
            if not v:
                fail(f"{where}: {option} expects a number")
            m[option[1]] = [v[0], v[1] if len(v) > 1 else (1.0 if option == "-s" else 0.0)]
        elif option == "-clamp":
            if i >= len(words) or words[i][0] not in ("on", "off"):
                fail(f"{where}: -clamp expects on or off")
            m["clamp"] = words[i][0] == "on"
            i += 1
        elif option == "-bm" and option in extra:
            if i >= len(words) or not is_number(words[i][0]):
                fail(f"{where}: -bm expects a number")
            m["bm"] = float(words[i][0])
            i += 1
        elif option == "-imfchan" and option in extra:
            if i >= len(words) or words[i][0] not in CHANNELS:
                fail(f"{where}: -imfchan expects one of {' '.join(CHANNELS)}")
            m["imfchan"] = words[i][0]
            i += 1
        else:
            fail(f"{where}: option {option} on {key} is outside what this check models")
    if i >= len(words):
        fail(f"{where}: {key} expects a file name")
    m["file"] = os.path.join(mtl_dir, line[words[i][1]:].strip())
    if not os.path.isfile(m["file"]):
        fail(f"{where}: {key}: no file {m['file']} (pt would render without the map)")
    return m


# ---------------------------------------------------------------- scene text
def parse_mtl(path):
    """Materials, lights, cameras, and the environment block (None, or a dict with "envmap" or
    "sky": the Preetham sky's sun direction, turbidity and scale, as issue 12 defines them)."""
    materials, lights, cameras = {}, [], []
    environment = None
    cur = None
    for lineno, raw in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
        line = raw.split("#", 1)[0]
        t = line.split()
        if not t:
            continue
        key, vals = t[0].lower(), t[1:]
        num = lambda: [float(v) for v in vals]
        if key == "newmtl":
            cur = {"kd": [0.7] * 3, "ks": [1.0] * 3, "r0": [0.0] * 3, "w": 0.0, "eta": 1.0, "pm": None,
                   "alpha": 0.001, "maps": {}, "opacity": []}
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
        elif key in ("transparency", "tr"):  # T, whatever else the material says
            cur["opacity"].append(("tr", num()[0]))
        elif key == "d":  # T = 1 - d, or with map_d the coverage multiplier (see below)
            cur["opacity"].append(("d", num()[0]))
        elif key in ("indexofrefraction", "ni"):
            cur["eta"] = num()[0]
        elif key == "pm":
            cur["pm"] = num()[0]
        elif key in MAPS:
            m = parse_map(line, key, f"{path}:{lineno}", os.path.dirname(path))
            cur["maps"][m["kind"]] = m
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
        elif key == "newenvironment":
            cur = environment = {"elevation": 45.0, "azimuth": 135.0, "dir": None, "turbidity": 3.0, "scale": 1.0,
                                 "sky": False, "envmap": None, "rotate": 0.0, "envscale": 1.0}
        elif key == "envsky":
            cur["sky"] = True
        elif key == "envmap":
            cur["envmap"] = os.path.join(os.path.dirname(path), line.split(None, 1)[1].strip())
        elif key in ("envrotate", "envscale"):
            cur["rotate" if key == "envrotate" else "envscale"] = num()[0]
        elif key in ("sunelevation", "sunazimuth", "turbidity", "skyscale"):
            cur[{"sunelevation": "elevation", "sunazimuth": "azimuth", "skyscale": "scale"}.get(key, key)] = num()[0]
        elif key == "sundir":
            cur["dir"] = num()
        else:
            fail(f"{path}:{lineno}: keyword {t[0]!r} is outside what this check models")
    for name, m in materials.items():
        # Without map_d, d x means T = 1 - x and the last of d and Tr wins; with map_d, d is the
        # coverage multiplier (alpha = d * map value) and only Tr sets T.
        events = m.pop("opacity")
        if "d" in m["maps"]:
            m["t"] = next((x for k, x in reversed(events) if k == "tr"), 0.0)
            m["coverage"] = next((x for k, x in reversed(events) if k == "d"), 1.0)
        else:
            m["t"] = (events[-1][1] if events[-1][0] == "tr" else 1.0 - events[-1][1]) if events else 0.0
        if "norm" in m["maps"] and "bump" in m["maps"]:
            print(f"crosscheck: material {name!r}: norm and bump; norm wins, bump is ignored (as in pt)",
                  file=sys.stderr)
            del m["maps"]["bump"]
    return materials, lights, cameras, environment


def sun_direction(elevation, azimuth):
    """Towards the sun: azimuth 0 is -z, 90 is +x (clockwise seen from above), as pt's --sky."""
    e, a = np.radians(elevation), np.radians(azimuth)
    return np.array([np.sin(a) * np.cos(e), np.sin(e), -np.cos(a) * np.cos(e)])


def pm_rule(m):
    """Kd, Ks, R0 and w of a material whose parameters are constant, after the Pm rule of issue 2:
    metallic m mixes the dielectric's F0 towards Ks, the blend is on, the mirror white, and the
    diffuse part fades out with m."""
    if m["pm"] is None:
        return m["kd"], m["ks"], m["r0"], m["w"]
    f0 = ((m["eta"] - 1) / (m["eta"] + 1)) ** 2
    return ([k * (1 - m["pm"]) for k in m["kd"]], [1.0] * 3, [f0 + (k - f0) * m["pm"] for k in m["ks"]], 1.0)


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
