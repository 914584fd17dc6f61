// Where a path goes after a surface: the one step that samples the next direction and gives the
// density of any direction, for the path's weight and for multiple importance sampling against
// next-event estimation. It is the BSDF's own sampling, or, where a path guide has learnt the
// region (--guide), the BSDF's and the guide's mixed as one-sample MIS: one of the two draws the
// direction, and the density is the mixture of both, so either strategy's weak spots are covered.
#pragma once

#include "guide/path_guide.h"
#include "material/evaluate_material.h"
#include "render/path_state.h"

namespace pt {

// The guide at a shading point: the region's learnt distribution, used for `share` of the
// directions (0: not guided here).
struct ScatterGuide {
    const PathGuide* guide = nullptr;
    uint32_t region = 0;
    float share = 0.0f;
};

// Guided where the BSDF has a non-specular lobe and transmits nothing: the guide's directions
// that a reflecting surface cannot take are wasted, and a transmitting one's refraction is the
// BSDF's to sample.
inline ScatterGuide scatterGuideAt(const PathGuide* guide, const Vec3& p, const Bsdf& bsdf, float share) {
    const uint8_t lobes = bsdf.lobes();
    if (!guide || !(lobes & kLobeNonSpecular) || (lobes & kLobeTransmission)) return {};
    const uint32_t region = guide->regionAt(p);
    if (!guide->trained(region)) return {guide, region, 0.0f};
    return {guide, region, share};
}

// The density of the world direction wi (wiLocal in the shading frame), given the BSDF's own.
inline float scatterPdf(float bsdfPdf, const Vec3& wi, const ScatterGuide& g) {
    if (g.share == 0.0f) return bsdfPdf;
    return (1.0f - g.share) * bsdfPdf + g.share * g.guide->pdf(g.region, wi);
}

// Samples the next direction (out.wi local, wi in world space) from the draws' lobe and
// direction values; out.weight is f |cos| over the mixed density, out.pdf that density.
inline bool sampleScatter(const ShadingPoint& s, const VertexDraws& u, const ScatterGuide& g, BsdfSample& out, Vec3& wi) {
    if (g.share == 0.0f) {
        if (!s.bsdf.sample(s.wo, u.lobe, u.direction, out)) return false;
        wi = s.frame.toWorld(out.wi);
        return true;
    }
    const float bsdfShare = 1.0f - g.share;
    if (u.lobe < bsdfShare) { // the BSDF draws; its lobe choice reads the rest of the value
        if (!s.bsdf.sample(s.wo, u.lobe / bsdfShare, u.direction, out)) return false;
        wi = s.frame.toWorld(out.wi);
        if (out.isDelta()) {
            out.weight /= bsdfShare;
            return true;
        }
        const Spectrum fCos = out.weight * out.pdf;
        out.pdf = bsdfShare * out.pdf + g.share * g.guide->pdf(g.region, wi);
        out.weight = fCos / out.pdf;
        return true;
    }
    float guidePdf;
    wi = g.guide->sample(g.region, u.direction, guidePdf);
    out.wi = s.frame.toLocal(wi);
    float bsdfPdf;
    const Spectrum fCos = s.bsdf.evalPdf(s.wo, out.wi, bsdfPdf);
    out.pdf = bsdfShare * bsdfPdf + g.share * guidePdf;
    if (!(out.pdf > 0.0f) || isBlack(fCos)) return false;
    out.weight = fCos / out.pdf;
    out.lobe = s.bsdf.lobes() & (kLobeReflection | kLobeNonSpecular);
    out.radianceScale = 1.0f;
    return true;
}

} // namespace pt
