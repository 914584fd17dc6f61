// Meshes built in code: triangles, quads, boxes and subdivided icosahedra added to a Scene. For
// the tests and for pt-bench (leak), so nothing here uses GoogleTest.
#pragma once

#include "scene/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace pt::test {

uint32_t addMaterial(Scene& scene, const Material& m);
void addTriangle(Scene& scene, Vec3 a, Vec3 b, Vec3 c, uint32_t material);
// Corners counter-clockwise seen from the side the normal faces.
void addQuad(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, uint32_t material);
// Subdivided icosahedron with flat faces (no vertex normals), normals facing out or in; with
// `smooth`, vertex normals along the radius (facing out, or in with `inward`).
void addIcosphere(Scene& scene, Vec3 center, float radius, int subdivisions, uint32_t material,
                  bool inward = false, bool smooth = false);
// A quad (as addQuad) with texture coordinates: uv0 at a, uv1 at c; with a shading normal for
// all four corners if `normal` is not zero.
void addUvQuad(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, uint32_t material, Vec2 uv0, Vec2 uv1,
               Vec3 normal = Vec3(0.0f));
// An axis-aligned box of six quads, normals facing out.
void addBox(Scene& scene, Vec3 lo, Vec3 hi, uint32_t material);

// A Lambert material of reflectance kd.
Material lambert(Spectrum kd);
// The lab's materials, as the MTL loader builds them: lambert, mirror, glass (eta 1.5), plastic
// (a Fresnel blend of a mirror over Lambert) and mixed (every lobe at once), by name.
std::vector<std::pair<std::string, Material>> labMaterials();
Material labMaterial(const std::string& name);

} // namespace pt::test
