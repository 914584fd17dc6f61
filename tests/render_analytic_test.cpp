// Scenes whose image is known in closed form. Each would catch a wrong estimator: a missing
// cosine or pi, a wrong pdf, a double-counted light, a self-intersecting ray.
#include "tests/test_scenes.h"

#include "io/scene_limits.h"
#include "load/scene_loader.h"
#include "scene/complete_scene.h"

#include <gtest/gtest.h>

#include <sstream>

namespace pt::test {
namespace {

// A convex Lambert object of albedo a under a constant environment E is a * E wherever it is
// seen: every bounce ray escapes. With cosine sampling each sample is exactly a * E, so any
// deviation is a bug (a self-hit from a bad ray offset, a wrong weight), not noise.
TEST(Analytic, ConvexLambertUnderConstantEnvironment) {
    Scene scene = emptyScene(lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40));
    const Spectrum E(1.0f, 2.0f, 0.5f), a(0.2f, 0.5f, 0.8f);
    scene.environment.sky = scene.environment.ground = E;
    Material m;
    m.kd = a;
    addIcosphere(scene, Vec3(0), 1.0f, 3, addMaterial(scene, m));

    Rendered r = render(scene, 32, 32, 4);
    for (int y = 10; y < 22; ++y)
        for (int x = 10; x < 22; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(r.pixel(x, y)[c], a[c] * E[c], 1e-5f * E[c]) << x << "," << y;
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(r.pixel(0, 0)[c], E[c]); // background corner

    // Uniform hemisphere sampling has variance but the same expectation.
    RenderSettings uniform;
    uniform.hemisphere = HemisphereSampling::Uniform;
    Rendered u = render(scene, 32, 32, 64, uniform);
    expectNear(regionStats(u, 10, 10, 22, 22), a * E, 5.0f, 1e-4f, "uniform hemisphere");
}

// Inside a closed surface of albedo a that emits Le everywhere, L = Le + a L, so L = Le / (1 - a);
// a path of at most D scattering events gives Le (1 + a + ... + a^D). This exercises emissive
// triangle sampling, MIS weights, Russian roulette and the depth limit together.
struct FurnaceCase {
    LightSampling mode;
    float albedo;
    SamplerKind sampler = SamplerKind::Sobol;
};

void PrintTo(const FurnaceCase& c, std::ostream* os) { *os << modeName(c.mode) << " albedo " << c.albedo; }
void PrintTo(LightSampling m, std::ostream* os) { *os << modeName(m); }

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(Furnace, ConvergesToGeometricSeries) {
    const FurnaceCase fc = GetParam();
    Scene scene = emptyScene(lookAt({0.1f, 0.05f, 0}, {0.1f, 0.05f, -1}, {0, 1, 0}, 90));
    const Spectrum Le(1.0f, 0.5f, 0.25f);
    Material m;
    m.kd = Spectrum(fc.albedo);
    m.emission = Le;
    addIcosphere(scene, Vec3(0), 1.0f, 2, addMaterial(scene, m), /*inward=*/true);

    for (int depth : {0, 1, 2, 1000}) {
        RenderSettings s;
        s.lightSampling = fc.mode;
        s.maxDepth = depth;
        s.sampler = fc.sampler;
        Rendered r = render(scene, 24, 24, 32, s);
        float series = depth == 1000 ? 1.0f / (1.0f - fc.albedo) : 0.0f;
        if (depth < 1000)
            for (int k = 0; k <= depth; ++k) series += std::pow(fc.albedo, float(k));
        expectNear(regionStats(r, 0, 0, 24, 24), Le * series, 5.0f, 1e-4f,
                   ("max-depth " + std::to_string(depth)).c_str());
        EXPECT_EQ(r.rays.discarded, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, Furnace,
                         ::testing::Values(FurnaceCase{LightSampling::Mis, 0.5f}, FurnaceCase{LightSampling::Mis, 0.8f},
                                           FurnaceCase{LightSampling::Nee, 0.5f},
                                           FurnaceCase{LightSampling::Bsdf, 0.5f},
                                           FurnaceCase{LightSampling::Mis, 0.8f, SamplerKind::Random}),
                         [](const ::testing::TestParamInfo<FurnaceCase>& info) {
                             return modeName(info.param.mode) + "_albedo" + std::to_string(int(info.param.albedo * 10)) +
                                    (info.param.sampler == SamplerKind::Random ? "_random" : "");
                         });

// A plane of reflectance Kd facing a point light of intensity I at height d: L = Kd I / (pi d^2)
// below the light. The camera looks down past the light (point lights do not occlude).
TEST(Analytic, PointLightOnPlane) {
    Scene scene = emptyScene(lookAt({0, 5, 0}, {0, 0, 0}, {0, 0, -1}, 2));
    Material m;
    m.kd = Spectrum(0.5f, 0.6f, 0.7f);
    uint32_t mat = addMaterial(scene, m);
    addQuad(scene, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}, mat);
    LocalLight light;
    light.center = Vec3(0, 2, 0);
    light.radius = 0.0f;
    light.intensity = Spectrum(3.0f, 2.0f, 1.0f);
    scene.lights.push_back(light);

    Rendered r = render(scene, 16, 16, 4);
    Spectrum expected = m.kd * light.intensity / (kPi * 4.0f);
    for (int y = 7; y < 9; ++y)
        for (int x = 7; x < 9; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.pixel(x, y)[c], expected[c], 2e-4f * expected[c]);
}

// Opaque surfaces are two-sided: a quad whose geometric normal faces away from the camera and the
// light (its winding reversed, as exported meshes often have it, or seen from behind as through
// glTF's doubleSided) must shade exactly as the quad facing them, under every direct-light
// strategy and for each material model. Before the fix the back of a glTF surface was black: its
// frame turned towards wo, but the light and BSDF samples were tested against the unturned normal.
struct TwoSidedCase {
    const char* what;
    Material material;
    LightSampling mode;
};
void PrintTo(const TwoSidedCase& c, std::ostream* os) { *os << c.what << " " << modeName(c.mode); }

Material gltfMaterial(Spectrum base, float metallic, float alpha, float clearcoat = 0.0f) {
    Material m;
    m.model = MaterialModel::MetalRough;
    m.kd = base;
    m.metallic = metallic;
    m.roughnessAlpha = alpha;
    m.eta = 1.5f;
    m.clearcoat = clearcoat;
    m.clearcoatAlpha = 0.01f;
    return m;
}

class TwoSided : public ::testing::TestWithParam<TwoSidedCase> {};

TEST_P(TwoSided, BackFacesShadeAsFrontFaces) {
    const TwoSidedCase& tc = GetParam();
    auto scene = [&](bool back) {
        Scene s = emptyScene(lookAt({1.5f, 3, 0}, {0, 0, 0}, {0, 1, 0}, 20));
        uint32_t mat = addMaterial(s, tc.material);
        if (back) addQuad(s, {-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}, mat); // normal -y
        else addQuad(s, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}, mat);      // normal +y
        LocalLight light;
        light.center = Vec3(-1, 2, 0);
        light.radius = 0.3f;
        light.intensity = Spectrum(3.0f, 2.0f, 1.0f);
        s.lights.push_back(light);
        return s;
    };
    RenderSettings settings;
    settings.lightSampling = tc.mode;
    settings.maxDepth = 1;
    const uint32_t spp = tc.mode == LightSampling::Bsdf ? 1024 : 128;
    RegionStats front = regionStats(render(scene(false), 16, 16, spp, settings), 4, 4, 12, 12);
    RegionStats back = regionStats(render(scene(true), 16, 16, spp, settings), 4, 4, 12, 12);
    ASSERT_GT(front.mean.x, 0.01f); // lit: the comparison means something
    for (int c = 0; c < 3; ++c) {
        float sigma = std::sqrt(sqr(front.stdError[c]) + sqr(back.stdError[c]));
        EXPECT_NEAR(back.mean[c], front.mean[c], 5.0f * sigma + 1e-3f * front.mean[c]) << "channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Materials, TwoSided,
    ::testing::ValuesIn([] {
        std::vector<TwoSidedCase> cases;
        Material lambert;
        lambert.kd = Spectrum(0.5f, 0.6f, 0.7f);
        const std::pair<const char*, Material> materials[] = {
            {"lab Lambert", lambert},
            {"glTF dielectric", gltfMaterial(Spectrum(0.5f, 0.6f, 0.7f), 0.0f, 0.25f)},
            {"glTF metal", gltfMaterial(Spectrum(0.9f, 0.6f, 0.3f), 1.0f, 0.2f)},
            {"glTF clear coat", gltfMaterial(Spectrum(0.5f, 0.6f, 0.7f), 0.0f, 0.5f, 1.0f)}};
        for (const auto& [what, m] : materials)
            for (LightSampling mode : {LightSampling::Mis, LightSampling::Nee, LightSampling::Bsdf})
                cases.push_back({what, m, mode});
        return cases;
    }()));

// The plane y = 0 of reflectance kPlaneKd, seen obliquely from (4, 1, 0) with the origin in the
// centre pixels, for lights placed above it: lights there do not hide the origin from the camera.
const Spectrum kPlaneKd(0.5f, 0.6f, 0.7f);

Scene obliquePlane() {
    Scene scene = emptyScene(lookAt({4, 1, 0}, {0, 0, 0}, {0, 1, 0}, 1));
    Material m;
    m.kd = kPlaneKd;
    uint32_t mat = addMaterial(scene, m);
    addQuad(scene, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}, mat);
    return scene;
}

// Direct light only, found by `mode`, in the centre region of a 16x16 render (more samples for
// BSDF sampling, which finds small lights by chance).
RegionStats directLightAtOrigin(const Scene& scene, LightSampling mode) {
    RenderSettings s;
    s.lightSampling = mode;
    s.maxDepth = 1;
    Rendered r = render(scene, 16, 16, mode == LightSampling::Bsdf ? 1024 : 64, s);
    return regionStats(r, 6, 6, 10, 10);
}

// The lab's sphere light: radiance I / (pi r^2) on its surface gives irradiance I / d^2 at a
// facing point at distance d from the centre, as a point light would. Every direct-light
// strategy must agree.
class SphereLightOnPlane : public ::testing::TestWithParam<LightSampling> {};

TEST_P(SphereLightOnPlane, MatchesPointLightIrradiance) {
    Scene scene = obliquePlane();
    LocalLight light;
    light.center = Vec3(0, 2, 0);
    light.radius = 0.5f;
    light.intensity = Spectrum(3.0f, 2.0f, 1.0f);
    scene.lights.push_back(light);
    Spectrum expected = kPlaneKd * light.intensity / (kPi * 4.0f);
    expectNear(directLightAtOrigin(scene, GetParam()), expected, 5.0f, 2e-3f, "sphere light");
}

INSTANTIATE_TEST_SUITE_P(Modes, SphereLightOnPlane,
                         ::testing::Values(LightSampling::Mis, LightSampling::Nee, LightSampling::Bsdf),
                         [](const ::testing::TestParamInfo<LightSampling>& info) { return modeName(info.param); });

// Twelve sphere lights on a ring above the plane: more than Accel tests one by one, so they are
// in the BVH, and the light tree chooses among them. Each still gives I cos / d^2 at the point
// below the ring's centre, and the sum must come out whichever strategy finds them.
class ManySphereLightsOnPlane : public ::testing::TestWithParam<LightSampling> {};

TEST_P(ManySphereLightsOnPlane, MatchTheSumOfTheirIrradiances) {
    Scene scene = obliquePlane();
    Spectrum irradiance(0.0f);
    for (int k = 0; k < 12; ++k) {
        LocalLight light;
        float phi = 2.0f * kPi * float(k) / 12.0f;
        light.center = Vec3(1.5f * std::cos(phi), 2.0f, 1.5f * std::sin(phi));
        light.radius = 0.3f;
        light.intensity = Spectrum(0.3f + 0.1f * float(k % 3), 0.5f, 0.8f - 0.05f * float(k));
        scene.lights.push_back(light);
        float d2 = glm::dot(light.center, light.center);
        irradiance += light.intensity * (light.center.y / std::sqrt(d2)) / d2;
    }
    expectNear(directLightAtOrigin(scene, GetParam()), kPlaneKd * irradiance * kInvPi, 5.0f, 2e-3f,
               "twelve sphere lights");
}

INSTANTIATE_TEST_SUITE_P(Modes, ManySphereLightsOnPlane,
                         ::testing::Values(LightSampling::Mis, LightSampling::Nee, LightSampling::Bsdf),
                         [](const ::testing::TestParamInfo<LightSampling>& info) { return modeName(info.param); });

// Camera and BSDF rays that hit a sphere light see its radiance I / (pi r^2), and it reflects
// nothing.
TEST(Analytic, SphereLightSeenDirectly) {
    Scene scene = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 10));
    LocalLight light;
    light.radius = 0.5f;
    light.intensity = Spectrum(1.0f, 2.0f, 3.0f);
    scene.lights.push_back(light);
    Rendered r = render(scene, 16, 16, 2);
    Spectrum L = light.intensity / (kPi * 0.25f);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(r.pixel(8, 8)[c], L[c]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(r.pixel(0, 0)[c], 0.0f); // beyond the sphere: black
}

// The lab's environment: sky above the horizon, ground below.
TEST(Analytic, EnvironmentSkyAndGround) {
    Scene scene = emptyScene(lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60));
    scene.environment = Environment{};
    Rendered r = render(scene, 16, 16, 1);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(r.pixel(8, 2)[c], Environment{}.sky[c]);
        EXPECT_EQ(r.pixel(8, 13)[c], Environment{}.ground[c]);
    }
}

// The image depends on (pixel, sample, seed) only: any thread count gives the same bits.
TEST(Determinism, SameImageForAnyThreadCount) {
    Warnings w;
    Scene scene = loadScene(PT_SOURCE_DIR "/scenes/glass.obj", w);
    Rendered one = render(scene, 48, 48, 4, {}, 1);
    for (int threads : {2, 3}) {
        Rendered many = render(scene, 48, 48, 4, {}, threads);
        ASSERT_EQ(one.mean, many.mean) << threads << " threads";
        ASSERT_EQ(one.variance, many.variance) << threads << " threads";
    }
    RenderSettings other;
    other.seed = 7;
    EXPECT_NE(one.mean, render(scene, 48, 48, 4, other, 2).mean); // the seed does matter
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// Scales a scene about the origin and moves it; lab lights keep their look (I / d^2 is kept by
// scaling I with s^2), emission and the environment are radiances and need nothing.
Scene transformed(Scene scene, float scale, Vec3 translate) {
    for (Vec3& p : scene.positions) p = p * scale + translate;
    for (LocalLight& l : scene.lights) {
        l.center = l.center * scale + translate;
        l.radius *= scale;
        l.intensity *= scale * scale;
    }
    for (Camera& c : scene.cameras) {
        c.position = c.position * scale + translate;
        c.target = c.target * scale + translate;
    }
    return scene;
}

// Scaled by 1e-3 or 1e4, or moved 1e4 away from the origin, a scene renders the same image: no
// acne, no leaks, no lost contact shadows from a scale-dependent ray offset.
TEST(Invariance, ScaleAndTranslation) {
    for (const char* file : {"/scenes/cornell_box.obj", "/scenes/glass.obj"}) {
        Warnings w;
        Scene base = loadScene(std::string(PT_SOURCE_DIR) + file, w);
        Rendered reference = render(base, 64, 64, 256);
        struct Case {
            float scale;
            Vec3 translate;
        };
        for (Case c : {Case{1e-3f, Vec3(0)}, Case{1e4f, Vec3(0)}, Case{1.0f, Vec3(1e4f, -1e4f, 1e4f)}}) {
            Rendered moved = render(transformed(base, c.scale, c.translate), 64, 64, 256, RenderSettings{.seed = 5});
            std::ostringstream what;
            what << file << " scale " << c.scale << " translate " << c.translate.x;
            expectSameImage(moved, reference, what.str());
        }
    }
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

float largestCoordinate(const Scene& s) {
    float m = 0.0f;
    for (const Vec3& p : s.positions) m = std::max(m, maxComponent(glm::abs(p)));
    for (const LocalLight& l : s.lights) m = std::max(m, maxComponent(glm::abs(l.center)) + l.radius);
    for (const Camera& c : s.cameras) m = std::max(m, maxComponent(glm::abs(c.position)));
    return m;
}

float triangleSpan(const Scene& s) {
    Vec3 lo(kInf), hi(-kInf);
    for (const Vec3& p : s.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return safeLength(hi - lo);
}

// The two ends of the range the loaders accept (io/scene_limits.h): the largest coordinate at
// exactly kMaxCoordinate, and the triangles spanning exactly kMinSceneSize. Both scenes must
// load and render the unit scene's image. Beyond either end Embree loses hits (the Cornell box
// changes at 3x the largest coordinate accepted and at 1/300 of the smallest size).
TEST(Invariance, AtTheLimitsOfTheAcceptedRange) {
    for (const char* file : {"/scenes/cornell_box.obj", "/scenes/glass.obj"}) {
        Warnings w;
        Scene base = loadScene(std::string(PT_SOURCE_DIR) + file, w);
        Rendered reference = render(base, 64, 64, 256);
        for (float scale : {kMaxCoordinate / largestCoordinate(base), kMinSceneSize / triangleSpan(base)}) {
            Scene scaled = transformed(base, scale, Vec3(0));
            Warnings none;
            ASSERT_NO_THROW(completeScene(scaled, none)) << file << " at scale " << scale << " is refused";
            Rendered r = render(scaled, 64, 64, 256, RenderSettings{.seed = 5});
            EXPECT_GT(r.rays.shadow, 0u);
            std::ostringstream what;
            what << file << " scale " << scale;
            expectSameImage(r, reference, what.str());
        }
    }
}

// Just outside the range, the loaders refuse the scene instead of drawing a wrong image.
TEST(Invariance, OutsideTheRangeIsRefused) {
    Warnings w;
    Scene base = loadScene(std::string(PT_SOURCE_DIR) + "/scenes/cornell_box.obj", w);
    Scene tiny = transformed(base, 0.5f * kMinSceneSize / triangleSpan(base), Vec3(0));
    Warnings none;
    EXPECT_THROW(completeScene(tiny, none), LoadError);
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// As alpha falls to the smooth threshold, rough Spec and Refr become the delta lobes: the glass
// scene (a glass ball and a metal ball) at alpha 0.0011 renders the smooth image.
TEST(RoughLobes, ConvergeToTheSmoothOnes) {
    Warnings w;
    Scene smooth = loadScene(std::string(PT_SOURCE_DIR) + "/scenes/glass.obj", w);
    Scene rough = smooth;
    for (Material& m : rough.materials) m.roughnessAlpha = 0.0011f;
    Rendered a = render(smooth, 64, 64, 256), b = render(rough, 64, 64, 256, RenderSettings{.seed = 3});
    EXPECT_GT(b.rays.shadow, 0u);
    expectSameImage(b, a, "alpha 0.0011 against the smooth lobes");
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// Light sampling alone, BSDF sampling alone and their MIS combination estimate the same direct
// light off a rough metal floor in four strips (alpha 0.01, 0.05, 0.2, 0.5). Light sampling is
// held against MIS under small sphere lights, one reflected in each strip. BSDF sampling cannot find a small light through the
// far tails of a narrow lobe within any test's budget, so it is held against MIS under a large
// emissive panel that every mirror direction of the floor meets.
Scene roughMetalStrips() {
    Scene scene = emptyScene(lookAt({0, 0.6f, 2.5f}, {0, 0, 0}, {0, 1, 0}, 50));
    const float alphas[] = {0.01f, 0.05f, 0.2f, 0.5f};
    for (int k = 0; k < 4; ++k) {
        Material metal;
        metal.kd = Spectrum(0.0f);
        metal.blend = 1.0f;
        metal.r0 = Spectrum(0.9f, 0.7f, 0.4f);
        metal.roughnessAlpha = alphas[k];
        float x0 = -2.0f + k, x1 = x0 + 1.0f;
        addQuad(scene, {x0, 0, 1}, {x1, 0, 1}, {x1, 0, -1}, {x0, 0, -1}, addMaterial(scene, metal));
    }
    return scene;
}

void expectSameAsMis(const Scene& scene, LightSampling mode, uint32_t spp, const char* what) {
    RenderSettings mis;
    mis.maxDepth = 1;
    Rendered reference = render(scene, 48, 48, 1024, mis);
    for (int k = 0; k < 4; ++k) // every strip is in view and lit, or agreeing would prove nothing
        EXPECT_GT(maxComponent(regionStats(reference, 12 * k, 24, 12 * k + 12, 48).mean), 1e-3f) << what << " strip " << k;
    RenderSettings s = mis;
    s.lightSampling = mode;
    s.seed = 17;
    Rendered r = render(scene, 48, 48, spp, s);
    expectSameImage(r, reference, what);
}

TEST(RoughLobes, LightSamplingAgreesWithMis) {
    Scene scene = roughMetalStrips();
    // One small light per strip, placed so that its mirror image lies at the strip's centre.
    for (float xc : {-1.5f, -0.5f, 0.5f, 1.5f}) {
        LocalLight light;
        light.center = Vec3(xc * 1.6f / 0.6f, 1.0f, 2.5f - 2.5f * 1.6f / 0.6f);
        light.radius = 0.05f;
        light.intensity = Spectrum(20.0f);
        scene.lights.push_back(light);
    }
    expectSameAsMis(scene, LightSampling::Nee, 2048, "nee, small sphere lights");
}

TEST(RoughLobes, BsdfSamplingAgreesWithMis) {
    Scene scene = roughMetalStrips();
    Material panel;
    panel.kd = Spectrum(0.0f);
    panel.emission = Spectrum(1.0f, 0.8f, 0.6f);
    addQuad(scene, {-20, 1, -20}, {20, 1, -20}, {20, 1, 20}, {-20, 1, 20}, addMaterial(scene, panel));
    expectSameAsMis(scene, LightSampling::Bsdf, 1024, "bsdf, large panel");
}

} // namespace
} // namespace pt::test
