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

// The guide at a shading point: the region's learnt distribution, and the weights of the two
// strategies in the density of a non-delta direction (guide 0: not guided here).
struct ScatterGuide {
    const PathGuide* guide = nullptr;
    uint32_t region = 0;
    float share = 0.0f;    // of the draws that do not take a delta lobe, the guide's
    float nonDelta = 0.0f; // 1 - the BSDF's delta share: the chance of a draw that may be guided
};

// A non-delta direction's density in its two strategies' parts: the BSDF's own density, and the
// guide's times the chance that a draw takes no delta lobe. Mixed, they count 1 - share and share.
struct ScatterParts {
    float bsdf = 0.0f, guide = 0.0f;
    float mixed(float share) const { return (1.0f - share) * bsdf + share * guide; }
};

// A path is guided only while guiding has scaled its throughput by at most this much
// (PathState::guideGain). Each guided vertex multiplies the throughput by f cos / p with p the
// mixed density; its mean is the BSDF's albedo, but its second moment is the albedo squared
// times E[p_bsdf / p] over the BSDF's directions, which is above 1 wherever the guide is not the
// BSDF's shape (Cauchy-Schwarz). Along a path the second moments multiply: in a closed room of
// albedo 0.99 the training guide's 1.13 per bounce made the variance of paths hundreds of
// bounces long grow without bound, and their sample mean fell 43 % short. Past the bound the path
// takes the BSDF's directions alone, so its throughput stays within kMaxGuideGain / (1 - share)
// of the BSDF-sampled one at any depth. 2 rather than 4: in the closed room at albedo 0.999 the
// training passes' standard error was 0.6 times 4's; on lamp_shaft at equal samples the guided
// variance was 1.08 times the unbounded guide's (4: 1.12; unguided: 1.20).
inline constexpr float kMaxGuideGain = 2.0f;

// Guided where the BSDF has a non-specular lobe and transmits nothing: the guide's directions
// that a reflecting surface cannot take are wasted, and a transmitting one's refraction is the
// BSDF's to sample. Its delta lobes keep the chance the BSDF gives them: a caustic is a diffuse
// bounce the guide aims, followed by a mirror the BSDF must still take as often as before. The
// guide's share is the one its region learnt (none where guiding did not pay), or in training
// the fixed share the choice is learnt from.
inline ScatterGuide scatterGuideAt(const PathGuide* guide, const Vec3& p, const Vec3& n, const Bsdf& bsdf, bool training,
                                   float guideGain) {
    const uint8_t lobes = bsdf.lobes();
    if (!guide || !(lobes & kLobeNonSpecular) || (lobes & kLobeTransmission)) return {};
    const uint32_t region = guide->regionAt(p, n);
    const float share = training ? (guide->trained(region) ? kTrainingShare : 0.0f) : guide->share(region);
    if (share == 0.0f || guideGain > kMaxGuideGain) return {guide, region};
    return {guide, region, share, 1.0f - bsdf.deltaShare()};
}

// The density of the world direction wi, given the BSDF's own (non-delta) density.
inline float scatterPdf(float bsdfPdf, const Vec3& wi, const ScatterGuide& g) {
    if (g.share == 0.0f) return bsdfPdf;
    return ScatterParts{bsdfPdf, g.nonDelta * g.guide->pdf(g.region, wi)}.mixed(g.share);
}

// Samples the next direction (out.wi local, wi in world space); out.weight is f |cos| over the
// density, out.pdf that density, and `parts` its two strategies' parts where guided (training
// learns the share from them). Guided, the lobe value first decides, as the BSDF would, whether
// a delta lobe is taken; if not, u.guide picks the guide (share) or the BSDF's non-delta lobes,
// and the density is both strategies' together (one-sample MIS).
inline bool sampleScatter(const ShadingPoint& s, const VertexDraws& u, const ScatterGuide& g, BsdfSample& out, Vec3& wi,
                          ScatterParts& parts) {
    if (g.share == 0.0f || u.guide >= g.share || s.bsdf.picksDelta(u.lobe)) {
        if (!s.bsdf.sample(s.wo, u.lobe, u.direction, out)) return false;
        wi = s.frame.toWorld(out.wi);
        if (g.share == 0.0f || out.isDelta()) return true;
        const Spectrum fCos = out.weight * out.pdf;
        parts = {out.pdf, g.nonDelta * g.guide->pdf(g.region, wi)};
        out.pdf = parts.mixed(g.share);
        out.weight = fCos / out.pdf;
        return true;
    }
    float guidePdf;
    wi = g.guide->sample(g.region, u.direction, guidePdf);
    out.wi = s.frame.toLocal(wi);
    float bsdfPdf;
    const Spectrum fCos = s.bsdf.evalPdf(s.wo, out.wi, bsdfPdf);
    parts = {bsdfPdf, g.nonDelta * guidePdf};
    out.pdf = parts.mixed(g.share);
    if (!(out.pdf > 0.0f) || isBlack(fCos)) return false;
    out.weight = fCos / out.pdf;
    out.lobe = s.bsdf.lobes() & (kLobeReflection | kLobeNonSpecular);
    out.radianceScale = 1.0f;
    return true;
}

} // namespace pt
