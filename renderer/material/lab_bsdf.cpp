#include "material/lab_bsdf.h"

#include "sampling/warp.h"

namespace pt {

LabBsdf LabBsdf::make(const LabParameters& m, float cosThetaO, HemisphereSampling hemisphere) {
    LabBsdf b;
    b.eta = m.eta;
    b.hemisphere = hemisphere;
    Spectrum wF = m.blend * schlickFresnel(m.r0, cosThetaO);
    Spectrum rest = Spectrum(1.0f) - wF;
    b.mirror = wF * m.ks;
    b.refract = rest * m.transparency;
    b.diffuse = rest * (1.0f - m.transparency) * m.kd;

    float am = average(b.mirror), at = average(b.refract), ad = average(b.diffuse);
    float sum = am + at + ad;
    if (sum > 0.0f) {
        b.pMirror = am / sum;
        b.pRefract = at / sum;
        b.pDiffuse = ad / sum;
    }
    return b;
}

bool refractDirection(const Vec3& wo, float etaRel, Vec3& wt) {
    float cosI = std::abs(wo.z);
    float sin2T = (1.0f - cosI * cosI) / (etaRel * etaRel);
    if (sin2T >= 1.0f) return false;
    float cosT = std::sqrt(1.0f - sin2T);
    float side = wo.z >= 0.0f ? 1.0f : -1.0f;
    wt = Vec3(-wo.x / etaRel, -wo.y / etaRel, -side * cosT);
    return true;
}

Spectrum LabBsdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (pDiffuse == 0.0f || wo.z * wi.z <= 0.0f) return Spectrum(0.0f);
    return diffuse * (kInvPi * std::abs(wi.z));
}

float LabBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (pDiffuse == 0.0f || wo.z * wi.z <= 0.0f) return 0.0f;
    float density = hemisphere == HemisphereSampling::Cosine ? std::abs(wi.z) * kInvPi : uniformHemispherePdf();
    return pDiffuse * density;
}

bool LabBsdf::sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const {
    if (wo.z == 0.0f) return false; // exactly in the surface plane: no side to scatter to
    float side = wo.z > 0.0f ? 1.0f : -1.0f;
    // Choose a lobe; rounding in the probabilities must not make u1 miss every non-empty lobe.
    bool chooseMirror = u1 < pMirror || (pMirror > 0.0f && pRefract == 0.0f && pDiffuse == 0.0f);
    bool chooseRefract = !chooseMirror && (u1 < pMirror + pRefract || (pRefract > 0.0f && pDiffuse == 0.0f));
    if (chooseMirror) {
        out.wi = Vec3(-wo.x, -wo.y, wo.z);
        out.weight = mirror / pMirror;
        out.pdf = 0.0f;
        out.lobeProbability = pMirror;
        out.delta = true;
        return true;
    }
    if (chooseRefract) {
        // Entering when wo is outside (z > 0). Radiance crossing into a denser medium is
        // compressed into a smaller solid angle, hence the (eta_o / eta_i)^2 factor.
        float etaRel = wo.z > 0.0f ? eta : 1.0f / eta;
        Vec3 wt;
        if (refractDirection(wo, etaRel, wt)) {
            out.wi = wt;
            out.radianceScale = 1.0f / (etaRel * etaRel);
            out.weight = refract * (out.radianceScale / pRefract);
        } else {
            out.wi = Vec3(-wo.x, -wo.y, wo.z); // total internal reflection, reflectance 1
            out.weight = refract / pRefract;
        }
        out.pdf = 0.0f;
        out.lobeProbability = pRefract;
        out.delta = true;
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
    out.pdf = pdf(wo, wi);
    out.lobeProbability = pDiffuse;
    out.delta = false;
    return true;
}

} // namespace pt
