// KHR_materials_sheen's lobe: the "Charlie" fibre distribution with the visibility term of
// Conty Estevez and Kulla 2017, as the extension writes them, and the lobe's directional albedo
// E(mu, alpha) for the albedo-scaling of the layer under it (table from tools/sheen_albedo.py).
//
//   f cos_i = sheenColor D(h) / (4 cos_o (1 + Lambda(cos_o) + Lambda(cos_i)))
//   D(h)    = (2 + 1 / alpha) sin(theta_h)^(1 / alpha) / (2 pi),   alpha = sheenRoughness
//
// The lobe is reciprocal. Its albedo exceeds 1 at grazing views of the smoothest sheens (1.28 at
// mu 0.008 and alpha 1/32); the scaling of the base is then clamped at 0.
#pragma once

#include "core/math.h"
#include "material/sheen_albedo_table.h"

#include <algorithm>

namespace pt {

// Roughness is clamped into the table's range: below 1/32 the lobe is a sliver at grazing angles.
inline constexpr float kMinSheenAlpha = 1.0f / kSheenAlphaNodes;

inline float sheenAlphaOf(float roughness) { return std::clamp(roughness, kMinSheenAlpha, 1.0f); }

// Lambda of the Charlie visibility: the paper's fit, mirrored about cos 0.5.
inline float sheenLambda(float cosTheta, float alpha) {
    const float t = sqr(1.0f - alpha);
    const float a = 21.5473f + (25.3245f - 21.5473f) * t, b = 3.82987f + (3.32435f - 3.82987f) * t,
                c = 0.19823f + (0.16801f - 0.19823f) * t, d = -1.97760f + (-1.27393f + 1.97760f) * t,
                e = -4.32054f + (-4.85967f + 4.32054f) * t;
    auto l = [&](float x) { return a / (1.0f + b * std::pow(x, c)) + d * x + e; };
    const float x = std::clamp(cosTheta, 0.0f, 1.0f);
    return x < 0.5f ? std::exp(l(x)) : std::exp(2.0f * l(0.5f) - l(1.0f - x));
}

inline float charlieD(float cosThetaH, float alpha) {
    float sin2 = std::max(0.0f, 1.0f - cosThetaH * cosThetaH);
    return (2.0f + 1.0f / alpha) * std::pow(sin2, 0.5f / alpha) * (0.5f * kInvPi);
}

// f cos_i of a white sheen (colour 1) for wo, wi above the surface and h their half vector;
// lambdaO is sheenLambda(wo.z, alpha).
inline float sheenLobe(const Vec3& wo, const Vec3& wi, const Vec3& h, float alpha, float lambdaO) {
    return charlieD(h.z, alpha) / (4.0f * wo.z * (1.0f + lambdaO + sheenLambda(wi.z, alpha)));
}

// E(mu, alpha), bilinear in the table (mu at i / 63, alpha at (j + 1) / 32), held at its edges.
inline float sheenAlbedo(float mu, float alpha) {
    const int m = kSheenCosNodes, n = kSheenAlphaNodes;
    float x = std::clamp(mu * float(m - 1), 0.0f, float(m - 1));
    float y = std::clamp(alpha * float(n) - 1.0f, 0.0f, float(n - 1));
    int i = std::min(int(x), m - 2), j = std::min(int(y), n - 2);
    float fx = x - float(i), fy = y - float(j);
    float lo = kSheenAlbedo[j][i] + fx * (kSheenAlbedo[j][i + 1] - kSheenAlbedo[j][i]);
    float hi = kSheenAlbedo[j + 1][i] + fx * (kSheenAlbedo[j + 1][i + 1] - kSheenAlbedo[j + 1][i]);
    return lo + fy * (hi - lo);
}

} // namespace pt
