// glTF 2.0's metallic-roughness BRDF exactly as the specification's Appendix B writes it, in
// double and in its own textbook form, as the reference the renderer's implementation
// (material/metal_rough_bsdf.h) and glTF renders are held to.
#pragma once

#include "core/math.h"

#include <cmath>

namespace pt::test {

// The specification's Appendix B, as it writes it: D and the visibility term V = G2 / (4 NdotL
// NdotV) in their textbook forms, Schlick's Fresnel at VdotH, the mix by metallic. Returns f.
// KHR_materials_specular's weight s and colour change the dielectric's fresnel_mix to
// (1 - s max(Fr)) diffuse + s Fr specular, Fr from F0 = min(0.04 specularColor, 1).
inline Spectrum specBrdf(const Spectrum& base, float metallic, float roughness, const Vec3& v, const Vec3& l,
                         float s = 1.0f, Spectrum specularColor = Spectrum(1.0f)) {
    double a = double(roughness) * roughness, a2 = a * a;
    Vec3 h = glm::normalize(v + l);
    double nl = l.z, nv = v.z, nh = h.z, vh = glm::dot(v, h);
    double d = a2 / (M_PI * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
    double vis = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
    double specular = vis * d;
    double w = std::pow(1.0 - std::abs(vh), 5.0);
    double fr[3], maxFr = 0.0;
    for (int c = 0; c < 3; ++c) {
        double f0 = std::min(0.04 * specularColor[c], 1.0);
        fr[c] = f0 + (1.0 - f0) * w;
        maxFr = std::max(maxFr, fr[c]);
    }
    Spectrum out;
    for (int c = 0; c < 3; ++c) {
        double dielectric = (1.0 - s * maxFr) * base[c] / M_PI + s * fr[c] * specular;
        double fm = base[c] + (1.0 - base[c]) * w;
        out[c] = float((1.0 - metallic) * dielectric + metallic * fm * specular);
    }
    return out;
}

} // namespace pt::test
