#include "material/lab_bsdf.h"

#include "sampling/warp.h"

namespace pt {

bool refractDirection(const Vec3& wo, float etaRel, Vec3& wt) {
    float cosI = std::abs(wo.z);
    float sin2T = (1.0f - cosI * cosI) / (etaRel * etaRel);
    if (sin2T >= 1.0f) return false;
    float cosT = std::sqrt(1.0f - sin2T);
    float side = wo.z >= 0.0f ? 1.0f : -1.0f;
    wt = Vec3(-wo.x / etaRel, -wo.y / etaRel, -side * cosT);
    return true;
}

namespace {

// The direction and lobe arithmetic below works on the side of wo: o.z > 0, and wi flipped with it.
struct Side {
    float sign;
    float etaRel; // eta of wi's side over eta of wo's side, for a transmitted wi
};

Side sideOf(const Vec3& wo, float eta) { return wo.z > 0.0f ? Side{1.0f, eta} : Side{-1.0f, 1.0f / eta}; }

Vec3 reflectAbout(const Vec3& o, const Vec3& m) { return 2.0f * glm::dot(o, m) * m - o; }

// Refracts o (o.m > 0) through the microfacet m; false when it is totally internally reflected.
bool refractAbout(const Vec3& o, const Vec3& m, float etaRel, Vec3& t) {
    float c = glm::dot(o, m);
    float sin2T = (1.0f - c * c) / (etaRel * etaRel);
    if (sin2T >= 1.0f) return false;
    t = (c / etaRel - std::sqrt(1.0f - sin2T)) * m - o / etaRel;
    return true;
}

bool totallyReflects(const Vec3& o, const Vec3& m, float etaRel) {
    float c = glm::dot(o, m);
    return (1.0f - c * c) >= etaRel * etaRel;
}

} // namespace

// Both values walk the same geometry (the side of wo, the half vector), so one pass gives both.
Spectrum LabBsdf::evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const {
    Spectrum f(0.0f);
    pdf = 0.0f;
    if (pDiffuse > 0.0f && wo.z * wi.z > 0.0f) {
        f += diffuse * (kInvPi * std::abs(wi.z));
        pdf += pDiffuse * (hemisphere == HemisphereSampling::Cosine ? std::abs(wi.z) * kInvPi : uniformHemispherePdf());
    }
    if (!rough() || wo.z == 0.0f) return f;
    // The rough lobes, on wo's side (o.z > 0).
    Side side = sideOf(wo, eta);
    Vec3 o = wo * side.sign, i = wi * side.sign;
    // A thin wall's Refr is the mirror lobe turned through the surface: evaluated at the mirror
    // image r of i, with Refr's weight.
    const bool through = thin && i.z < 0.0f && pRefract > 0.0f;
    if (i.z > 0.0f || through) { // reflection: the mirror lobe, and Refr's totally internally reflecting facets
        const Vec3 r = through ? Vec3(i.x, i.y, -i.z) : i;
        Vec3 m = safeNormalize(o + r);
        if (m.z <= 0.0f) return f;
        // D and G1(o, m) serve both: f cos = D G1(o) G1(r) / (4 o.z), and the density of the
        // visible normal, G1(o) (o.m) D / o.z, times the reflection's Jacobian.
        float d = ggxD(m, alpha), g1o = smithG1(o, m, alpha), om = std::max(0.0f, glm::dot(o, m));
        float g = d * g1o * smithG1(r, m, alpha) / (4.0f * o.z);
        float lobes; // the probability of the lobes that reach r
        if (through) {
            f += refract * g;
            lobes = pRefract;
        } else {
            bool tir = pRefract > 0.0f && !thin && totallyReflects(o, m, side.etaRel);
            if (pMirror > 0.0f) f += mirror * g;
            if (tir) f += refract * g;
            lobes = pMirror + (tir ? pRefract : 0.0f);
        }
        pdf += lobes * (g1o * om * d / o.z) * reflectionJacobian(r, m);
    } else if (i.z < 0.0f && pRefract > 0.0f) { // transmission through m = -(o + eta i)
        Vec3 m = safeNormalize(-(o + side.etaRel * i));
        if (m.z < 0.0f) m = -m;
        float om = glm::dot(o, m), im = glm::dot(i, m);
        if (om <= 0.0f || im >= 0.0f) return f;
        float denom = om + side.etaRel * im;
        float d = ggxD(m, alpha), g1o = smithG1(o, m, alpha);
        f += refract * (d * g1o * smithG1(i, m, alpha) * om * -im / (o.z * denom * denom));
        pdf += pRefract * (g1o * om * d / o.z) * refractionJacobian(o, i, m, side.etaRel);
    }
    return f;
}

bool LabBsdf::sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const {
    if (wo.z == 0.0f) return false; // exactly in the surface plane: no side to scatter to
    float side = wo.z > 0.0f ? 1.0f : -1.0f;
    // Choose a lobe; rounding in the probabilities must not make u1 miss every non-empty lobe.
    bool chooseMirror = u1 < pMirror || (pMirror > 0.0f && pRefract == 0.0f && pDiffuse == 0.0f);
    bool chooseRefract = !chooseMirror && (u1 < pMirror + pRefract || (pRefract > 0.0f && pDiffuse == 0.0f));
    if (rough() && (chooseMirror || chooseRefract)) {
        Side s = sideOf(wo, eta);
        Vec3 o = wo * s.sign;
        Vec3 m = sampleVisibleNormal(o, alpha, u2);
        Vec3 i;
        float scale = 1.0f;
        // A thin wall's Refr reflects about m and then crosses the wall unbent.
        if (chooseMirror || thin || !refractAbout(o, m, s.etaRel, i)) {
            i = reflectAbout(o, m);
            if (i.z <= 0.0f) return false; // reflected into the surface: lost to single scattering
            if (chooseRefract && thin) i.z = -i.z; // through the wall
        } else {
            if (i.z >= 0.0f) return false;
            scale = 1.0f / (s.etaRel * s.etaRel);
        }
        out.wi = i * s.sign;
        out.radianceScale = scale;
        out.lobe = kLobeGlossy | (out.wi.z * wo.z > 0.0f ? kLobeReflection : kLobeTransmission);
        // The weight of the whole mixture, f / pdf over every non-delta lobe: lower variance than
        // the chosen lobe's own ratio (its weight times G1(wi, m) times the radiance scaling), and
        // what MIS's pdf describes.
        Spectrum f = evalPdf(wo, out.wi, out.pdf);
        if (!(out.pdf > 0.0f)) return false;
        out.weight = f / out.pdf;
        return true;
    }
    if (chooseMirror) {
        out.wi = Vec3(-wo.x, -wo.y, wo.z);
        out.weight = mirror / pMirror;
        out.pdf = 0.0f;
        out.lobe = kLobeReflection | kLobeSpecular;
        return true;
    }
    if (chooseRefract) {
        // Entering when wo is outside (z > 0). Radiance crossing into a denser medium is
        // compressed into a smaller solid angle, hence the (eta_o / eta_i)^2 factor.
        float etaRel = wo.z > 0.0f ? eta : 1.0f / eta;
        Vec3 wt;
        if (thin) { // straight through the wall: no bending, no compression of radiance
            out.wi = -wo;
            out.weight = refract / pRefract;
        } else if (refractDirection(wo, etaRel, wt)) {
            out.wi = wt;
            out.radianceScale = 1.0f / (etaRel * etaRel);
            out.weight = refract * (out.radianceScale / pRefract);
        } else {
            out.wi = Vec3(-wo.x, -wo.y, wo.z); // total internal reflection, reflectance 1
            out.weight = refract / pRefract;
        }
        out.pdf = 0.0f;
        out.lobe = kLobeSpecular | (out.wi.z * wo.z > 0.0f ? kLobeReflection : kLobeTransmission);
        return true;
    }
    if (pDiffuse == 0.0f) return false;
    Vec3 wi;
    if (hemisphere == HemisphereSampling::Cosine) {
        wi = squareToCosineHemisphere(u2);
        out.weight = diffuse / pDiffuse; // (Kd / pi) cos / (pDiffuse cos / pi)
    } else {
        wi = squareToUniformHemisphere(u2);
        out.weight = diffuse * (2.0f * wi.z / pDiffuse); // (Kd / pi) cos / (pDiffuse / 2 pi)
    }
    if (wi.z == 0.0f) return false;
    wi.z *= side;
    out.wi = wi;
    out.lobe = kLobeReflection | kLobeDiffuse;
    Spectrum f = evalPdf(wo, wi, out.pdf);
    if (rough()) { // other non-delta lobes overlap the diffuse one: weigh the whole mixture
        if (!(out.pdf > 0.0f)) return false;
        out.weight = f / out.pdf;
    }
    return true;
}

} // namespace pt
