#include "tests/test_scenes.h"

#include "accel/accel.h"
#include "image/compare.h"

#include <gtest/gtest.h>

namespace pt::test {

Image toImage(const Rendered& r) {
    Image img;
    img.width = r.width;
    img.height = r.height;
    img.rgb = r.mean;
    img.layers.push_back({"variance", {"R", "G", "B"}, r.variance});
    return img;
}

Camera lookAt(Vec3 from, Vec3 to, Vec3 up, float fov) {
    Camera c;
    c.name = "test";
    c.position = from;
    c.target = to;
    c.up = up;
    c.fovY = fov;
    return c;
}

Camera lookAt(Vec3 from, Vec3 to, float fov) { return lookAt(from, to, Vec3(0, 1, 0), fov); }

std::string modeName(LightSampling m) {
    return m == LightSampling::Mis ? "mis" : m == LightSampling::Nee ? "nee" : "bsdf";
}

Scene emptyScene(const Camera& camera) {
    Scene scene;
    scene.path = "(test)";
    scene.cameras.push_back(camera);
    scene.environment.sky = scene.environment.ground = Spectrum(0.0f);
    return scene;
}

Scene groundScene() {
    Scene scene = emptyScene(lookAt({0, 1.2f, 3.5f}, {0, 0.4f, 0}, 40));
    Material ground, white, gloss;
    ground.kd = Spectrum(0.5f);
    white.kd = Spectrum(0.8f);
    gloss.kd = Spectrum(0.0f);
    gloss.ks = Spectrum(0.95f, 0.75f, 0.45f);
    gloss.metallic = 1.0f;
    gloss.roughnessAlpha = 0.1f;
    gloss.eta = 1.5f;
    addQuad(scene, Vec3(-4, 0, 4), Vec3(4, 0, 4), Vec3(4, 0, -4), Vec3(-4, 0, -4), addMaterial(scene, ground));
    addIcosphere(scene, Vec3(-0.55f, 0.5f, 0), 0.5f, 3, addMaterial(scene, white), false, true);
    addIcosphere(scene, Vec3(0.55f, 0.5f, 0), 0.5f, 3, addMaterial(scene, gloss), false, true);
    return scene;
}

Rendered render(const Scene& scene, int width, int height, uint32_t spp, const RenderSettings& settings, int threads) {
    Accel accel(scene, threads);
    RenderResult result = renderImage(scene, accel, scene.cameras[0], width, height, spp, threads, settings);
    Rendered r;
    r.width = width;
    r.height = height;
    r.mean = result.film.mean();
    r.variance = result.film.varianceOfMean();
    r.rays = result.rays;
    return r;
}

void expectStrategiesAgree(const Scene& scene) {
    RenderSettings mis;
    mis.seed = 5;
    Rendered reference = render(scene, 32, 24, 1024, mis);
    for (LightSampling mode : {LightSampling::Nee, LightSampling::Bsdf}) {
        RenderSettings s;
        s.lightSampling = mode;
        s.seed = 9;
        expectSameImage(render(scene, 32, 24, mode == LightSampling::Bsdf ? 4096 : 1024, s), reference, modeName(mode));
    }
}

RegionStats regionStats(const Rendered& r, int x0, int y0, int x1, int y1) {
    glm::dvec3 sum(0.0), var(0.0);
    double n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            size_t i = 3 * (size_t(y) * r.width + x);
            for (int c = 0; c < 3; ++c) {
                sum[c] += r.mean[i + c];
                var[c] += r.variance[i + c];
            }
            n += 1;
        }
    RegionStats s;
    s.mean = Spectrum(sum / n);
    s.stdError = Spectrum(glm::sqrt(var) / n);
    return s;
}

void expectNear(const RegionStats& s, const Spectrum& expected, float sigmas, float relTol, const char* what) {
    for (int c = 0; c < 3; ++c) {
        float tol = sigmas * s.stdError[c] + relTol * std::abs(expected[c]);
        EXPECT_NEAR(s.mean[c], expected[c], tol)
            << what << ", channel " << c << ": standard error " << s.stdError[c];
    }
}

void expectSameImage(const Rendered& test, const Rendered& reference, const std::string& what) {
    CompareOptions options;
    options.blockSize = 8;
    CompareReport report = compareImages(toImage(test), toImage(reference), options);
    EXPECT_TRUE(report.pass) << what << ": " << report.failedTests << " tests differ; worst z " << report.worst[0].z
                             << " at " << report.worst[0].x0 << "," << report.worst[0].y0;
}

TextureMap mapOf(int texture, TextureChannel channel) {
    TextureMap m;
    m.texture = texture;
    m.channel = channel;
    return m;
}

Texture checkerTexture() {
    std::vector<float> texels;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) texels.push_back(float(((x / 8) + (y / 8)) % 2));
    return Texture::fromFloats(64, 64, 3, texels);
}

Texture rampTexture(int width, int height) {
    std::vector<float> texels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) texels.push_back((x + 0.5f) / float(width));
    return Texture::fromFloats(width, height, 1, texels, false);
}

} // namespace pt::test
