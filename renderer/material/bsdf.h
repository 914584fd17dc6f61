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

    // One dispatch on the model for every method below: f(lab) or f(metalRough).
    template <typename F>
    decltype(auto) visit(F&& f) const {
        return model == Model::Lab ? f(lab) : f(metalRough);
    }

    // The BsdfLobe flags of the lobes with weight at this hit's wo; 0: the surface is black.
    uint8_t lobes() const { return visit([](const auto& b) { return b.lobes(); }); }
    bool hasNonDelta() const { return lobes() & kLobeNonSpecular; }
    bool isBlack() const { return lobes() == 0; }
    // The surface's reflectance at wo, for the albedo AOV and the denoiser: in every model each
    // lobe's colour times its share at wo (Fresnel at the normal), summed.
    Spectrum albedo(const Vec3& wo) const { return visit([&](const auto& b) { return b.albedo(wo); }); }
    // f |cos theta_i| and the density with which sample() gives wi, in one pass.
    Spectrum evalPdf(const Vec3& wo, const Vec3& wi, float& pdf) const {
        return visit([&](const auto& b) { return b.evalPdf(wo, wi, pdf); });
    }
    bool sample(const Vec3& wo, float u1, Vec2 u2, BsdfSample& out) const {
        return visit([&](const auto& b) { return b.sample(wo, u1, u2, out); });
    }
    // The chance that sample() takes a delta lobe, and whether lobe value u1 makes it.
    float deltaShare() const { return visit([](const auto& b) { return b.deltaShare(); }); }
    bool picksDelta(float u1) const { return visit([&](const auto& b) { return b.picksDelta(u1); }); }
};

static_assert(std::is_trivially_copyable_v<LabBsdf> && std::is_trivially_copyable_v<MetalRoughBsdf>);

} // namespace pt
