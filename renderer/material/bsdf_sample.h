// What every BSDF model shares: the kinds of lobe it has (flags, as pbrt-v4's BxDFFlags and
// Mitsuba's BSDFFlags), and a sampled direction.
#pragma once

#include "core/math.h"

#include <cstdint>

namespace pt {

// A lobe is one of reflection or transmission, and one of diffuse, glossy or specular (a delta:
// only its one direction, which no other sampling strategy can find).
enum BsdfLobe : uint8_t {
    kLobeReflection = 1,
    kLobeTransmission = 2,
    kLobeDiffuse = 4,
    kLobeGlossy = 8,
    kLobeSpecular = 16,
    kLobeNonSpecular = kLobeDiffuse | kLobeGlossy, // what light sampling and MIS can reach
};

// A sampled direction. A specular lobe's sample has pdf 0 and carries its selection probability
// in its weight only: once glossy and specular lobes mix in one material, that probability is not
// a density, and using it as one (in MIS) would be wrong.
struct BsdfSample {
    Vec3 wi;
    Spectrum weight;  // f * |cos theta_i| / pdf, or the lobe weight over its probability for specular lobes
    float pdf = 0.0f; // solid-angle density of wi over all non-specular lobes, lobe choice included; 0 for specular
    uint8_t lobe = 0; // the BsdfLobe flags of the lobe sampled
    float radianceScale = 1.0f; // (eta_o / eta_i)^2 included in weight when the path refracted

    bool isDelta() const { return lobe & kLobeSpecular; }
};

// How the lab model samples its Lambert lobe (--hemisphere); the glTF model always uses cosine.
enum class HemisphereSampling { Cosine, Uniform };

} // namespace pt
