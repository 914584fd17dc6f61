// The one step from a material at a hit to its BSDF: texture lookups, the Pm rule, then the lab
// tree collapsed for the outgoing direction. Everything a material's value depends on at a hit
// goes through here, so new maps and lobes have one place to go.
#pragma once

#include "material/lab_bsdf.h"
#include "texture/texture.h"

#include <vector>

namespace pt {

// `uvAtHit()` gives the hit's texture coordinates; it is called only if the material has a
// texture, so untextured materials pay nothing for uvs.
template <typename UvAtHit>
inline LabBsdf evaluateMaterial(const Material& m, const std::vector<Texture>& textures, UvAtHit&& uvAtHit,
                                float cosThetaO, HemisphereSampling hemisphere) {
    Spectrum kd = m.kd;
    if (m.kdMap.used()) kd *= lookupTexture(textures, m.kdMap, uvAtHit());
    return LabBsdf::make(labParameters(m, kd), cosThetaO, hemisphere);
}

} // namespace pt
