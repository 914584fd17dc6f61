// A material's emitted radiance at a point: read by the path loop where a path hits an emitter
// and by the light set where next-event estimation samples one, so it sits below both.
#pragma once

#include "scene/scene.h"

namespace pt {

// Radiance a material emits at texture coordinates uv: Ke, times its emission texture (glTF).
inline Spectrum emittedRadiance(const Material& m, const TextureCache& textures, Vec2 uv, const Footprint& footprint) {
    if (!m.emissionMap.used()) return m.emission;
    return m.emission * textures.color(m.emissionMap, uv, footprint);
}

} // namespace pt
