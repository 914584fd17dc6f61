// The medium a path travels in: air, or the inside of a closed mesh whose material bounds a
// volume (glTF KHR_materials_volume), which absorbs by Beer-Lambert's law. One medium at a time:
// a path that crosses into a volume is in it until it crosses a volume's surface outwards, and
// then in air (volumes nested inside each other are not tracked).
#pragma once

#include "scene/scene.h"

namespace pt {

inline constexpr uint32_t kAir = ~0u; // the medium outside every volume: clear

// The share of light left after `distance` in a medium of absorption `sigma` per channel; a
// channel that does not absorb keeps all of it, at any distance.
inline Spectrum transmittance(const Spectrum& sigma, float distance) {
    Spectrum t(1.0f);
    for (int c = 0; c < 3; ++c)
        if (sigma[c] > 0.0f) t[c] = std::exp(-sigma[c] * distance);
    return t;
}

// The medium a direction wi travels in after crossing the surface of material `material` (`m`),
// ng its outward geometric normal; `current` where the surface bounds no volume.
inline uint32_t mediumAfterCrossing(uint32_t current, uint32_t material, const Material& m, const Vec3& wi,
                                    const Vec3& ng) {
    if (!m.volume) return current;
    return glm::dot(wi, ng) < 0.0f ? material : kAir;
}

} // namespace pt
