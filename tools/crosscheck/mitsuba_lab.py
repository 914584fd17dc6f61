#!/usr/bin/env python3
"""Renders a lab scene (OBJ + extended MTL) with Mitsuba 3, as an independent check of pt.

The lab semantics are rebuilt from the text of issue 2, not from pt's code: sphere lights of
radiance I / (pi r^2), the two-colour sky and ground, a pinhole camera with a vertical field of
view and a box pixel filter, and the lab material tree as a Mitsuba BSDF written here in Python:

    f  = w * FresnelBlend(R0)[Spec(Ks), B1] + (1 - w) * B1,  B1 = T * Refr(eta) + (1 - T) * Lambert(Kd)

with Schlick's F = R0 + (1 - R0)(1 - |cos|)^5, and the rough Spec and Refr lobes of issue 11 with
Mitsuba's GGX distribution. Only what the scenes use is read; any other keyword stops the script
rather than being rendered differently from pt.

Texture maps (issue 11) are Mitsuba's own plugins: `bitmap` textures (bilinear, repeat or clamp,
-s and -o as to_uv) for map_Kd and map_Ks (Mitsuba decodes the sRGB, checked against the rule
here) and for the data maps, whose values are read here with OpenImageIO (v/255, v/65535, floats
as they are), reduced to the channel -imfchan picks and handed over as float bitmaps; the lab
BSDF evaluates Kd, Ks, alpha = value^2 (map_Pr) and the Pm rule (map_Pm) per hit. `norm` is
Mitsuba's `normalmap` and `bump` its `bumpmap` (scale = -bm), both around the lab BSDF with
Mitsuba's two additions switched off (flip_invalid_normals, use_shadowing_function); map_d is
`mask` with opacity d * value outermost, and a scene with map_d renders with `volpath`, whose
shadow rays pass through masks with transmittance 1 - alpha. See build_material for what these
cannot express; anything else stops the script.

An environment map (--env, issue 12) is Mitsuba's `envmap` emitter turned by 90 degrees about +y
plus --env-rotate: Mitsuba's u runs from -z towards +x, pt's centre column looks along +x (the
convention of Blender for a y-up scene). Mitsuba keeps pt's texel centres across (u), but puts
its first and last rows on the poles, so it gets 2H + 1 rows resampled from pt's bilinear
interpolant at v = r / 2H: between those rows pt's interpolant is linear, so both renderers see
the same radiance in every direction.

The Preetham sky (--sky, or an envsky block, issue 12) comes from preetham.py, an implementation
of the paper written for this check: the sky and ground evaluated at each texel of a tall map in
the same layout, and the sun a distant `disk` shape 1e4 away with an `area` emitter, of radius
1e4 tan(r), so that it subtends pt's cone of angular radius r from the scene.

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

sys.path.insert(0, os.path.dirname(__file__))
from exr import write_mean_of_passes  # noqa: E402
from lab_scene import GROUND, SKY, fail, parse_mtl, parse_obj, sun_direction, write_ply  # noqa: E402
import preetham  # noqa: E402

import OpenImageIO as oiio  # noqa: E402  (Debian's, through the venv's system site packages)

mi.set_variant("llvm_ad_rgb")

# ---------------------------------------------------------------- the lab BSDF
class LabBsdf(mi.BSDF):
    """The lab tree; two-sided: the frame is mirrored to wi's side.

    Lobe weights per channel: Spec w F Ks, Refr (1 - w F) T, Lambert (1 - w F)(1 - T) Kd, one lobe
    picked in proportion to its mean weight. With alpha > 0.001 Spec and Refr are GGX lobes with
    Mitsuba's own microfacet distribution (separable Smith G, visible-normal sampling), as issue
    11 defines them: Spec f cos = Ks D G / (4 cos_view); Refr per microfacet m refracts with
    throughput 1 (Walter et al. eq. 21 with F = 0) or, where m totally reflects, reflects with 1.

    Textures (bitmap plugins, evaluated per hit): kd_map and ks_map multiply Kd and Ks; pr_map
    gives alpha = value^2 in place of the constant alpha; with pm (>= 0) or pm_map the Pm rule is
    applied at the hit to the textured Kd and Ks. Inside Mitsuba's normalmap and bumpmap,
    si.sh_frame is the mapped frame (in world coordinates), which the frame rules below use as
    the shading normal.
    """

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.kd = mi.Color3f(props["kd_r"], props["kd_g"], props["kd_b"])
        self.ks = mi.Color3f(props["ks_r"], props["ks_g"], props["ks_b"])
        self.r0 = mi.Color3f(props["r0_r"], props["r0_g"], props["r0_b"])
        self.w, self.t, self.eta = props["w"], props["t"], props["eta"]
        self.pm = props["pm"]  # metallic; < 0: none (no Pm rule) unless pm_map gives it
        self.alpha = props["alpha"]
        texture = lambda name: props[name] if name in props else None
        self.kd_map, self.ks_map = texture("kd_map"), texture("ks_map")
        self.pr_map, self.pm_map = texture("pr_map"), texture("pm_map")  # data: value (Pr) and metallic
        # With map_Pr every texel is rough (build_material checks it): alpha = value^2 per hit.
        self.rough = self.alpha > 0.001 or self.pr_map is not None
        self.distr = (mi.MicrofacetDistribution(mi.MicrofacetType.GGX, self.alpha, True)
                      if self.rough and self.pr_map is None else None)
        self.pt_normals = bool(props["pt_normals"])
        both = mi.BSDFFlags.FrontSide | mi.BSDFFlags.BackSide
        if self.rough:
            spec = mi.BSDFFlags.GlossyReflection | both
            refr = mi.BSDFFlags.GlossyTransmission | mi.BSDFFlags.GlossyReflection | both
        else:
            spec = mi.BSDFFlags.DeltaReflection | both
            refr = mi.BSDFFlags.DeltaTransmission | mi.BSDFFlags.DeltaReflection | both
        self.m_components = [spec, refr, mi.BSDFFlags.DiffuseReflection | both]
        flags = spec
        if self.t > 0:
            flags |= refr
        if self.t < 1:
            flags |= mi.BSDFFlags.DiffuseReflection
        self.m_flags = flags

    def params(self, si, active):
        """Kd, Ks, R0, w and the GGX distribution at the hit: the maps, then the Pm rule."""
        kd = self.kd if self.kd_map is None else self.kd * self.kd_map.eval(si, active)
        ks = self.ks if self.ks_map is None else self.ks * self.ks_map.eval(si, active)
        r0, w = self.r0, mi.Float(self.w)
        metallic = self.pm_map.eval_1(si, active) if self.pm_map is not None else (
            mi.Float(self.pm) if self.pm >= 0 else None)
        if metallic is not None:
            f0 = ((self.eta - 1) / (self.eta + 1)) ** 2
            r0 = f0 + (ks - f0) * metallic
            w, ks, kd = mi.Float(1.0), mi.Color3f(1.0), kd * (1 - metallic)
        distr = self.distr
        if self.pr_map is not None:
            value = self.pr_map.eval_1(si, active)
            distr = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, value * value, True)
        return kd, ks, r0, w, distr

    def lobes(self, si, cos_i, active):
        """Per-channel lobe weights, the probabilities of picking each lobe, and the GGX distribution."""
        kd, ks, r0, w, distr = self.params(si, active)
        f = w * (r0 + (1 - r0) * dr.power(1 - cos_i, 5))
        spec = f * ks
        refr = (1 - f) * self.t
        diff = (1 - f) * (1 - self.t) * kd
        mean = lambda c: (c.x + c.y + c.z) / 3
        total = mean(spec) + mean(refr) + mean(diff)
        safe = dr.select(total > 0, total, 1.0)
        return spec, refr, diff, mean(spec) / safe, mean(refr) / safe, mean(diff) / safe, distr

    def frame(self, si):
        """The scattering frame, in Mitsuba's shading-frame coordinates, and the geometric normal.

        Plain Mitsuba scatters about the interpolated (or mapped) normal, whatever the geometry
        says. With pt_normals, pt's two rules for smooth meshes, with a mapped normal as the
        shading normal: where the viewer is behind the shading normal's side of the geometric
        surface, scatter about the geometric normal; and a direction whose side differs between
        the two normals carries nothing.
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

    def glossy(self, d, wi, wo, eta_rel, spec, refr, p_spec, p_refr):
        """f cos and pdf of the rough lobes, on the viewer's side (wi.z > 0, wo flipped with it)."""
        # Reflection: the half vector; Refr's share only where m totally reflects wi.
        h = dr.normalize(wi + wo)
        c_h = dr.dot(wi, h)
        tir_h = (1 - c_h * c_h) >= eta_rel * eta_rel
        g_r = d.eval(h) * d.G(wi, wo, h) / (4 * wi.z)
        pdf_r = d.pdf(wi, h) / (4 * dr.abs(dr.dot(wo, h)))
        refl = (wo.z > 0) & (h.z > 0)
        f_refl = spec * g_r + dr.select(tir_h, refr * g_r, 0.0)
        p_refl = (p_spec + dr.select(tir_h, p_refr, 0.0)) * pdf_r
        # Transmission: the generalized half vector -(wi + eta wo), on the normal's side.
        ht = dr.normalize(-(wi + eta_rel * wo))
        ht = dr.select(ht.z < 0, -ht, ht)
        im, om = dr.dot(wi, ht), dr.dot(wo, ht)
        denom = im + eta_rel * om
        trans = (wo.z < 0) & (im > 0) & (om < 0) & (self.t > 0)
        f_tr = refr * (d.eval(ht) * d.G(wi, wo, ht) * im * -om / (wi.z * denom * denom))
        p_tr = p_refr * d.pdf(wi, ht) * eta_rel * eta_rel * -om / (denom * denom)
        f = dr.select(refl, f_refl, dr.select(trans, f_tr, 0.0))
        pdf = dr.select(refl, p_refl, dr.select(trans, p_tr, 0.0))
        return f, dr.select(dr.isfinite(pdf), pdf, 0.0)

    def sample(self, ctx, si, sample1, sample2, active):
        frame, ng = self.frame(si)
        wi = frame.to_local(si.wi)
        side = dr.select(wi.z >= 0, 1.0, -1.0)
        cos_i = dr.abs(wi.z)
        spec, refr, diff, p_spec, p_refr, p_diff, distr = self.lobes(si, cos_i, active)
        pick_spec = sample1 < p_spec
        pick_refr = ~pick_spec & (sample1 < p_spec + p_refr)
        pick_diff = ~pick_spec & ~pick_refr
        eta_rel = dr.select(wi.z >= 0, self.eta, 1.0 / self.eta)
        diffuse = mi.warp.square_to_cosine_hemisphere(sample2)
        diffuse = mi.Vector3f(diffuse.x, diffuse.y, side * diffuse.z)
        bs = dr.zeros(mi.BSDFSample3f)

        if self.rough:
            wi_u = mi.Vector3f(wi.x, wi.y, cos_i)
            m, _ = distr.sample(wi_u, sample2)
            c = dr.dot(wi_u, m)
            sin2_t = (1 - c * c) / (eta_rel * eta_rel)
            tir = sin2_t >= 1
            reflected = 2 * c * m - wi_u
            refracted = (c / eta_rel - dr.sqrt(dr.maximum(0.0, 1 - sin2_t))) * m - wi_u / eta_rel
            wo_u = dr.select(pick_spec | (pick_refr & tir), reflected,
                             dr.select(pick_refr, refracted, mi.Vector3f(diffuse.x, diffuse.y, dr.abs(diffuse.z))))
            wo = mi.Vector3f(wo_u.x, wo_u.y, side * wo_u.z)
            f, pdf = self.mixture(distr, wi_u, wo_u, eta_rel, spec, refr, diff, p_spec, p_refr, p_diff)
            bs.wo = frame.to_world(wo)
            bs.pdf = pdf
            transmitted = wo_u.z < 0
            bs.eta = dr.select(transmitted, eta_rel, 1.0)
            bs.sampled_type = dr.select(pick_diff, mi.UInt32(+mi.BSDFFlags.DiffuseReflection),
                                        dr.select(transmitted, mi.UInt32(+mi.BSDFFlags.GlossyTransmission),
                                                  mi.UInt32(+mi.BSDFFlags.GlossyReflection)))
            bs.sampled_component = dr.select(pick_spec, mi.UInt32(0), dr.select(pick_refr, mi.UInt32(1), mi.UInt32(2)))
            valid_side = dr.select(pick_spec | (pick_refr & tir) | pick_diff, wo_u.z > 0, wo_u.z < 0)
            ok = active & (wi.z != 0) & (pdf > 0) & valid_side & self.consistent(bs.wo, wo.z, ng)
            return bs, dr.select(ok, f / dr.select(pdf > 0, pdf, 1.0), 0.0)

        mirror = mi.Vector3f(-wi.x, -wi.y, wi.z)
        # Refraction: entering when wi is on the normal's side; TIR reflects with reflectance 1.
        sin2_t = (1 - cos_i * cos_i) / (eta_rel * eta_rel)
        tir = sin2_t >= 1
        cos_t = dr.sqrt(dr.maximum(0.0, 1 - sin2_t))
        refracted = mi.Vector3f(-wi.x / eta_rel, -wi.y / eta_rel, -side * cos_t)
        wo = dr.select(pick_spec | (pick_refr & tir), mirror, dr.select(pick_refr, refracted, diffuse))
        bs.wo = frame.to_world(wo)
        bs.pdf = dr.select(pick_spec, p_spec, dr.select(pick_refr, p_refr, p_diff * dr.abs(diffuse.z) / math.pi))
        bs.eta = dr.select(pick_refr & ~tir, eta_rel, 1.0)
        bs.sampled_type = dr.select(pick_spec, mi.UInt32(+mi.BSDFFlags.DeltaReflection),
                                    dr.select(pick_refr & ~tir, mi.UInt32(+mi.BSDFFlags.DeltaTransmission),
                                              dr.select(pick_refr, mi.UInt32(+mi.BSDFFlags.DeltaReflection),
                                                        mi.UInt32(+mi.BSDFFlags.DiffuseReflection))))
        bs.sampled_component = dr.select(pick_spec, mi.UInt32(0), dr.select(pick_refr, mi.UInt32(1), mi.UInt32(2)))
        # value = lobe weight over its probability, times the radiance scale for refraction.
        safe = lambda p: dr.select(p > 0, p, 1.0)
        refr_scale = dr.select(tir, 1.0, 1.0 / (eta_rel * eta_rel))
        value = dr.select(pick_spec, spec / safe(p_spec),
                          dr.select(pick_refr, refr * refr_scale / safe(p_refr), diff / safe(p_diff)))
        ok = active & (wi.z != 0) & (bs.pdf > 0) & ~(pick_diff & (diffuse.z == 0)) & self.consistent(bs.wo, wo.z, ng)
        return bs, dr.select(ok, value, 0.0)

    def mixture(self, distr, wi_u, wo_u, eta_rel, spec, refr, diff, p_spec, p_refr, p_diff):
        """f cos and pdf of every non-delta lobe together, on the viewer's side."""
        lambert = wo_u.z > 0
        f = dr.select(lambert, diff * wo_u.z / math.pi, 0.0)
        pdf = dr.select(lambert, p_diff * wo_u.z / math.pi, 0.0)
        if self.rough:
            fg, pg = self.glossy(distr, wi_u, wo_u, eta_rel, spec, refr, p_spec, p_refr)
            f, pdf = f + fg, pdf + pg
        return f, pdf

    def eval_pdf(self, ctx, si, wo, active):
        frame, ng = self.frame(si)
        wi, wo_f = frame.to_local(si.wi), frame.to_local(wo)
        side = dr.select(wi.z >= 0, 1.0, -1.0)
        cos_i = dr.abs(wi.z)
        spec, refr, diff, p_spec, p_refr, p_diff, distr = self.lobes(si, cos_i, active)
        eta_rel = dr.select(wi.z >= 0, self.eta, 1.0 / self.eta)
        wi_u = mi.Vector3f(wi.x, wi.y, cos_i)
        wo_u = mi.Vector3f(wo_f.x, wo_f.y, side * wo_f.z)
        f, pdf = self.mixture(distr, wi_u, wo_u, eta_rel, spec, refr, diff, p_spec, p_refr, p_diff)
        usable = active & (wi.z != 0) & self.consistent(wo, wo_f.z, ng)
        return dr.select(usable, f, 0.0), dr.select(usable, pdf, 0.0)

    def eval(self, ctx, si, wo, active):
        return self.eval_pdf(ctx, si, wo, active)[0]

    def pdf(self, ctx, si, wo, active):
        return self.eval_pdf(ctx, si, wo, active)[1]

    def to_string(self):
        return "LabBsdf"


mi.register_bsdf("lab", lambda props: LabBsdf(props))


# ---------------------------------------------------------------- texture maps
def read_image(path):
    """The stored values of an image as floats (8-bit v/255, 16-bit v/65535, float as is; no colour
    conversion, alpha not premultiplied), and the index of its alpha channel or None."""
    config = oiio.ImageSpec()
    config.attribute("oiio:UnassociatedAlpha", 1)
    buf = oiio.ImageBuf(path, 0, 0, config)
    if buf.has_error:
        fail(f"{path}: {buf.geterror()}")
    spec = buf.spec()
    pixels = buf.get_pixels(oiio.FLOAT)
    if pixels is None:
        fail(f"{path}: cannot read its pixels")
    pixels = np.asarray(pixels, dtype=np.float64).reshape(spec.height, spec.width, spec.nchannels)
    alpha = spec.alpha_channel if spec.alpha_channel >= 0 else None
    return pixels, alpha, spec.format.basetype in (oiio.FLOAT, oiio.HALF, oiio.DOUBLE)


def colour_of(pixels, alpha):
    """RGB of an image: grey replicated, alpha left out."""
    colour = [c for c in range(pixels.shape[2]) if c != alpha]
    if len(colour) == 1:
        return np.repeat(pixels[:, :, colour[:1]], 3, axis=2)
    if len(colour) < 3:
        fail(f"an image with {pixels.shape[2]} channels is outside what this check models")
    return pixels[:, :, colour[:3]]


def data_channel(tex, default):
    """The scalar a data map gives (-imfchan: r, g, b, m for alpha, l for luminance
    0.2126 r + 0.7152 g + 0.0722 b, the value itself for a grey image), texel by texel."""
    pixels, alpha, _ = read_image(tex["file"])
    chan = tex["imfchan"] or default(alpha)
    if chan == "m":
        if alpha is None:
            fail(f"{tex['where']}: -imfchan m on {tex['file']}, which has no alpha channel")
        return pixels[:, :, alpha]
    rgb = colour_of(pixels, alpha)
    return rgb @ np.array([0.2126, 0.7152, 0.0722]) if chan == "l" else rgb[:, :, "rgb".index(chan)]


def lookup(tex):
    """Mitsuba's bitmap options for a map: bilinear, repeat or clamp, and the uv transform.

    The meshes carry Mitsuba's uv (u, 1 - v) (write_ply); the lab looks up the image at
    (u', v') = uv * s + o with v' = 0 at the bottom row, which in Mitsuba's image coordinates is
    (su u + ou, 1 - (sv v + ov)) = (su u_m + ou, sv v_m + 1 - sv - ov)."""
    (su, sv), (ou, ov) = tex["s"], tex["o"]
    to_uv = mi.ScalarTransform3f().translate([ou, 1 - sv - ov]).scale([su, sv])  # scale, then translate
    return {"type": "bitmap", "filter_type": "bilinear", "wrap_mode": "clamp" if tex["clamp"] else "repeat",
            "to_uv": to_uv}


def colour_map(tex):
    """map_Kd / map_Ks: Mitsuba's own sRGB decoding of the file (8- and 16-bit files sRGB, float
    files linear, grey replicated, alpha left out), in full float precision. It must agree with
    the lab's rule, decoded here from the file's stored values; else the check stops."""
    pixels, alpha, is_float = read_image(tex["file"])
    rgb = colour_of(pixels, alpha)
    if not is_float:
        rgb = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    decoded = np.array(mi.Bitmap(tex["file"]).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, False))
    if decoded.shape != rgb.shape or np.max(np.abs(decoded - rgb)) > 1e-5:
        fail(f"{tex['where']}: Mitsuba decodes {tex['file']} differently from the lab's rule")
    return {**lookup(tex), "filename": tex["file"], "raw": False, "format": "variant"}


def data_map(values):
    """A float bitmap of data values (raw: Mitsuba leaves them as they are), shape (h, w, c)."""
    return {"type": "bitmap", "bitmap": mi.Bitmap(np.ascontiguousarray(values, dtype=np.float32)), "raw": True}


def triangle_frames(pos, uv):
    """Per triangle: geometric normal, dp/du and dp/dv of the OBJ uvs (v up), and the uv area."""
    p = np.asarray(pos, dtype=np.float64).reshape(-1, 3, 3)
    t = np.asarray(uv, dtype=np.float64).reshape(-1, 3, 2)
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d1, d2 = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
    det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    safe = np.where(det == 0, 1.0, det)[:, None]
    dpdu = (d2[:, 1:2] * e1 - d1[:, 1:2] * e2) / safe
    dpdv = (d1[:, 0:1] * e2 - d2[:, 0:1] * e1) / safe
    ng = np.cross(e1, e2)
    ng /= np.linalg.norm(ng, axis=1, keepdims=True)
    return ng, dpdu, dpdv, det


def build_material(name, m, pt_normals, pos, nrm, uv):
    """The Mitsuba BSDF of one lab material: the lab BSDF with its maps, inside normalmap or
    bumpmap (norm, bump), inside mask (map_d).

    What Mitsuba cannot express as issue 11 has it, and what is done about it:
    - map_Pr with texels at or below alpha 0.001 would mix smooth and rough lobes per hit: stops.
    - Mitsuba's normalmap takes x along dp/du (projected) and y along cross(N, x); issue 11's
      bitangent is sign * cross(N, T). They agree where the uv layout is not mirrored; a
      mirrored triangle stops the check. Both maps need flat shading here (each corner normal the
      face normal), where the tangent frame of issue 11 and Mitsuba's agree; else the check stops.
    - Mitsuba's bumpmap turns the bumped normal to the geometric normal's side, issue 11 to the
      shading normal's: the same on the flat faces allowed here.
    """
    maps = m["maps"]
    bsdf = {"type": "lab", "w": m["w"], "t": m["t"], "eta": m["eta"], "alpha": m["alpha"],
            "pm": -1.0 if m["pm"] is None else m["pm"], "pt_normals": pt_normals}
    for c, kd, ks, r0 in zip("rgb", m["kd"], m["ks"], m["r0"]):
        bsdf[f"kd_{c}"], bsdf[f"ks_{c}"], bsdf[f"r0_{c}"] = kd, ks, r0
    for kind in ("kd", "ks"):
        if kind in maps:
            bsdf[f"{kind}_map"] = colour_map(maps[kind])
    luminance = lambda alpha: "l"
    if "pr" in maps:
        value = data_channel(maps["pr"], luminance)
        if value.min() ** 2 <= 0.001:
            fail(f"{maps['pr']['where']}: map_Pr reaches alpha <= 0.001 (smooth lobes) on some texels; "
                 "a mix of smooth and rough lobes per hit is outside what this check models")
        bsdf["pr_map"] = {**lookup(maps["pr"]), **data_map(value[:, :, None])}
    if "pm" in maps:
        bsdf["pm_map"] = {**lookup(maps["pm"]), **data_map(data_channel(maps["pm"], luminance)[:, :, None])}
    if "norm" in maps or "bump" in maps:
        ng, dpdu, dpdv, det = triangle_frames(pos, uv)
        corners = np.asarray(nrm, dtype=np.float64).reshape(-1, 3, 3)
        corners /= np.linalg.norm(corners, axis=2, keepdims=True)
        if np.any(np.abs(corners - ng[:, None, :]).max(axis=(1, 2)) > 1e-4):
            fail(f"material {name!r}: norm or bump on faces whose corner normals are not the face normal "
                 "(smooth shading) is outside what this check models")
        if np.any(det == 0):
            fail(f"material {name!r}: norm or bump on a face without a uv layout (zero uv area)")
        if "norm" in maps and np.any(np.einsum("ij,ij->i", np.cross(ng, dpdu), dpdv) < 0):
            fail(f"material {name!r}: a normal map on a mirrored uv layout (bitangent sign -1) is outside "
                 "what Mitsuba's normalmap expresses")
    off = {"flip_invalid_normals": False, "use_shadowing_function": False}  # Mitsuba's, not issue 11's
    if "norm" in maps:
        tex = maps["norm"]
        pixels, alpha, _ = read_image(tex["file"])
        n = colour_of(pixels, alpha) * 2 - 1  # -bm scales x and y; Mitsuba normalizes
        n[:, :, :2] *= tex["bm"]
        bsdf = {"type": "normalmap", "normalmap": {**lookup(tex), **data_map((n + 1) / 2)}, "bsdf": bsdf, **off}
    elif "bump" in maps:
        tex = maps["bump"]
        bsdf = {"type": "bumpmap", "height": {**lookup(tex), **data_map(data_channel(tex, luminance)[:, :, None])},
                "scale": tex["bm"], "bsdf": bsdf, **off}
    if "d" in maps:
        tex = maps["d"]
        coverage = m["coverage"] * data_channel(tex, lambda alpha: "l" if alpha is None else "m")
        bsdf = {"type": "mask", "opacity": {**lookup(tex), **data_map(coverage[:, :, None])}, "bsdf": bsdf}
    return bsdf


# ---------------------------------------------------------------- scene dict
def environment_map(path, rotate, scale):
    """Mitsuba's envmap emitter for pt --env PATH --env-rotate ROTATE --env-scale SCALE."""
    pixels, _, is_float = read_image(path)
    if not is_float:
        fail(f"{path}: an environment map holds float or half values")
    rgb = pixels[:, :, :3] if pixels.shape[2] >= 3 else np.repeat(pixels[:, :, :1], 3, axis=2)
    h = rgb.shape[0]
    # pt's rows sit at v = (i + 0.5) / h and clamp at the poles; Mitsuba's row r of R at r / (R - 1).
    v = np.arange(2 * h + 1) / (2 * h)
    y = np.clip(v * h - 0.5, 0, h - 1)
    y0 = np.floor(y).astype(int)
    y1 = np.minimum(y0 + 1, h - 1)
    t = (y - y0)[:, None, None]
    rows = (1 - t) * rgb[y0] + t * rgb[y1]
    return {"type": "envmap", "bitmap": mi.Bitmap(np.ascontiguousarray(rows * scale, dtype=np.float32)),
            "to_world": mi.ScalarTransform4f().rotate([0, 1, 0], 90.0 + rotate)}


def preetham_sky(sun_dir, turbidity, scale, rows=4097, columns=8192):
    """The emitters of pt --sky: a map of sky and ground (pt's layout, Mitsuba's pole rows), and the
    sun's disk as a distant emissive disk. The map is fine (0.04-degree texels across) because pt
    evaluates the model exactly and Perez's circumsolar term has a cusp at the sun: at 0.35-degree
    texels Mitsuba's bilinear lookups blurred it, and glossy reflections of the sun's surroundings
    came out 0.15 % darker than pt's."""
    sky = preetham.Sky(sun_dir, turbidity, scale)
    theta = np.pi * np.arange(rows) / (rows - 1)
    phi = 2 * np.pi * ((np.arange(columns) + 0.5) / columns - 0.5)
    T, P = np.meshgrid(theta, phi, indexing="ij")
    d = np.stack([np.sin(T) * np.cos(P), np.cos(T), np.sin(T) * np.sin(P)], axis=-1)
    radiance = sky.radiance(d)
    # pt's horizon is a step; the row on it holds the mean of both sides, so that Mitsuba's linear
    # blend between rows is symmetric about the horizon and integrates to the step.
    radiance[rows // 2] = 0.5 * (sky.sky(d[rows // 2]) + sky.ground)
    emitters = {"env": {"type": "envmap", "bitmap": mi.Bitmap(np.ascontiguousarray(radiance, dtype=np.float32)),
                        "to_world": mi.ScalarTransform4f().rotate([0, 1, 0], 90.0)}}
    if sky.sun_radiance.max() > 0:
        if sky.sun[1] < math.sin(preetham.SUN_RADIUS):
            fail("a sun that touches the horizon is cut by pt's ground; this check models a sun above it")
        distance = 1e4
        up = [0, 0, 1] if abs(sky.sun[1]) > 0.9 else [0, 1, 0]
        to_world = mi.ScalarTransform4f().look_at(origin=(distance * sky.sun).tolist(), target=[0, 0, 0], up=up)
        r = distance * math.tan(preetham.SUN_RADIUS)
        emitters["sun"] = {"type": "disk", "to_world": to_world @ mi.ScalarTransform4f().scale([r, r, 1]),
                           "emitter": {"type": "area", "radiance": {"type": "rgb", "value": sky.sun_radiance.tolist()}},
                           "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}}}
    return emitters


def build_scene(obj_path, camera_index, width, height, max_depth, pt_normals, tmp, rr_depth=5, env=None, sky=None):
    mtllib, groups = parse_obj(obj_path)
    materials, lights, cameras, environment = parse_mtl(mtllib)
    if not cameras:
        fail("the scene has no camera")
    cam = cameras[camera_index]
    scene = {
        "type": "scene",
        # pt's --max-depth D counts scattering events; Mitsuba's max_depth counts path vertices.
        # With map_d, volpath: its shadow rays pass through `mask` surfaces with transmittance
        # 1 - alpha and a pass-through is no bounce, as in issue 11. (path's shadow rays stop at
        # any surface, so light through a cutout would come from BSDF sampling alone: unbiased,
        # but very noisy.) Without media volpath is otherwise the same path tracer.
        "integrator": {"type": "volpath" if any("d" in m["maps"] for m in materials.values()) else "path",
                       "max_depth": max_depth + 1, "rr_depth": rr_depth},
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
    two_tone = np.zeros((rows, 4, 3), dtype=np.float32)
    two_tone[: rows // 2] = SKY
    two_tone[rows // 2:] = GROUND
    scene["env"] = {"type": "envmap", "bitmap": mi.Bitmap(two_tone)}
    if environment and not env and not sky:  # the MTL's block, unless the command line replaces it
        if environment["sky"]:
            e = environment
            sky = (e["dir"] if e["dir"] else sun_direction(e["elevation"], e["azimuth"]), e["turbidity"], e["scale"])
        else:
            env = (environment["envmap"], environment["rotate"], environment["envscale"])
    if env:
        scene["env"] = environment_map(*env)
    if sky:
        scene.update(preetham_sky(*sky))
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
        bsdf = build_material(name, m, pt_normals, pos, nrm, uv)
        scene[f"shape{k}"] = {"type": "ply", "filename": ply, "face_normals": False, "bsdf": bsdf}
    return mi.load_dict(scene)


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
    ap.add_argument("--env", help="an environment map, as pt render --env")
    ap.add_argument("--env-rotate", type=float, default=0.0)
    ap.add_argument("--env-scale", type=float, default=1.0)
    ap.add_argument("--sky", action="store_true", help="the Preetham sky and sun, as pt render --sky")
    ap.add_argument("--sun-elevation", type=float, default=45.0)
    ap.add_argument("--sun-azimuth", type=float, default=135.0)
    ap.add_argument("--turbidity", type=float, default=3.0)
    ap.add_argument("--sky-scale", type=float, default=1.0)
    ap.add_argument("--bench", type=int, default=0, metavar="K",
                    help="instead: time K frames of --spp after one warm-up frame (which compiles the kernel)")
    a = ap.parse_args()
    width, height = (int(x) for x in a.res.lower().split("x"))
    import time
    with tempfile.TemporaryDirectory() as tmp:
        env = (a.env, a.env_rotate, a.env_scale) if a.env else None
        sky = (sun_direction(a.sun_elevation, a.sun_azimuth), a.turbidity, a.sky_scale) if a.sky else None
        scene = build_scene(a.scene, a.camera, width, height, a.max_depth, a.pt_normals, tmp, a.rr_depth, env, sky)
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
    write_mean_of_passes(a.out, total, total_sq, a.passes, {
        "pt:renderer": f"mitsuba {mi.__version__} llvm_ad_rgb path", "pt:spp": a.spp * a.passes,
        "pt:seconds": float(time.time() - start)})
    print(f"{a.out}: {width}x{height}, {a.spp * a.passes} spp, {time.time() - start:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
