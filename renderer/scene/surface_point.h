// What shading knows about a point on a surface: the plain record that render/surface_hit.h
// fills from a triangle hit and that materials read.
#pragma once

#include "core/color.h"
#include "core/math.h"
#include "texture/texture.h"

#include <cstdint>

namespace pt {

struct SurfacePoint {
    Vec3 p;
    float pError; // bound on |p - true surface point|, see core/ray_offset.h
    Vec3 ng;      // unit geometric normal, on the outside as the vertex normals define it
    Vec3 ns;      // unit shading normal, same hemisphere as ng
    uint32_t material;

    // Filled for textured materials only (addTextureCoordinates).
    Vec2 uv{0.0f};
    Vec3 dpdu{0.0f}, dpdv{0.0f}; // zero where the uv layout is degenerate
    Footprint footprint;         // what a lookup filters over (a ray cone's ellipse, in uv)
    Vec3 tangent{0.0f};          // interpolated vertex tangent (normal maps), not renormalised
    float bitangentSign = 1.0f;
    Spectrum color{1.0f};        // interpolated vertex colour (glTF COLOR_0)
};

} // namespace pt
