// The range of scenes pt renders correctly, measured, not guessed: tests/render_analytic_test.cpp
// renders the Cornell box and the glass scene at each end of it and compares them with the unit
// scene. Loaders refuse what lies outside with the file and line, instead of drawing a silently
// wrong image.
#pragma once

#include <cstddef>

namespace pt {

// Largest coordinate. Embree 3's float ray-triangle test forms products of three lengths: the
// Cornell box renders unchanged with coordinates up to 9e12 and loses hits at 3e13.
inline constexpr float kMaxCoordinate = 1e12f;
// Smallest scene (diagonal of the triangles' bounding box). Embree's test also has absolute
// thresholds: the box is unchanged down to 3e-8 across and loses light at 3.5e-9.
inline constexpr float kMinSceneSize = 1e-6f;
// Largest emitted radiance (Ke, or a sphere light's I / (pi r^2)), per channel. A sample's square
// must fit in float for the variance layer: 1e18 leaves 1e38.
inline constexpr float kMaxRadiance = 1e18f;
// Largest Kd or Ks. Above 1 a material creates energy (a warning); at 10 sixteen bounces already
// multiply a sample by 1e16, so beyond it samples would overflow float.
inline constexpr float kMaxReflectance = 10.0f;
// A point light's intensity is bounded so that at a tenth of the scene's size from it the
// irradiance stays below kMaxRadiance: I <= kMaxRadiance * (size / 10)^2.
inline constexpr float kPointLightDistanceFraction = 0.1f;
// Smallest sphere light radius, as a fraction of the scene's size: below it the light's solid
// angle underflows float and the light vanishes. Radius 0 is a point light.
inline constexpr float kMinLightRadiusFraction = 1e-12f;
// Most triangles: Embree's primitive IDs and pt's triangle indices are 32-bit.
inline constexpr unsigned long long kMaxTriangles = 1ull << 31;
// Memory a triangle takes from load to render, scene arrays, BVH and shading records together
// (pt-bench load measured 302 bytes at the peak for a million). A glTF file can instance a mesh
// without bound, so its triangles are checked against half of the machine's memory with it.
inline constexpr double kBytesPerTriangle = 320.0;
// Narrowest field of view, in degrees: below it, at 512 pixels across, a float ray direction no
// longer tells neighbouring pixels apart.
inline constexpr float kMinFieldOfView = 0.01f;
// An orthographic camera's half-height must be at least this fraction of its distance from the
// origin, for the same reason (its ray origins step by 2 h / 512 in float coordinates).
inline constexpr float kMinOrthoFraction = 1e-4f;
// Widest aspect ratio a glTF camera may ask for: an image side is at most 65536 pixels.
inline constexpr float kMaxAspect = 65536.0f;
// Largest |scale| and |offset| of a texture's coordinate transform (MTL -s and -o, glTF
// KHR_texture_transform): beyond, float texture coordinates no longer tell a texel from its
// neighbours, and a scale of 1e30 draws the texture as noise.
inline constexpr float kMaxTextureTransform = 1e4f;
// Largest |scale| of a normal map (glTF normalTexture.scale): the perturbed normal (s x, s y, z)
// is squared when normalized, which overflows float beyond about 1e19.
inline constexpr double kMaxNormalScale = 1e6;

} // namespace pt
