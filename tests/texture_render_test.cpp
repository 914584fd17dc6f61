// Textures in renders: filtering far away, normal and bump maps against the geometry they stand
// for, and cutouts in camera and shadow rays.
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

// A texture of one value per channel, everywhere.
int constantTexture(Scene& scene, std::vector<float> value, bool colour) {
    std::vector<float> texels;
    for (int i = 0; i < 16; ++i) texels.insert(texels.end(), value.begin(), value.end());
    Texture t = Texture::fromFloats(4, 4, int(value.size()), texels, colour);
    t.path = "(constant)";
    return scene.textures->add(std::move(t));
}

// A black-and-white checker (Kd 0.8) on a plane to the horizon under a white sky: every pixel
// converges to the pixel's average of the checker. Far away each pixel covers many squares;
// filtered lookups give every sample nearly that average, so 16 samples show neither moire nor
// the noise of point samples (+-0.1 at 16 spp), while near pixels keep the checker's contrast.
TEST(TextureRender, CheckerToTheHorizonWithoutMoire) {
    Scene scene = emptyScene(lookAt({0, 1, 0}, {0, 1 - 10 * std::tan(glm::radians(16.0f)), -10}, {0, 1, 0}, 30));
    scene.environment.sky = Spectrum(1.0f);
    Material m;
    m.kd = Spectrum(0.8f);
    m.kdMap = mapOf(scene.textures->add(checkerTexture()));
    addUvQuad(scene, {-1000, 0, 1000}, {1000, 0, 1000}, {1000, 0, -1000}, {-1000, 0, -1000}, addMaterial(scene, m),
              Vec2(0.0f), Vec2(1000.0f)); // the texture repeats every 2 units: squares of 0.25
    RenderSettings s;
    s.maxDepth = 1;
    Rendered r = render(scene, 64, 64, 16, s);
    // Rows 0-7 look 13 to 57 units away, where a pixel's footprint spans 6 to 30 squares.
    float worst = 0.0f;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 64; ++x) worst = std::max(worst, std::abs(r.pixel(x, y).x - 0.4f));
    EXPECT_LT(worst, 0.05f) << "far pixels must be the checker's mean, 0.4";
    EXPECT_NEAR(regionStats(r, 0, 0, 64, 8).mean.x, 0.4f, 0.01f);
    // The bottom rows are 2 units away, where a square spans about 8 pixels: still a checker.
    float lo = 1.0f, hi = 0.0f;
    for (int x = 0; x < 64; ++x) {
        lo = std::min(lo, r.pixel(x, 62).x);
        hi = std::max(hi, r.pixel(x, 62).x);
    }
    EXPECT_LT(lo, 0.1f);
    EXPECT_GT(hi, 0.7f);
}

// A plane lit by a small light off to one side, seen from above: what a normal or bump map does
// to it is compared with the same plane whose vertex normal is the mapped normal.
Scene litPlane() {
    Scene scene = emptyScene(lookAt({0, 3, 0.01f}, {0, 0, 0}, {0, 1, 0}, 40));
    LocalLight light;
    light.center = Vec3(2.0f, 1.5f, 1.0f);
    light.radius = 0.1f;
    light.intensity = Spectrum(10.0f);
    scene.lights.push_back(light);
    return scene;
}

// The plane y = 0 from (-1, -1) to (1, 1) in x and z, u along +x and v along -z.
void addPlane(Scene& scene, const Material& m, Vec3 normal = Vec3(0.0f), Vec2 uv0 = Vec2(0.0f), Vec2 uv1 = Vec2(1.0f)) {
    addUvQuad(scene, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, addMaterial(scene, m), uv0, uv1, normal);
}

TEST(TextureRender, FlatNormalMapIsNoMap) {
    Material plain;
    plain.kd = Spectrum(0.6f);
    Scene reference = litPlane();
    addPlane(reference, plain);
    Scene mapped = litPlane();
    Material m = plain;
    m.normalMap = mapOf(constantTexture(mapped, {0.5f, 0.5f, 1.0f}, false));
    addPlane(mapped, m);
    Rendered a = render(mapped, 32, 32, 64), b = render(reference, 32, 32, 64);
    for (size_t i = 0; i < a.mean.size(); ++i) ASSERT_NEAR(a.mean[i], b.mean[i], 1e-4f * (1.0f + b.mean[i])) << i;
}

// Tilts along +u (x) and +v (-z): the map's x follows u and its y follows v (green up).
TEST(TextureRender, TiltedNormalMapIsTiltedNormal) {
    const float s = std::sin(0.5f), c = std::cos(0.5f);
    struct Case {
        std::vector<float> texel;
        Vec3 normal;
        const char* what;
    } cases[] = {{{0.5f + 0.5f * s, 0.5f, 0.5f + 0.5f * c}, {s, c, 0}, "x along u"},
                 {{0.5f, 0.5f + 0.5f * s, 0.5f + 0.5f * c}, {0, c, -s}, "y along v"},
                 {{0.5f - 0.5f * s, 0.5f, 0.5f + 0.5f * c}, {-s, c, 0}, "x against u"}};
    for (const Case& k : cases) {
        Material plain;
        plain.kd = Spectrum(0.6f);
        Scene reference = litPlane();
        addPlane(reference, plain, k.normal);
        Scene mapped = litPlane();
        Material m = plain;
        m.normalMap = mapOf(constantTexture(mapped, k.texel, false));
        addPlane(mapped, m);
        Rendered a = render(mapped, 32, 32, 64), b = render(reference, 32, 32, 64);
        float lit = regionStats(b, 0, 0, 32, 32).mean.x;
        ASSERT_GT(lit, 1e-3f);
        for (size_t i = 0; i < a.mean.size(); ++i)
            ASSERT_NEAR(a.mean[i], b.mean[i], 2e-3f * (lit + b.mean[i])) << k.what << " at " << i / 3;
    }
}

// A height ramp h = bm * u across the plane tilts the normal away from +u by atan(bm * du/dx):
// with uv from 0.1 to 0.9 over 2 units in x, du/dx = 0.4, and bm = 1.5 gives a slope of 0.6.
TEST(TextureRender, BumpRampIsTiltedNormal) {
    Scene mapped = litPlane();
    Material m;
    m.kd = Spectrum(0.6f);
    Material plain = m;
    m.bumpMap = mapOf(mapped.textures->add(rampTexture(64, 2)), TextureChannel::R);
    m.bumpMap.bumpScale = 1.5f;
    m.bumpMap.wrapU = m.bumpMap.wrapV = TextureWrap::Clamp;
    addPlane(mapped, m, Vec3(0.0f), Vec2(0.1f), Vec2(0.9f));
    Scene reference = litPlane();
    addPlane(reference, plain, glm::normalize(Vec3(-0.6f, 1.0f, 0.0f)));
    Rendered a = render(mapped, 32, 32, 64), b = render(reference, 32, 32, 64);
    float lit = regionStats(b, 0, 0, 32, 32).mean.x;
    for (size_t i = 0; i < a.mean.size(); ++i) ASSERT_NEAR(a.mean[i], b.mean[i], 2e-3f * (lit + b.mean[i])) << i / 3;
}

// A floor under a point light and a screen halfway up: the screen's coverage is what fraction of
// the light's irradiance its shadow keeps out. Only shadow rays see the screen: the camera is
// below it, looking down at the middle of its shadow.
Scene shadowScene(float coverage, bool withAlphaChannel) {
    Scene scene = emptyScene(lookAt({0, 1, 0}, {0, 0, 0}, {0, 0, -1}, 40));
    LocalLight light;
    light.center = Vec3(0, 4, 0);
    light.intensity = Spectrum(16.0f);
    scene.lights.push_back(light);
    Material floor;
    floor.kd = Spectrum(0.5f);
    addUvQuad(scene, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, addMaterial(scene, floor), Vec2(0.0f), Vec2(1.0f));
    Material screen;
    screen.kd = Spectrum(0.5f);
    screen.alphaMap = withAlphaChannel ? mapOf(constantTexture(scene, {1.0f, 1.0f, 1.0f, coverage}, false), TextureChannel::Alpha)
                                       : mapOf(constantTexture(scene, {coverage}, false), TextureChannel::Luminance);
    addUvQuad(scene, {-0.5f, 2, 0.5f}, {0.5f, 2, 0.5f}, {0.5f, 2, -0.5f}, {-0.5f, 2, -0.5f}, addMaterial(scene, screen),
              Vec2(0.0f), Vec2(1.0f));
    return scene;
}

TEST(TextureRender, CutoutsCastTheirCoverageAsShadow) {
    RenderSettings direct;
    direct.maxDepth = 1;
    // The shadow covers x and z in [-1, 1] on the floor, the whole view.
    Rendered open = render(shadowScene(0.0f, true), 32, 32, 256, direct);
    // Irradiance below the light is I / d^2 = 1, so the floor's radiance is 0.5 / pi.
    expectNear(regionStats(open, 15, 15, 17, 17), Spectrum(0.5f / kPi), 4.0f, 1e-3f, "alpha 0: no shadow at all");
    for (float coverage : {0.25f, 0.5f, 1.0f})
        for (bool alphaChannel : {true, false}) {
            Rendered r = render(shadowScene(coverage, alphaChannel), 32, 32, 256, direct);
            expectNear(regionStats(r, 0, 0, 32, 32), (1.0f - coverage) * regionStats(open, 0, 0, 32, 32).mean, 4.0f, 1e-3f,
                       alphaChannel ? "coverage from the alpha channel" : "coverage from a grey map");
        }
}

// A black screen of coverage 0.5 in front of a white emitter, seen by the camera: half the light
// gets through. Cutout images do not depend on the thread count.
TEST(TextureRender, CameraRaysPassCutouts) {
    Scene scene = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 20));
    Material wall;
    wall.kd = Spectrum(0.0f);
    wall.emission = Spectrum(1.0f);
    addQuad(scene, {-5, -5, -1}, {5, -5, -1}, {5, 5, -1}, {-5, 5, -1}, addMaterial(scene, wall));
    Material screen;
    screen.kd = Spectrum(0.0f);
    screen.alphaMap = mapOf(constantTexture(scene, {1.0f}, false), TextureChannel::Luminance);
    screen.coverage = 0.5f; // d 0.5 with map_d
    addUvQuad(scene, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, addMaterial(scene, screen), Vec2(0.0f), Vec2(1.0f));
    Rendered one = render(scene, 16, 16, 256, {}, 1), two = render(scene, 16, 16, 256, {}, 2);
    expectNear(regionStats(one, 0, 0, 16, 16), Spectrum(0.5f), 4.0f, 0.0f, "half the wall shows through");
    EXPECT_EQ(one.mean, two.mean);
}

// The glTF extensions' maps multiply their factors: a sphere whose specularTexture (A),
// specularColorTexture (RGB) and transmissionTexture (R) are constants renders as the sphere with
// those constants for factors, sample for sample (the same parameters reach the same BSDF).
TEST(TextureRender, ExtensionMapsMultiplyTheirFactors) {
    enum Form { Bare, Factors, Maps };
    auto sphere = [](Material m, Form form) {
        Scene s = emptyScene(lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30));
        s.environment.sky = Spectrum(1.0f);
        s.environment.ground = Spectrum(0.2f);
        if (form == Maps) {
            m.specularMap = mapOf(constantTexture(s, {1.0f, 1.0f, 1.0f, 0.25f}, false), TextureChannel::Alpha);
            m.ksMap = mapOf(constantTexture(s, {0.25f, 0.5f, 1.0f}, true));
            if (m.transparency > 0.0f) m.transmissionMap = mapOf(constantTexture(s, {0.5f}, false), TextureChannel::R);
        } else if (form == Factors) {
            m.specular *= 0.25f;
            m.ks *= Spectrum(0.25f, 0.5f, 1.0f);
            m.transparency *= 0.5f;
        }
        addIcosphere(s, Vec3(0), 1.0f, 3, addMaterial(s, m), false, true);
        return render(s, 16, 16, 16).mean;
    };
    Material m;
    m.model = MaterialModel::MetalRough;
    m.kd = Spectrum(0.5f, 0.4f, 0.3f);
    m.metallic = 0.0f;
    m.roughnessAlpha = 0.09f;
    m.eta = 2.0f; // F0 0.11, so that the specular colour shows
    EXPECT_EQ(sphere(m, Factors), sphere(m, Maps)) << "specular and specular colour maps";
    EXPECT_NE(sphere(m, Factors), sphere(m, Bare)) << "the constants change the image";
    m.transparency = 1.0f;
    EXPECT_EQ(sphere(m, Factors), sphere(m, Maps)) << "transmission map";
    EXPECT_NE(sphere(m, Factors), sphere(m, Bare)) << "the transmission constant changes the image";
}

} // namespace
} // namespace pt::test
