// Scenes built in code for tests, and helpers to render them and measure image regions.
#pragma once

#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "tests/scene_builders.h"

#include <string>
#include <vector>

namespace pt::test {

// A pinhole camera at `from` looking at `to`, vertical field of view `fov` degrees (up +y unless given).
Camera lookAt(Vec3 from, Vec3 to, Vec3 up, float fov);
Camera lookAt(Vec3 from, Vec3 to, float fov);
// "mis", "nee" or "bsdf", as --light-sampling spells them.
std::string modeName(LightSampling m);

// Scene with one camera and a black environment.
Scene emptyScene(const Camera& camera);
// A small outdoor scene: a diffuse and a glossy sphere (GGX alpha 0.1 metal) on a ground plane,
// for tests under environment lighting.
Scene groundScene();

struct Rendered {
    int width = 0, height = 0;
    std::vector<float> mean, variance; // RGB, variance of the pixel mean
    RayCounts rays;

    Spectrum pixel(int x, int y) const {
        const float* p = &mean[3 * (size_t(y) * width + x)];
        return Spectrum(p[0], p[1], p[2]);
    }
};

Rendered render(const Scene& scene, int width, int height, uint32_t spp, const RenderSettings& settings = {},
                int threads = 0);

// Mean of the pixel means over [x0, x1) x [y0, y1) and its standard error, from the per-pixel
// variance estimates (pixels are independent).
struct RegionStats {
    Spectrum mean{0.0f};
    Spectrum stdError{0.0f};
};
RegionStats regionStats(const Rendered& r, int x0, int y0, int x1, int y1);

// The render as an image with its variance layer, for compareImages (image/compare.h).
Image toImage(const Rendered& r);

// Asserts that `test` and `reference` agree within noise, block by block (image/compare.h).
void expectSameImage(const Rendered& test, const Rendered& reference, const std::string& what);
// Asserts that light sampling alone and BSDF sampling alone (4096 spp) converge to MIS's image
// (1024 spp) of `scene` at 32 x 24.
void expectStrategiesAgree(const Scene& scene);

// Textures for tests: a map of one, a 64 x 64 black-and-white checker of 8 x 8 squares (RGB), a
// data ramp rising from 0 to 1 across u in `width` texels (one channel).
TextureMap mapOf(int texture, TextureChannel channel = TextureChannel::Rgb);
Texture checkerTexture();
Texture rampTexture(int width, int height);

// Asserts |measured - expected| <= sigmas * stdError + relTol * expected in every channel.
void expectNear(const RegionStats& s, const Spectrum& expected, float sigmas, float relTol, const char* what);

} // namespace pt::test
