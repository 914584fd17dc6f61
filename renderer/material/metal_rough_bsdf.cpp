#include "material/metal_rough_bsdf.h"

#include "material/sheen.h"
#include "sampling/warp.h"

namespace pt {
namespace {

inline float schlickWeight(float cosTheta) {
    float m = 1.0f - std::clamp(cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

// The clear coat's Fresnel: Schlick's with F0 = 0.04 (ior 1.5), as the extension fixes it.
inline float coatFresnel(float cosTheta) { return 0.04f + 0.96f * schlickWeight(std::abs(cosTheta)); }

// The sheen's parts, out of line: materials without a sheen (most) keep evalPdf's hot path as it
// was without them (inlined, they cost 1.7 % of a sheen-free glTF scene's time).
[[gnu::noinline]] float sheenBaseScale(const Spectrum& sheenColor, float alpha, float scaleO, float cosThetaI) {
    return std::min(scaleO, std::max(0.0f, 1.0f - maxComponent(sheenColor) * sheenAlbedo(cosThetaI, alpha)));
}
[[gnu::noinline]] float sheenLobeAt(const Vec3& wo, const Vec3& wi, const Vec3& h, float alpha) {
    return pt::sheenLobe(wo, wi, h, alpha, sheenLambda(wo.z, alpha));
}

} // namespace

MetalRoughBsdf MetalRoughBsdf::make(const MetalRoughParameters& p, const Vec3& wo) {
    MetalRoughBsdf b;
    b.init(p, wo);
    return b;
}

void MetalRoughBsdf::init(const MetalRoughParameters& p, const Vec3& wo) {
    MetalRoughBsdf& b = *this;
    b = MetalRoughBsdf{};
    const float cosThetaO = wo.z;
    const Spectrum& baseColor = p.baseColor;
    b.baseColor = baseColor;
    b.metallic = std::clamp(p.metallic, 0.0f, 1.0f);
    b.alpha = p.alpha > kSmoothAlpha ? p.alpha : 0.0f;
    b.f0 = glm::min(sqr((p.ior - 1.0f) / (p.ior + 1.0f)) * p.specularColor, Spectrum(1.0f));
    b.specular = std::clamp(p.specular, 0.0f, 1.0f);
    if (p.clearcoat > 0.0f) {
        b.coatNormal = p.clearcoatNormal;
        b.coatAlpha = p.clearcoatAlpha > kSmoothAlpha ? p.clearcoatAlpha : 0.0f;
        b.coat = std::clamp(p.clearcoat, 0.0f, 1.0f) * coatFresnel(glm::dot(wo, b.coatNormal));
    }
    float sheen = 0.0f; // the sheen's albedo at wo
    if (maxComponent(p.sheenColor) > 0.0f && cosThetaO > 0.0f) {
        b.sheenColor = p.sheenColor;
        b.sheenAlpha = sheenAlphaOf(p.sheenRoughness);
        float e = sheenAlbedo(cosThetaO, b.sheenAlpha);
        b.sheenScaleO = std::max(0.0f, 1.0f - maxComponent(p.sheenColor) * e);
        sheen = (1.0f - b.coat) * average(p.sheenColor) * e;
    }
    // Lobe weights at wo, with Fresnel at the normal: the sampling estimate of each lobe's share.
    float w = schlickWeight(cosThetaO);
    Spectrum fd = b.f0 + (Spectrum(1.0f) - b.f0) * w;
    Spectrum fm = baseColor + (Spectrum(1.0f) - baseColor) * w;
    const float base = (1.0f - b.coat) * b.sheenScaleO;
    float specular = base * ((1.0f - b.metallic) * b.specular * average(fd) + b.metallic * average(fm));
    float diffuse = base * (1.0f - b.metallic) * (1.0f - b.specular * maxComponent(fd)) * average(baseColor);
    float sum = specular + diffuse + b.coat + sheen;
    if (cosThetaO > 0.0f && sum > 0.0f) {
        b.pSpecular = specular / sum;
        b.pDiffuse = diffuse / sum;
        b.pCoat = b.coat / sum;
        b.pSheen = sheen / sum;
    }
}

Spectrum MetalRoughBsdf::albedo(const Vec3& wo) const {
    if (isBlack()) return Spectrum(0.0f);
    const float w = schlickWeight(wo.z);
    const Spectrum fd = f0 + (Spectrum(1.0f) - f0) * w;
    const Spectrum fm = baseColor + (Spectrum(1.0f) - baseColor) * w;
    const float base = (1.0f - coat) * sheenScaleO;
    Spectrum a = base * ((1.0f - metallic) * specular * fd + metallic * fm) +
                 base * (1.0f - metallic) * (1.0f - specular * maxComponent(fd)) * baseColor + Spectrum(coat);
    if (sheenAlpha > 0.0f) a += (1.0f - coat) * sheenColor * sheenAlbedo(wo.z, sheenAlpha);
    return a;
}

Spectrum MetalRoughBsdf::evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const {
    pdf = 0.0f;
    if (wo.z <= 0.0f || wi.z <= 0.0f || isBlack()) return Spectrum(0.0f);
    Vec3 h = safeNormalize(wo + wi);
    float vh = glm::dot(wo, h);
    float w = schlickWeight(vh);
    Spectrum fd = f0 + (Spectrum(1.0f) - f0) * w;
    // The base under the sheen's albedo-scaling (the smaller of the two directions' scalings:
    // reciprocal) and under the coat.
    float base = 1.0f - coat;
    if (sheenAlpha > 0.0f) [[unlikely]]
        base *= sheenBaseScale(sheenColor, sheenAlpha, sheenScaleO, wi.z);
    Spectrum f = (base * (1.0f - metallic) * (1.0f - specular * maxComponent(fd)) * kInvPi * wi.z) * baseColor;
    pdf = pDiffuse * wi.z * kInvPi;
    if (!smooth() && h.z > 0.0f) {
        Spectrum fm = baseColor + (Spectrum(1.0f) - baseColor) * w;
        // S |cos theta_i| = D G2 / (4 cos theta_o).
        float s = ggxD(h, alpha) * smithG2HeightCorrelated(wo, wi, h, alpha) / (4.0f * wo.z);
        f += (base * s) * ((1.0f - metallic) * specular * fd + metallic * fm);
        pdf += pSpecular * visibleNormalPdf(wo, h, alpha) * reflectionJacobian(wi, h);
    }
    if (pSheen > 0.0f) [[unlikely]] {
        f += ((1.0f - coat) * sheenLobeAt(wo, wi, h, sheenAlpha)) * sheenColor;
        pdf += pSheen * uniformHemispherePdf();
    }
    if (pCoat > 0.0f && !coatSmooth()) {
        // In the coat's frame: C |cos theta_i| = D G2 |n.l| / (4 |nc.v| |nc.l|), n the shading normal.
        const Frame frame(coatNormal);
        const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi), hc = frame.toLocal(h);
        if (o.z > 0.0f && i.z > 0.0f && hc.z > 0.0f) {
            float c = ggxD(hc, coatAlpha) * smithG2HeightCorrelated(o, i, hc, coatAlpha) * wi.z / (4.0f * o.z * i.z);
            f += Spectrum(coat * c);
            pdf += pCoat * visibleNormalPdf(o, hc, coatAlpha) * reflectionJacobian(i, hc);
        }
    }
    return f;
}

bool MetalRoughBsdf::sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const {
    if (wo.z <= 0.0f || isBlack()) return false;
    out.radianceScale = 1.0f;
    if (u1 < pCoat) {
        if (coatSmooth()) { // the mirror about the coat's normal
            out.wi = 2.0f * glm::dot(wo, coatNormal) * coatNormal - wo;
            if (out.wi.z <= 0.0f) return false;
            out.weight = Spectrum(coat / pCoat);
            out.pdf = 0.0f;
            out.lobe = kLobeReflection | kLobeSpecular;
            return true;
        }
        const Frame frame(coatNormal);
        const Vec3 o = frame.toLocal(wo);
        if (o.z <= 0.0f) return false;
        Vec3 m = sampleVisibleNormal(o, coatAlpha, u2);
        Vec3 i = 2.0f * glm::dot(o, m) * m - o;
        if (i.z <= 0.0f) return false; // below the coat: evalPdf gives the coat no density there
        out.wi = frame.toWorld(i);
    } else if (u1 < pCoat + pSpecular) {
        if (smooth()) {
            // The mirror, with Fresnel at the normal (h = n).
            float w = schlickWeight(wo.z);
            Spectrum fm = baseColor + (Spectrum(1.0f) - baseColor) * w;
            Spectrum lobe = (1.0f - metallic) * specular * (f0 + (Spectrum(1.0f) - f0) * w) + metallic * fm;
            out.wi = Vec3(-wo.x, -wo.y, wo.z);
            out.weight = lobe * ((1.0f - coat) * sheenScaleO / pSpecular); // wi.z = wo.z: both scalings equal
            out.pdf = 0.0f;
            out.lobe = kLobeReflection | kLobeSpecular;
            return true;
        }
        Vec3 m = sampleVisibleNormal(wo, alpha, u2);
        out.wi = 2.0f * glm::dot(wo, m) * m - wo;
    } else if (u1 < pCoat + pSpecular + pSheen) {
        out.wi = squareToUniformHemisphere(u2); // the sheen's lobe spreads to the horizon
    } else {
        out.wi = squareToCosineHemisphere(u2);
    }
    if (out.wi.z <= 0.0f) return false;
    float pdf;
    Spectrum f = evalPdf(wo, out.wi, pdf);
    if (!(pdf > 0.0f)) return false;
    out.weight = f / pdf;
    out.pdf = pdf;
    out.lobe = kLobeReflection | (u1 < pCoat + pSpecular + pSheen ? kLobeGlossy : kLobeDiffuse);
    return true;
}

} // namespace pt
