// Where methods break: lossless materials in a white furnace, grazing views, a camera inside
// glass, degenerate and duplicated geometry, normals that point inward or are not unit length,
// lights inside objects, tiny and enclosing lights. Each case has an answer known without the
// renderer (a constant, or another render it must match statistically).
#include "tests/test_scenes.h"

#include "image/compare.h"
#include "load/scene_loader.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

// glTF transmission: white, smooth, Fresnel from the ior; refracting into a clear volume, or a
// thin wall.
Material gltfGlass(bool volume) {
    Material glass;
    glass.model = MaterialModel::MetalRough;
    glass.kd = Spectrum(1.0f);
    glass.metallic = 0.0f;
    glass.roughnessAlpha = 0.0f;
    glass.eta = 1.5f;
    glass.transparency = 1.0f;
    glass.volume = volume;
    return glass;
}

// Materials whose every lobe is white: they absorb nothing at any angle.
std::vector<std::pair<std::string, Material>> losslessMaterials() {
    std::vector<std::pair<std::string, Material>> out;
    Material lambert;
    lambert.kd = Spectrum(1.0f);
    out.emplace_back("lambert", lambert);
    Material mirror;
    mirror.blend = 1.0f;
    mirror.r0 = Spectrum(1.0f);
    out.emplace_back("mirror", mirror);
    Material glass; // pure refraction (and total internal reflection)
    glass.transparency = 1.0f;
    glass.eta = 1.5f;
    out.emplace_back("glass", glass);
    Material fresnelGlass = glass;
    fresnelGlass.blend = 1.0f;
    fresnelGlass.r0 = Spectrum(0.04f);
    out.emplace_back("fresnel_glass", fresnelGlass);
    Material plastic = lambert;
    plastic.blend = 1.0f;
    plastic.r0 = Spectrum(0.1f);
    out.emplace_back("plastic", plastic);
    Material mixed = lambert; // every lobe at once, linear blend
    mixed.blend = 0.5f;
    mixed.r0 = Spectrum(0.3f);
    mixed.transparency = 0.4f;
    mixed.eta = 1.33f;
    out.emplace_back("mixed", mixed);
    out.emplace_back("gltf_glass", gltfGlass(true));
    out.emplace_back("gltf_thin_wall", gltfGlass(false)); // the mirror and straight through
    return out;
}

// The furnace scene: a ball, a box and a floor slab seen at grazing angles, all closed (a glass
// sheet of no thickness would be the boundary of an infinite glass half-space).
Scene furnaceScene(const Material& m, bool smoothBall) {
    Scene scene = emptyScene(lookAt({0, 0.15f, 6}, {0, 0, 0}, 30));
    scene.environment.sky = scene.environment.ground = Spectrum(1.0f);
    uint32_t mat = addMaterial(scene, m);
    addIcosphere(scene, Vec3(-0.8f, 0.4f, 0), 0.7f, 3, mat, false, smoothBall);
    addBox(scene, Vec3(0.3f, -0.3f, -0.5f), Vec3(1.3f, 0.7f, 0.5f), mat);
    addBox(scene, Vec3(-50, -0.45f, -50), Vec3(50, -0.35f, 50), mat);
    return scene;
}

// White furnace: under a uniform environment of radiance 1, lossless objects vanish. A faceted
// ball, a box (total internal reflection inside) and a floor slab at grazing angles all render
// exactly 1: any energy gain or loss, NaN or self-intersection shows.
TEST(WhiteFurnace, LosslessMaterialsVanishAtEveryAngle) {
    for (const auto& [name, m] : losslessMaterials()) {
        RenderSettings s;
        s.maxDepth = 1000; // lossless paths end only by leaving; do not cut them
        Rendered r = render(furnaceScene(m, false), 48, 48, 8, s);
        EXPECT_EQ(r.rays.discarded, 0u) << name;
        float worst = 0.0f;
        for (float v : r.mean) worst = std::max(worst, std::abs(v - 1.0f));
        EXPECT_LT(worst, 1e-4f) << name << ": a pixel differs from 1 by " << worst;
    }
}

// With interpolated normals a direction sampled around the shading normal can point into the
// geometric surface; such paths end (continuing would leak light through the surface), which
// loses a little energy near silhouettes, never gains any. Bounded here so it stays small.
TEST(WhiteFurnace, ShadingNormalsLoseLittleEnergy) {
    for (const auto& [name, m] : losslessMaterials()) {
        RenderSettings s;
        s.maxDepth = 1000;
        Rendered r = render(furnaceScene(m, true), 48, 48, 8, s);
        double sum = 0.0;
        for (float v : r.mean) {
            ASSERT_LE(v, 1.0f + 1e-4f) << name;
            sum += v;
        }
        EXPECT_GT(sum / double(r.mean.size()), 0.995) << name;
    }
}

// The same scene with every material at half albedo never exceeds the furnace's 1.
TEST(WhiteFurnace, LossyMaterialsNeverGainEnergy) {
    for (auto [name, m] : losslessMaterials()) {
        m.kd *= 0.5f;
        m.ks *= 0.5f;
        m.transparency *= 0.5f;
        Rendered r = render(furnaceScene(m, true), 32, 32, 16);
        for (float v : r.mean) ASSERT_LE(v, 1.0f + 1e-5f) << name;
    }
}

class CornellBox : public ::testing::Test {
protected:
    void SetUp() override {
        Warnings w;
        scene_ = loadScene(PT_SOURCE_DIR "/scenes/cornell_box.obj", w);
        reference_ = render(scene_, kSize, kSize, kSpp);
    }
    // Renders `changed` with another seed and compares it with the unchanged scene.
    void expectSameImage(const Scene& changed, const char* what, float scale = 1.0f) {
        RenderSettings s;
        s.seed = 99;
        Rendered r = render(changed, kSize, kSize, kSpp, s);
        EXPECT_EQ(r.rays.discarded, 0u) << what;
        for (float& v : r.mean) v /= scale;
        for (float& v : r.variance) v /= scale * scale;
        CompareReport report = compareImages(toImage(r), toImage(reference_));
        EXPECT_EQ(report.inputError, "") << what;
        EXPECT_TRUE(report.pass) << what << ": " << report.failedTests << " of " << report.tests
                                 << " tests fail; worst z " << report.worst[0].z << " at " << report.worst[0].x0
                                 << "," << report.worst[0].y0;
    }
    // Gives every triangle vertex normals: the geometric normal times `scale`, or minus it.
    static Scene withNormals(Scene s, float scale) {
        s.triNormals.clear();
        for (size_t t = 0; t < s.triangleCount(); ++t) {
            const glm::uvec3& tri = s.triPositions[t];
            Vec3 n = glm::normalize(glm::cross(s.positions[tri[1]] - s.positions[tri[0]],
                                               s.positions[tri[2]] - s.positions[tri[0]]));
            s.normals.push_back(n * scale);
            int i = int(s.normals.size() - 1);
            s.triNormals.emplace_back(i, i, i);
        }
        return s;
    }

    static constexpr int kSize = 48;
    static constexpr uint32_t kSpp = 256;
    Scene scene_;
    Rendered reference_;
};

// Zero-area triangles (collinear, or all three corners equal) and exact duplicates of every
// triangle: nothing may change.
TEST_F(CornellBox, DegenerateAndDuplicateTrianglesChangeNothing) {
    Scene s = scene_;
    size_t n = s.triangleCount();
    for (size_t t = 0; t < n; ++t) {
        s.triPositions.push_back(s.triPositions[t]);
        s.triMaterial.push_back(s.triMaterial[t]);
        glm::uvec3 tri = s.triPositions[t];
        s.triPositions.emplace_back(tri.x, tri.x, tri.y); // a segment
        s.triMaterial.push_back(s.triMaterial[t]);
        s.triPositions.emplace_back(tri.y, tri.y, tri.y); // a point
        s.triMaterial.push_back(s.triMaterial[t]);
    }
    expectSameImage(s, "duplicates and zero-area triangles");
}

// Vertex normals pointing inward on opaque two-sided materials, or far from unit length (even
// so far that squaring them overflows or underflows): the same image.
TEST_F(CornellBox, VertexNormalsInwardOrNotUnitLengthChangeNothing) {
    expectSameImage(withNormals(scene_, -1.0f), "inward normals");
    expectSameImage(withNormals(scene_, 1e-6f), "normals of length 1e-6");
    expectSameImage(withNormals(scene_, 1e6f), "normals of length 1e6");
    expectSameImage(withNormals(scene_, 1e-30f), "normals of length 1e-30");
    expectSameImage(withNormals(scene_, 1e30f), "normals of length 1e30");
    expectSameImage(withNormals(scene_, 0.0f), "zero normals");
}

// A camera inside glass of index 1 without Fresnel sees straight through it.
TEST_F(CornellBox, CameraInsideGlassOfIndexOneSeesThrough) {
    Scene s = scene_;
    Material clear;
    clear.transparency = 1.0f;
    clear.eta = 1.0f;
    addIcosphere(s, s.cameras[0].position, 0.3f, 2, addMaterial(s, clear));
    expectSameImage(s, "camera inside glass of index 1");
}

// Inside a small glass ball of index 1.5 centred on the camera, every camera ray leaves at normal
// incidence, undeviated, and radiance is compressed into the denser medium: the image is the
// plain one times 1.5^2.
TEST_F(CornellBox, CameraInsideGlassSeesRadianceScaledByEtaSquared) {
    Scene s = scene_;
    Material glass;
    glass.transparency = 1.0f;
    glass.eta = 1.5f;
    addIcosphere(s, s.cameras[0].position, 0.01f, 3, addMaterial(s, glass), false, true);
    expectSameImage(s, "camera inside glass of index 1.5", 2.25f);
}

// A light inside a closed opaque box is hidden: its shadow rays and its emission stay inside.
TEST_F(CornellBox, LightInsideAClosedBoxIsHidden) {
    Scene s = scene_;
    Material grey;
    grey.kd = Spectrum(0.5f);
    Vec3 c(0.5f, 0.5f, 0.3f);
    addBox(s, c - Vec3(0.1f), c + Vec3(0.1f), addMaterial(s, grey));
    LocalLight light;
    light.center = c;
    light.radius = 0.05f;
    light.intensity = Spectrum(50.0f);
    s.lights.push_back(light);
    Scene reference = s;
    reference.lights.clear();
    // Compare against the scene with the box but without the light.
    Rendered boxOnly = render(reference, kSize, kSize, kSpp);
    reference_ = boxOnly;
    expectSameImage(s, "light inside a box");
}

// A point light and a sphere light of radius 1e-5 (a cone of 1e-11 sr) give the same irradiance
// I cos / d^2 on a plane; the cone stays exact in float (sampling/warp.h).
TEST(TinyLights, TinySphereLightMatchesPointLight) {
    for (LightSampling mode : {LightSampling::Mis, LightSampling::Nee}) {
        Spectrum result[2];
        for (int k = 0; k < 2; ++k) {
            Scene scene = emptyScene(lookAt({0, 1, 1}, {0, 0, 0}, 1));
            Material m;
            m.kd = Spectrum(0.5f);
            uint32_t mat = addMaterial(scene, m);
            addQuad(scene, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}, mat);
            LocalLight light;
            light.center = Vec3(1, 2, 0);
            light.radius = k == 0 ? 0.0f : 1e-5f;
            light.intensity = Spectrum(3.0f);
            scene.lights.push_back(light);
            RenderSettings s;
            s.lightSampling = mode;
            s.maxDepth = 1;
            Rendered r = render(scene, 8, 8, 16, s);
            EXPECT_EQ(r.rays.discarded, 0u);
            result[k] = regionStats(r, 0, 0, 8, 8).mean;
        }
        float d2 = 5.0f, cosTheta = 2.0f / std::sqrt(5.0f);
        float expected = 0.5f * kInvPi * 3.0f * cosTheta / d2;
        EXPECT_NEAR(result[0].x, expected, 1e-3f * expected);
        EXPECT_NEAR(result[1].x, expected, 1e-3f * expected);
    }
}

// A camera and a floor inside a huge sphere light of radiance L: the camera sees L and the floor,
// lit from every direction, a * L, whether light or BSDF sampling finds the light.
TEST(TinyLights, InsideAnEnclosingSphereLight) {
    for (LightSampling mode : {LightSampling::Mis, LightSampling::Nee, LightSampling::Bsdf}) {
        Scene scene = emptyScene(lookAt({0, 1, 3}, {0, 0, 0}, 60));
        Material m;
        m.kd = Spectrum(0.6f);
        addQuad(scene, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}, {-20, 0, -20}, addMaterial(scene, m));
        LocalLight light;
        light.radius = 1e3f;
        light.intensity = Spectrum(kPi * 1e6f); // radiance 1
        scene.lights.push_back(light);
        RenderSettings s;
        s.lightSampling = mode;
        s.maxDepth = 1;
        Rendered r = render(scene, 16, 16, 64, s);
        EXPECT_EQ(r.rays.discarded, 0u);
        expectNear(regionStats(r, 0, 0, 16, 1), Spectrum(1.0f), 5.0f, 1e-4f, "the light seen directly");
        expectNear(regionStats(r, 4, 10, 12, 16), Spectrum(0.6f), 5.0f, 2e-3f, "the floor");
    }
}

// Volume absorption at the extremes of attenuation distance (1e-30: sigma capped at 1e30, black
// at once; 1e30: clear), on glass seen at grazing angles: finite, no discarded samples, and the
// clear one is the clear volume's image exactly.
TEST(WhiteFurnace, ExtremeAbsorptionStaysFinite) {
    Material glass = gltfGlass(true);
    RenderSettings s;
    s.maxDepth = 64;
    Rendered clear = render(furnaceScene(glass, false), 32, 32, 8, s);
    glass.attenuation = Spectrum(1e30f, 1e-30f, 0.5f);
    Rendered mixed = render(furnaceScene(glass, false), 32, 32, 8, s);
    EXPECT_EQ(mixed.rays.discarded, 0u);
    for (size_t i = 0; i < mixed.mean.size(); ++i) {
        ASSERT_TRUE(std::isfinite(mixed.mean[i]) && mixed.mean[i] >= 0.0f) << i;
        if (i % 3 == 1) EXPECT_NEAR(mixed.mean[i], clear.mean[i], 1e-5f) << "sigma 1e-30 is clear, pixel " << i / 3;
        if (i % 3 == 0) EXPECT_LE(mixed.mean[i], clear.mean[i] + 1e-6f) << "absorbing, pixel " << i / 3;
    }
}

// A sphere light inside a glass ball: only caustic paths carry its light out, which MIS cannot
// sample; the image must stay finite and non-negative.
TEST(TinyLights, LightInsideGlassStaysFinite) {
    Scene scene = emptyScene(lookAt({0, 1, 4}, {0, 0, 0}, 40));
    Material floor;
    floor.kd = Spectrum(0.7f);
    addQuad(scene, {-5, -1, 5}, {5, -1, 5}, {5, -1, -5}, {-5, -1, -5}, addMaterial(scene, floor));
    Material glass;
    glass.transparency = 1.0f;
    glass.eta = 1.5f;
    glass.blend = 1.0f;
    glass.r0 = Spectrum(0.04f);
    addIcosphere(scene, Vec3(0), 0.5f, 3, addMaterial(scene, glass), false, true);
    LocalLight light;
    light.radius = 0.1f;
    light.intensity = Spectrum(10.0f);
    scene.lights.push_back(light);
    Rendered r = render(scene, 32, 32, 32);
    EXPECT_EQ(r.rays.discarded, 0u);
    for (float v : r.mean) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
}

} // namespace
} // namespace pt::test
