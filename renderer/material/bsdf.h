// The BSDF at a hit, whichever material model made it: the lab's tree (lab_bsdf.h) or glTF's
// metallic-roughness BRDF (metal_rough_bsdf.h). A tag and a switch, not virtual calls: the path
// loop sees one interface, and each call is a predictable branch on the hit's material.
#pragma once

#include "material/lab_bsdf.h"
#include "material/metal_rough_bsdf.h"

#include <type_traits>

namespace pt {

struct Bsdf {
    enum class Model : uint8_t { Lab, MetalRough };
    Model model;
    union { // both are plain values (trivially copyable): only the one `model` names is set
        LabBsdf lab;
        MetalRoughBsdf metalRough;
    };

    Bsdf() : model(Model::Lab), lab() {}
    // Built in place: a BSDF made elsewhere and assigned is copied through the stack, each
    // 16-byte load of the copy a failed store forwarding from the member-wise stores before it
    // (evaluateMaterial took 10 % of cornell's time so, 4 % in place).
    void initLab(const LabParameters& p, float cosThetaO, HemisphereSampling hemisphere) {
        model = Model::Lab;
        lab.init(p, cosThetaO, hemisphere);
    }
    void initMetalRough(const MetalRoughParameters& p, const Vec3& wo) {
        model = Model::MetalRough;
        metalRough.init(p, wo);
    }

    bool hasNonDelta() const { return model == Model::Lab ? lab.hasNonDelta() : metalRough.hasNonDelta(); }
    bool isBlack() const { return model == Model::Lab ? lab.isBlack() : metalRough.isBlack(); }
    Spectrum albedo() const {
        return model == Model::Lab ? lab.mirror + lab.refract + lab.diffuse : metalRough.albedo();
    }
    Spectrum evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const {
        return model == Model::Lab ? lab.evalPdf(wo, wi, pdf) : metalRough.evalPdf(wo, wi, pdf);
    }
    Spectrum eval(const Vec3& wo, const Vec3& wi) const {
        float unused;
        return evalPdf(wo, wi, unused);
    }
    float pdf(const Vec3& wo, const Vec3& wi) const {
        float p;
        evalPdf(wo, wi, p);
        return p;
    }
    bool sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const {
        return model == Model::Lab ? lab.sample(wo, u1, u2, out) : metalRough.sample(wo, u1, u2, out);
    }
};

static_assert(std::is_trivially_copyable_v<LabBsdf> && std::is_trivially_copyable_v<MetalRoughBsdf>);

} // namespace pt
