// Tangents for normal maps, per triangle corner, computed the way MikkTSpace (Mikkelsen 2008)
// does, so that maps baked by common tools (Blender, Substance, xNormal) look right: a face's
// tangent is dp/du; at each vertex it is projected into the plane of the vertex normal, weighted
// by the corner's angle and summed over the faces that share that vertex (same position, normal
// and uv, and the same uv handedness); the bitangent is sign * cross(n, t), where sign is the
// handedness of the face's uv layout. Shading interpolates t and n without renormalising them
// first, as the baker does.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace pt {

struct CornerTangent {
    Vec3 tangent{0.0f}; // unit; zero where the uv layout gives no direction (then any is used)
    float sign = 1.0f;  // bitangent = sign * cross(normal, tangent)
};

// Three per triangle, in corner order; empty when no material of the scene has a normal map
// (scenes that do not use them pay nothing). Triangles of other materials get zero tangents.
std::vector<CornerTangent> buildCornerTangents(const Scene& scene);

} // namespace pt
