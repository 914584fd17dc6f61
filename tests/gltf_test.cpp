// glTF 2.0 loading and rendering: node transforms against pre-transformed triangles, each light
// type against its analytic radiance on a plane, texture orientation, alpha modes, cameras, the
// default lighting, and the Khronos sample models loading and rendering without NaN.
#include "accel/accel.h"
#include "gltf/gltf_loader.h"
#include "material/sheen.h"
#include "render/vertex_tangents.h"
#include "load/scene_loader.h"
#include "scene/complete_scene.h"
#include "tests/gltf_brdf_reference.h"
#include "tests/test_scenes.h"


#include "material/evaluate_material.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace pt::test {
namespace {

const std::string kGltf = PT_SOURCE_DIR "/scenes/gltf/";

Scene load(const std::string& path, Warnings* warningsOut = nullptr) {
    Warnings w;
    Scene s = loadScene(path, w);
    addDefaultLighting(s, w);
    if (warningsOut) *warningsOut = w;
    return s;
}

TEST(Gltf, NodeTransformsEqualPreTransformedTriangles) {
    Scene a = load(kGltf + "transforms.gltf"), b = load(kGltf + "transforms_flat.gltf");
    ASSERT_EQ(a.triangleCount(), 12u);
    ASSERT_EQ(b.triangleCount(), a.triangleCount());
    for (size_t t = 0; t < a.triangleCount(); ++t) {
        Vec3 pa[3], pb[3];
        for (int k = 0; k < 3; ++k) pa[k] = a.positions[a.triPositions[t][k]], pb[k] = b.positions[b.triPositions[t][k]];
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(pa[k][c], pb[k][c], 1e-5f) << "triangle " << t << " corner " << k;
        // The same winding: the mirrored instance's triangles are turned back to face outwards.
        Vec3 na = glm::cross(pa[1] - pa[0], pa[2] - pa[0]), nb = glm::cross(pb[1] - pb[0], pb[2] - pb[0]);
        EXPECT_GT(glm::dot(na, nb), 0.0f) << "triangle " << t;
    }
    // The transformed box renders as the flat one does.
    a.cameras = b.cameras = {lookAt({3, 2, 4}, {0, 0.3f, 0}, 40)};
    RenderSettings s;
    expectSameImage(render(a, 24, 24, 64, s), render(b, 24, 24, 64, s), "transformed against flat");
}

// A white dielectric plane (roughness 1) under each light, seen straight down by an orthographic
// camera at depth 1: every pixel's radiance is f(wo = up, wi) E(wi), with f the specification's
// BRDF and E the light's irradiance, 683 cd or lux being 1 W/sr or W/m^2.
struct Expected {
    std::string file;
    std::function<Spectrum(Vec3 p)> radiance;
};

Spectrum brdfTimesCos(Vec3 towardsLight) {
    Vec3 v(0, 0, 1), l(towardsLight.x, towardsLight.z, towardsLight.y); // the plane's frame: z up
    return specBrdf(Spectrum(0.8f), 0.0f, 1.0f, v, l) * l.z;
}

TEST(Gltf, LightsMatchTheirAnalyticRadianceOnAPlane) {
    const Vec3 lamp(0, 2, 0);
    auto point = [&](Vec3 p, float falloff) {
        Vec3 d = lamp - p;
        float d2 = glm::dot(d, d);
        return brdfTimesCos(glm::normalize(d)) * (falloff / d2);
    };
    std::vector<Expected> cases = {
        {"plane_point.gltf", [&](Vec3 p) { return point(p, 1.0f); }},
        {"plane_range.gltf",
         [&](Vec3 p) {
             float d = glm::length(lamp - p);
             return point(p, sqr(std::clamp(1.0f - sqr(sqr(d / 3.0f)), 0.0f, 1.0f)));
         }},
        {"plane_spot.gltf",
         [&](Vec3 p) {
             float cd = glm::normalize(p - lamp).y * -1.0f; // the spot points straight down
             float t = std::clamp((cd - std::cos(0.5f)) / (std::cos(0.2f) - std::cos(0.5f)), 0.0f, 1.0f);
             return point(p, t * t);
         }},
        {"plane_directional.gltf",
         [&](Vec3) {
             // The light's -z turned by -60 degrees about x: it shines down and towards -z, so it
             // comes from (0, cos 30, sin 30), 30 degrees from the normal.
             float a = 30.0f * kPi / 180.0f;
             return brdfTimesCos(Vec3(0, std::cos(a), std::sin(a)));
         }},
    };
    for (const Expected& c : cases) {
        Scene scene = load(kGltf + c.file);
        ASSERT_EQ(scene.cameras.size(), 1u);
        ASSERT_GT(scene.cameras[0].orthoHalfHeight, 0.0f);
        RenderSettings s;
        s.maxDepth = 1;
        const int n = 16;
        Rendered r = render(scene, n, n, 256, s);
        // Pixel (i, j) sees the plane at x = -2 + 4 (i + 0.5) / n, z = -2 + 4 (j + 0.5) / n (row 0 at -z).
        for (int j = 1; j < n - 1; j += 3)
            for (int i = 1; i < n - 1; i += 3) {
                Vec3 p(-2.0f + 4.0f * (i + 0.5f) / n, 0.0f, -2.0f + 4.0f * (j + 0.5f) / n);
                // Average the expectation over the pixel, as the render does (the spot's edge is steep).
                const int k = 16;
                Spectrum want(0.0f);
                for (int sy = 0; sy < k; ++sy)
                    for (int sx = 0; sx < k; ++sx)
                        want += c.radiance(p + Vec3((sx + 0.5f - 0.5f * k) / k * 4.0f / n, 0,
                                                    (sy + 0.5f - 0.5f * k) / k * 4.0f / n));
                want /= float(k * k);
                Spectrum got = r.pixel(i, j);
                EXPECT_NEAR(got.y, want.y, 0.01f * want.y + 1e-5f) << c.file << " pixel " << i << ", " << j;
            }
    }
}

// glTF's uv (0, 0) is the image's top-left corner: the checker's dark top-left block shows at
// the top-left of the quad, seen from +z.
TEST(Gltf, TexturesAreTheRightWayUp) {
    Scene scene = load(kGltf + "bin_and_image.gltf");
    ASSERT_EQ(scene.textures->size(), 1u);
    for (const char* file : {"bin_and_image.gltf", "bin_and_image.bin", "checker.png"})
        EXPECT_NE(std::find_if(scene.sources.begin(), scene.sources.end(),
                               [&](const SourceFile& f) { return f.path == kGltf + file && f.hash != 0; }),
                  scene.sources.end())
            << file;
    scene.cameras = {lookAt({0, 0, 3}, {0, 0, 0}, 30)};
    RenderSettings s;
    s.maxDepth = 1;
    Rendered r = render(scene, 32, 32, 16, s);
    float topLeft = regionStats(r, 9, 9, 14, 14).mean.y, topRight = regionStats(r, 18, 9, 23, 14).mean.y;
    float bottomLeft = regionStats(r, 9, 18, 14, 23).mean.y;
    EXPECT_LT(topLeft * 5.0f, topRight);
    EXPECT_LT(topLeft * 5.0f, bottomLeft);
}

// A sampler's wrapS and wrapT reach the map, each by its own: MIRRORED_REPEAT in s, CLAMP_TO_EDGE
// in t (the lookup tests are in texture_test.cpp).
TEST(Gltf, SamplerWrapsEachAxis) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("pt_gltf_wrap_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const char* file : {"bin_and_image.bin", "checker.png"}) fs::copy_file(kGltf + file, dir / file);
    std::ifstream in(kGltf + "bin_and_image.gltf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string source = "\"source\": 0";
    ASSERT_NE(text.find(source), std::string::npos);
    text.replace(text.find(source), source.size(), source + ", \"sampler\": 0");
    text.insert(text.rfind('}'), ", \"samplers\": [{\"wrapS\": 33648, \"wrapT\": 33071}]");
    std::ofstream(dir / "wrap.gltf") << text;
    Warnings w;
    Scene scene = loadScene((dir / "wrap.gltf").string(), w);
    fs::remove_all(dir);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].kdMap.wrapU, TextureWrap::Mirror);
    EXPECT_EQ(scene.materials[0].kdMap.wrapV, TextureWrap::Clamp);
    for (const std::string& warning : w.messages()) EXPECT_EQ(warning.find("MIRRORED"), std::string::npos) << warning;
}

TEST(Gltf, AlphaModesCoverAsSpecified) {
    Scene scene = load(kGltf + "alpha_modes.gltf");
    RenderSettings s;
    s.maxDepth = 1;
    Rendered r = render(scene, 160, 100, 16, s);
    // The quads cover pixel columns 0 to 35 (OPAQUE), 42 to 90 (MASK) and 97 to 145 (BLEND), rows
    // 43 to 77; alpha rises from 0 at each quad's left edge to 1 at its right.
    auto redness = [&](int x0, int x1) {
        Spectrum m = regionStats(r, x0, 50, x1, 70).mean;
        return m.x / std::max(1e-6f, m.y);
    };
    EXPECT_LT(redness(10, 30), 1.5f);   // OPAQUE ignores alpha: white even where alpha is 0
    // and equally bright there: colour and alpha are separate in glTF, so alpha never darkens the
    // colour (premultiplied on reading, the OPAQUE quad fell to black at its alpha-0 edge).
    const float opaqueLeft = regionStats(r, 2, 50, 8, 70).mean.y, opaqueRight = regionStats(r, 28, 50, 34, 70).mean.y;
    EXPECT_NEAR(opaqueLeft, opaqueRight, 0.03f * opaqueRight);
    EXPECT_NEAR(regionStats(r, 80, 50, 86, 70).mean.y, opaqueRight, 0.03f * opaqueRight); // MASK above its cutoff
    EXPECT_GT(redness(46, 58), 4.0f);   // MASK, alpha below 0.5: the red wall shows
    EXPECT_LT(redness(74, 86), 1.5f);   // MASK, alpha above 0.5: the quad
    EXPECT_GT(redness(100, 106), 3.0f); // BLEND: mostly the wall where alpha is below 0.2
    EXPECT_GT(redness(100, 106), 2.0f * redness(136, 142)); // and mostly the quad above 0.8
    EXPECT_GT(redness(136, 142), 1.05f);                    // still a little see-through
}

// Without a camera the view frames what can be seen: the meshes, not a point light's position
// (issue 35: a lamp's light 100 units off to the side shrank the plane to a dot, and Blender's
// framing, which takes the meshes, saw another picture).
TEST(Gltf, FramingCameraFramesTheMeshesNotThePointLights) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(::testing::TempDir()) / "pt_gltf_framing";
    fs::create_directories(dir);
    nlohmann::json d = nlohmann::json::parse(std::ifstream(kGltf + "plane_point.gltf"));
    // The light node moves from (0, 2, 0) to (100, 2, 0); the camera node goes from the scene.
    ASSERT_EQ(d["nodes"][1]["translation"], nlohmann::json::array({0.0, 2.0, 0.0}));
    d["nodes"][1]["translation"] = {100.0, 2.0, 0.0};
    d["scenes"][0]["nodes"] = {0, 1};
    std::string text = d.dump();
    std::ofstream(dir / "lamp_aside.gltf") << text;
    Scene scene = load((dir / "lamp_aside.gltf").string());
    ASSERT_EQ(scene.cameras.size(), 1u);
    const Camera& c = scene.cameras[0];
    EXPECT_EQ(c.name, "auto");
    // The plane spans [-50, 50] in x and z at y = 0: its box's centre, from +z at its bounding
    // sphere's distance for a 45 degree view.
    EXPECT_NEAR(glm::length(c.target - Vec3(0.0f)), 0.0f, 1e-4f);
    EXPECT_NEAR(c.position.z, 50.0f * std::sqrt(2.0f) / std::sin(glm::radians(22.5f)), 1e-2f);
}

TEST(Gltf, CamerasKeepTheirAspectAndProjection) {
    Scene scene = load(kGltf + "cameras.gltf");
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_EQ(scene.cameras[0].name, "Wide");
    EXPECT_NEAR(scene.cameras[0].fovY, 30.0f, 1e-4f);
    EXPECT_NEAR(scene.cameras[0].aspect, 2.0f, 1e-6f);
    EXPECT_NEAR(scene.cameras[0].position.x, 2.0f, 1e-5f);
    Vec3 ahead = glm::normalize(scene.cameras[0].target - scene.cameras[0].position);
    Vec3 wanted = glm::normalize(Vec3(-2.0f, -1.5f, -3.0f));
    EXPECT_GT(glm::dot(ahead, wanted), 0.99999f);
    EXPECT_EQ(scene.cameras[1].name, "Ortho");
    EXPECT_NEAR(scene.cameras[1].orthoHalfHeight, 1.0f, 1e-6f);
    EXPECT_NEAR(scene.cameras[1].aspect, 1.5f, 1e-6f);
}

TEST(Gltf, UnlitFilesGetAWhiteEnvironmentAndLitOnesABlackOne) {
    Warnings w;
    Scene unlit = load(kGltf + "alpha_modes.gltf", &w);
    ASSERT_TRUE(unlit.environment.map);
    EXPECT_EQ(unlit.environment.map->radiance(Vec3(0, 1, 0)), Spectrum(1.0f));
    bool warned = false;
    for (const std::string& m : w.messages()) warned |= m.find("has no lights") != std::string::npos;
    EXPECT_TRUE(warned);
    Scene lit = load(kGltf + "spheres.gltf");
    EXPECT_FALSE(lit.environment.map);
    EXPECT_TRUE(isBlack(lit.environment.radiance(Vec3(0, 1, 0))));
    EXPECT_EQ(lit.lights.size(), 1u);
    EXPECT_EQ(lit.directionalLights.size(), 1u);
    EXPECT_TRUE(lit.lights[0].isSpot());
}

// The five Khronos models of ../shared/gltf load and render without NaN or negative values.
TEST(Gltf, SampleModelsRenderWithoutNan) {
    const std::string dir = PT_SOURCE_DIR "/../shared/gltf/";
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " is absent (shared data)";
    for (const char* name : {"Box", "BoxTextured", "Duck", "DamagedHelmet", "MetalRoughSpheresNoTextures"})
        for (const char* form : {"glTF-Binary/%s.glb", "glTF/%s.gltf"}) {
            char rel[128];
            std::snprintf(rel, sizeof rel, form, name);
            std::string path = dir + name + "/" + rel;
            if (!std::filesystem::exists(path)) continue;
            Scene scene = load(path);
            EXPECT_GT(scene.triangleCount(), 0u) << path;
            RenderSettings s;
            Rendered r = render(scene, 24, 24, 8, s);
            double sum = 0.0;
            for (float v : r.mean) {
                ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << path;
                sum += v;
            }
            EXPECT_GT(sum, 0.0) << path;
            EXPECT_EQ(r.rays.discarded, 0u) << path;
        }
}

TEST(Gltf, RequiredExtensionsMustBeSupported) {
    EXPECT_TRUE(gltfExtensionSupported("KHR_lights_punctual"));
    EXPECT_TRUE(gltfExtensionSupported("KHR_texture_transform"));
    EXPECT_FALSE(gltfExtensionSupported("KHR_draco_mesh_compression"));
    EXPECT_FALSE(gltfExtensionSupported("EXT_meshopt_compression"));
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// The Cornell box as OBJ + MTL and as glTF (scenes/make_gltf.py writes it from the OBJ): Lambert
// walls through KHR_materials_specular's weight 0, the lamp's Ke through emissive strength, the
// MTL's camera as a glTF camera node. Where the OBJ says what glTF cannot (TallBox's
// Fresnel-blended mirror), the OBJ's material is made Lambert here; and both get one black
// environment (the OBJ's lab sky and the glTF's default white differ by design).
TEST(Gltf, CornellBoxEqualsItsObj) {
    Warnings w;
    Scene obj = loadScene(PT_SOURCE_DIR "/scenes/cornell_box.obj", w);
    Scene gltf = loadScene(kGltf + "cornell_box.gltf", w);
    ASSERT_EQ(obj.triangleCount(), gltf.triangleCount());
    for (Material& m : obj.materials)
        if (m.name == "TallBox") m.blend = 0.0f;
    for (Scene* s : {&obj, &gltf}) s->environment = Environment{}, s->environment.sky = s->environment.ground = Spectrum(0.0f);
    ASSERT_EQ(gltf.cameras.size(), 1u);
    EXPECT_NEAR(gltf.cameras[0].fovY, obj.cameras[0].fovY, 1e-4f);
    RenderSettings s;
    s.seed = 3;
    Rendered a = render(obj, 32, 32, 512, s);
    s.seed = 4;
    expectSameImage(render(gltf, 32, 32, 512, s), a, "glTF Cornell box against the OBJ");
}

// KHR_materials_transmission as a smooth clear dielectric: a white glass sphere in a white
// furnace reflects and refracts all it receives, so it vanishes (radiance 1 everywhere); a rough
// one loses only what single scattering loses, and the base colour tints what passes.
// An empty scene seen from (0, 0, 4) under a uniform white environment map (a light: sampled).
// A glTF metallic-roughness dielectric: base colour kd, GGX alpha, ior eta.
Material dielectric(Spectrum kd, float alpha, float eta) {
    Material m;
    m.model = MaterialModel::MetalRough;
    m.kd = kd;
    m.metallic = 0.0f;
    m.roughnessAlpha = alpha;
    m.eta = eta;
    return m;
}

Scene whiteFurnace() {
    Scene s = emptyScene(lookAt({0, 0, 4}, {0, 0, 0}, 30));
    auto white = std::make_shared<EnvironmentMap>();
    white->width = 4, white->height = 2;
    white->rgb.assign(4 * 2 * 3, 1.0f);
    s.environment.map = white;
    return s;
}

TEST(Gltf, TransmissionInAFurnace) {
    Scene s = whiteFurnace();
    Material glass = dielectric(Spectrum(1.0f), 0.0f, 1.5f);
    glass.transparency = 1.0f;
    glass.volume = true;
    addIcosphere(s, Vec3(0), 1.0f, 4, addMaterial(s, glass), false, true);
    RenderSettings settings;
    settings.maxDepth = 64;
    Rendered r = render(s, 16, 16, 256, settings);
    expectNear(regionStats(r, 4, 4, 12, 12), Spectrum(1.0f), 4.0f, 2e-3f, "smooth white glass in a furnace");
    s.materials[0].volume = false; // thin-walled
    expectNear(regionStats(render(s, 16, 16, 256, settings), 4, 4, 12, 12), Spectrum(1.0f), 4.0f, 2e-3f,
               "a smooth white thin wall in a furnace");
    s.materials[0].volume = true;

    s.materials[0].kd = Spectrum(0.5f, 1.0f, 1.0f); // red is tinted at each of the two crossings
    Rendered tinted = render(s, 16, 16, 256, settings);
    RegionStats centre = regionStats(tinted, 7, 7, 9, 9);
    EXPECT_LT(centre.mean.x, 0.5f * centre.mean.y) << "red passes the glass tinted twice";
    EXPECT_NEAR(centre.mean.y, 1.0f, 0.02f);
}

// Transmission without KHR_materials_volume is a thin wall: a sheet of ior 1.5 in front of an
// emitter of radiance 1, seen head-on, passes 1 - F(0) = 0.96 of it, undisplaced: the emitter's
// edge stays where it is without the sheet. Refracting (with a volume), a tilted sheet would
// shift it.
TEST(Gltf, ThinWallTransmitsUnbent) {
    auto scene = [](bool sheet) {
        Scene s = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, 20));
        Material wall;
        wall.kd = Spectrum(0.0f);
        wall.emission = Spectrum(1.0f);
        addQuad(s, {0, -5, -2}, {5, -5, -2}, {5, 5, -2}, {0, 5, -2}, addMaterial(s, wall)); // the right half
        if (sheet) {
            Material glass = dielectric(Spectrum(1.0f), 0.0f, 1.5f);
            glass.transparency = 1.0f;
            addQuad(s, {-3, -3, -0.5f}, {3, -3, 0.5f}, {3, 3, 0.5f}, {-3, 3, -0.5f}, addMaterial(s, glass)); // tilted
        }
        return render(s, 32, 32, 1024);
    };
    Rendered with = scene(true), without = scene(false);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            float a = with.pixel(x, y).x, b = without.pixel(x, y).x;
            if (b == 0.0f || b == 1.0f) // pixels wholly off or on the emitter: the same ones with the sheet
                EXPECT_NEAR(a, 0.96f * b, 0.025f) << x << ", " << y; // 4 % of samples take the mirror
        }
}

// KHR_materials_unlit: camera rays see the base colour and nothing else sees the surface. A quad
// facing the camera shows kd exactly under a white sky; a quad between a point light and a lit
// floor, out of the camera's view, changes the image not at all (no shadow, no bounce), where a
// Lambert quad in its place shadows the floor.
TEST(Gltf, UnlitIsSeenByCameraRaysOnly) {
    Material unlit;
    unlit.model = MaterialModel::MetalRough;
    unlit.kd = Spectrum(0.8f, 0.2f, 0.1f);
    unlit.unlit = true;
    Scene facing = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, 10));
    facing.environment.sky = Spectrum(1.0f);
    addQuad(facing, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, addMaterial(facing, unlit));
    expectNear(regionStats(render(facing, 8, 8, 16), 0, 0, 8, 8), unlit.kd, 0.0f, 1e-6f, "an unlit quad seen by the camera");

    auto lit = [](const Material* quad) {
        Scene s = emptyScene(lookAt({1, 0.5f, 3}, {1, 0, 0}, 30));
        Material floor;
        floor.kd = Spectrum(0.5f);
        addQuad(s, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, addMaterial(s, floor));
        if (quad) addQuad(s, {0.2f, 1, 0.3f}, {0.8f, 1, 0.3f}, {0.8f, 1, -0.3f}, {0.2f, 1, -0.3f}, addMaterial(s, *quad));
        LocalLight lamp;
        lamp.center = Vec3(0, 2, 0);
        lamp.intensity = Spectrum(5.0f);
        s.lights.push_back(lamp);
        return render(s, 32, 16, 16).mean;
    };
    EXPECT_EQ(lit(&unlit), lit(nullptr)) << "the unlit quad above the view casts no shadow and reflects nothing";
    Material lambert;
    lambert.kd = Spectrum(0.8f);
    EXPECT_NE(lit(&lambert), lit(nullptr)) << "a Lambert quad in its place shadows the floor in view";
}

// KHR_materials_transmission with metallic: the specification mixes a metal (a mirror with the
// base colour's Fresnel, no transmission, no diffuse) and the dielectric (Fresnel over
// transmission T and (1 - T) Lambert) by metallic. A smooth, fully transmitting material of
// metallic 0.5 is half mirror, half glass: no diffuse lobe, which pt's tree gave it before
// (0.25 (1 - F) of the base colour), so a glass globe of metallic 0.5 came out frosted.
TEST(Gltf, PartlyMetallicGlassIsMetalAndGlassMixed) {
    const Spectrum base(0.9f, 0.7f, 0.5f);
    for (float metallic : {0.0f, 0.5f, 1.0f})
        for (float transmission : {1.0f, 0.6f})
            for (float cosTheta : {1.0f, 0.5f, 0.1f}) {
                Material m = dielectric(base, 0.0f, 1.5f);
                m.transparency = transmission;
                m.volume = true;
                MetalRoughParameters p;
                p.baseColor = base;
                p.metallic = metallic;
                p.alpha = 0.0f;
                const LabBsdf b = LabBsdf::make(transmissionParameters(m, p, SurfaceInputs{}), cosTheta);
                const Spectrum fMetal = schlickFresnel(base, cosTheta), fGlass = schlickFresnel(Spectrum(0.04f), cosTheta);
                const Spectrum mirror = metallic * fMetal + (1.0f - metallic) * fGlass;
                const Spectrum glass = (1.0f - metallic) * (Spectrum(1.0f) - fGlass);
                for (int c = 0; c < 3; ++c) {
                    SCOPED_TRACE("metallic " + std::to_string(metallic) + ", transmission " + std::to_string(transmission) +
                                 ", cos " + std::to_string(cosTheta) + ", channel " + std::to_string(c));
                    EXPECT_NEAR(b.mirror[c], mirror[c], 1e-5f);
                    EXPECT_NEAR(b.refract[c], glass[c] * transmission * base[c], 1e-5f);
                    EXPECT_NEAR(b.diffuse[c], glass[c] * (1.0f - transmission) * base[c], 1e-5f);
                }
            }
    // In a render: a smooth, fully transmitting sphere of metallic 0.5 has delta lobes only, so
    // direct light (--max-depth 1) sends no shadow ray from it (0.26 M at 256 spp before).
    Scene s = whiteFurnace();
    Material globe = dielectric(base, 0.0f, 1.5f);
    globe.transparency = 1.0f;
    globe.volume = true;
    globe.metallic = 0.5f;
    addIcosphere(s, Vec3(0), 1.0f, 3, addMaterial(s, globe), false, true);
    RenderSettings one;
    one.maxDepth = 1;
    EXPECT_EQ(render(s, 16, 16, 16, one).rays.shadow, 0u);
}

// doubleSided false: the camera does not see an opaque surface from behind (its winding turned
// away); a transmitting one keeps both sides. Under a white sky a dark quad facing the camera is
// seen; turned away it is not (the sky, 1 exactly), unless it is double-sided or transmits.
TEST(Gltf, SingleSidedSurfacesAreNotSeenFromBehind) {
    auto seen = [](Material m, bool facing) {
        Scene s = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, 10));
        s.environment.sky = s.environment.ground = Spectrum(1.0f);
        const uint32_t mat = addMaterial(s, m);
        if (facing) addQuad(s, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, mat); // normal +z, to the camera
        else addQuad(s, {-3, -3, 0}, {-3, 3, 0}, {3, 3, 0}, {3, -3, 0}, mat);        // normal -z
        return regionStats(render(s, 8, 8, 16), 0, 0, 8, 8).mean;
    };
    Material dark = dielectric(Spectrum(0.1f), 0.25f, 1.5f);
    dark.singleSided = true;
    EXPECT_LT(seen(dark, true).y, 0.5f) << "its front is seen";
    EXPECT_EQ(seen(dark, false), Spectrum(1.0f)) << "its back is not seen: the sky";
    Material twoSided = dark;
    twoSided.singleSided = false;
    EXPECT_LT(seen(twoSided, false).y, 0.5f) << "a double-sided surface is seen from behind";
    Material glass = dielectric(Spectrum(0.9f, 0.1f, 0.1f), 0.0f, 1.5f);
    glass.transparency = 1.0f;
    glass.singleSided = true;
    EXPECT_LT(seen(glass, false).y, 0.5f) << "a transmitting surface keeps its back: red glass";
}

// Every ray but the camera's sees both sides of a single-sided surface: a quad above the view,
// between a lamp and the floor, shadows the floor the same whichever way it faces (a surface
// culled for light transport too would be one-way glass, letting through the light of whatever
// lies behind it). A single-sided emitter lights the floor from its back as from its front, and
// next-event estimation, BSDF sampling and MIS agree on it.
TEST(Gltf, SingleSidedSurfacesHaveTwoSidesForLight) {
    Material dark = dielectric(Spectrum(0.1f), 0.25f, 1.5f);
    dark.singleSided = true;
    auto floor = [&](const Material* quad, bool facingFloor) {
        Scene s = emptyScene(lookAt({1, 0.5f, 3}, {1, 0, 0}, 30));
        Material ground;
        ground.kd = Spectrum(0.5f);
        addQuad(s, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, addMaterial(s, ground));
        if (quad) {
            const uint32_t mat = addMaterial(s, *quad);
            if (facingFloor) addQuad(s, {0.2f, 1, -0.3f}, {0.8f, 1, -0.3f}, {0.8f, 1, 0.3f}, {0.2f, 1, 0.3f}, mat); // normal -y
            else addQuad(s, {0.2f, 1, 0.3f}, {0.8f, 1, 0.3f}, {0.8f, 1, -0.3f}, {0.2f, 1, -0.3f}, mat);           // normal +y
        }
        LocalLight lamp;
        lamp.center = Vec3(0, 2, 0);
        lamp.intensity = Spectrum(5.0f);
        s.lights.push_back(lamp);
        RenderSettings one;
        one.maxDepth = 1;
        return render(s, 32, 16, 16, one).mean;
    };
    EXPECT_NE(floor(&dark, true), floor(nullptr, true)) << "the quad shadows the floor";
    EXPECT_EQ(floor(&dark, false), floor(&dark, true)) << "whichever way it faces";

    auto lit = [](bool faceDown) {
        Scene s = emptyScene(lookAt({0, 3, 4}, {0, 0, 0}, 40));
        Material ground;
        ground.kd = Spectrum(0.6f);
        addQuad(s, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, addMaterial(s, ground));
        Material lamp = dielectric(Spectrum(0.0f), 1.0f, 1.5f);
        lamp.emission = Spectrum(4.0f, 3.0f, 2.0f);
        lamp.singleSided = true;
        const uint32_t mat = addMaterial(s, lamp);
        if (faceDown) addQuad(s, {-1, 1.5f, -1}, {1, 1.5f, -1}, {1, 1.5f, 1}, {-1, 1.5f, 1}, mat); // normal -y
        else addQuad(s, {-1, 1.5f, 1}, {1, 1.5f, 1}, {1, 1.5f, -1}, {-1, 1.5f, -1}, mat);          // normal +y
        return s;
    };
    RenderSettings one;
    one.maxDepth = 1;
    const RegionStats down = regionStats(render(lit(true), 16, 12, 256, one), 0, 9, 16, 12);
    const RegionStats up = regionStats(render(lit(false), 16, 12, 256, one), 0, 9, 16, 12);
    ASSERT_GT(down.mean.x, 0.05f);
    expectNear(up, down.mean, 5.0f, 1e-3f, "the floor lit by a single-sided lamp's back, against its front");
    expectStrategiesAgree(lit(false));
}

// KHR_materials_volume's absorption, Beer-Lambert along the path inside: a slab of ior 1 (no
// refraction, no Fresnel at normal incidence) and thickness 0.5 in front of an emitter of
// radiance 1 transmits exp(-sigma 0.5) per channel, sigma from attenuationColor and
// attenuationDistance as the extension defines it.
Material absorbingGlass(Spectrum color, float distance) {
    Material glass = dielectric(Spectrum(1.0f), 0.0f, 1.0f);
    glass.transparency = 1.0f;
    glass.volume = true;
    for (int c = 0; c < 3; ++c) glass.attenuation[c] = -std::log(color[c]) / distance;
    return glass;
}

TEST(Gltf, VolumeAbsorbsByBeerLambert) {
    Scene s = emptyScene(lookAt({0, 0, 5}, {0, 0, 0}, 5));
    Material wall;
    wall.kd = Spectrum(0.0f);
    wall.emission = Spectrum(1.0f);
    addQuad(s, {-5, -5, -2}, {5, -5, -2}, {5, 5, -2}, {-5, 5, -2}, addMaterial(s, wall));
    const Spectrum color(0.8f, 0.4f, 0.1f);
    addBox(s, {-3, -3, -0.5f}, {3, 3, 0}, addMaterial(s, absorbingGlass(color, 2.0f)));
    Rendered r = render(s, 8, 8, 16);
    Spectrum expected;
    for (int c = 0; c < 3; ++c) expected[c] = std::pow(color[c], 0.5f / 2.0f); // exp(-sigma d) = color^(d / distance)
    // 1e-3: the image's corner rays cross the slab 0.1 % longer than 0.5.
    expectNear(regionStats(r, 0, 0, 8, 8), expected, 0.0f, 1e-3f, "slab of thickness 0.5, attenuation distance 2");

    // Without the volume (thin-walled, or a clear volume) nothing is absorbed.
    s.materials[1].volume = false;
    expectNear(regionStats(render(s, 8, 8, 16), 0, 0, 8, 8), Spectrum(1.0f), 0.0f, 1e-4f, "no volume");
}

// A next-event shadow ray that starts inside a volume is absorbed along its length: a Lambert
// floor inside an absorbing box of ior 1, lit by a point light inside it, seen from above. The
// camera ray travels 1.99 inside and the shadow ray 0.99, so the floor's radiance is the clear
// box's times exp(-sigma 2.98).
TEST(Gltf, ShadowRaysInsideAVolumeAreAbsorbed) {
    auto floorRadiance = [](Spectrum color) {
        Scene s = emptyScene(lookAt({0, 5, 0}, {0, 0, 0}, {0, 0, -1}, 2));
        Material floor;
        floor.kd = Spectrum(0.5f);
        addQuad(s, {-0.9f, 0.01f, 0.9f}, {0.9f, 0.01f, 0.9f}, {0.9f, 0.01f, -0.9f}, {-0.9f, 0.01f, -0.9f}, addMaterial(s, floor));
        addBox(s, {-1, 0, -1}, {1, 2, 1}, addMaterial(s, absorbingGlass(color, 1.0f)));
        LocalLight lamp;
        lamp.center = Vec3(0, 1, 0);
        lamp.intensity = Spectrum(1.0f);
        s.lights.push_back(lamp);
        return regionStats(render(s, 4, 4, 16), 0, 0, 4, 4).mean;
    };
    Spectrum clear = floorRadiance(Spectrum(1.0f));
    EXPECT_NEAR(clear.x, 0.5f / kPi / sqr(0.99f), 2e-3f) << "kd / pi times I / r^2";
    const Spectrum color(0.9f, 0.6f, 0.3f);
    Spectrum absorbed = floorRadiance(color);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(absorbed[c] / clear[c], std::pow(color[c], 2.98f), 2e-3f) << c;
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// COLOR_0 multiplies the base colour, interpolated across the triangle; a material whose texture
// reads TEXCOORD_1 gets that set (TEXCOORD_0 is all zeros in the file, one texel everywhere).
// Lambert surfaces under the white environment show their base colour as radiance.
TEST(Gltf, VertexColorsAndTheSecondUvSet) {
    Scene scene = load(kGltf + "vertex_colors.gltf");
    ASSERT_EQ(scene.vertexColors.size(), scene.positions.size());
    RenderSettings s;
    Rendered r = render(scene, 48, 24, 64, s);
    EXPECT_EQ(r.rays.discarded, 0u); // interpolated colours must not dip below 0 at edges
    auto expectColor = [&](int x, int y, Spectrum want, const char* what) {
        Spectrum got = regionStats(r, x, y, x + 2, y + 2).mean;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], want[c], 0.25f) << what << " channel " << c;
    };
    expectColor(3, 19, Spectrum(1, 0, 0), "bottom left: red");
    expectColor(19, 19, Spectrum(0, 1, 0), "bottom right: green");
    expectColor(19, 3, Spectrum(0, 0, 1), "top right: blue");
    expectColor(3, 3, Spectrum(1, 1, 1), "top left: white");
    // The texture's quadrants, each one texel (blurred a little by the footprint's filter).
    expectColor(30, 6, Spectrum(1, 0, 0), "TEXCOORD_1 top left");
    expectColor(40, 6, Spectrum(0, 1, 0), "TEXCOORD_1 top right");
    expectColor(30, 16, Spectrum(0, 0, 1), "TEXCOORD_1 bottom left");
    expectColor(40, 16, Spectrum(1, 1, 1), "TEXCOORD_1 bottom right");
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// A TANGENT attribute replaces the generated tangent, turned with its node (the file's
// (0, 1, 0) under a quarter turn about +z is (-1, 0, 0)), with its handedness w.
TEST(Gltf, FileTangentsAreUsed) {
    Scene scene = load(kGltf + "tangents.gltf");
    std::vector<CornerTangent> t = buildCornerTangents(scene);
    ASSERT_EQ(t.size(), 3 * scene.triangleCount());
    for (const CornerTangent& c : t) {
        EXPECT_NEAR(c.tangent.x, -1.0f, 1e-5f);
        EXPECT_NEAR(c.tangent.y, 0.0f, 1e-5f);
        EXPECT_EQ(c.sign, -1.0f);
    }
}

} // namespace
} // namespace pt::test

namespace pt::test {
namespace {

// The scene's material of that name (the first material, and a failure, where none is).
const Material& materialNamed(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials[0];
}

// KHR_materials_clearcoat as read from clearcoat.gltf: factors, alpha = roughness^2, the three
// maps with their channels, and no "ignored" warning.
TEST(Gltf, ClearcoatIsRead) {
    Warnings w;
    Scene s = load(kGltf + "clearcoat.gltf", &w);
    for (const std::string& m : w.messages()) EXPECT_EQ(m.find("ignored"), std::string::npos) << m;
    auto find = [&](const std::string& name) -> const Material& { return materialNamed(s, name); };
    EXPECT_EQ(find("Red").clearcoat, 0.0f);
    EXPECT_EQ(find("RedSmoothCoat").clearcoat, 1.0f);
    EXPECT_EQ(find("RedSmoothCoat").clearcoatAlpha, 0.0f);
    EXPECT_NEAR(find("RedRoughCoat").clearcoatAlpha, 0.16f, 1e-6f);
    const Material& t = find("TexturedCoat");
    EXPECT_NEAR(t.clearcoatAlpha, 0.25f, 1e-6f);
    EXPECT_TRUE(t.clearcoatMap.used() && t.clearcoatRoughnessMap.used() && t.clearcoatNormalMap.used());
    EXPECT_EQ(t.clearcoatMap.channel, TextureChannel::R);
    EXPECT_EQ(t.clearcoatRoughnessMap.channel, TextureChannel::G);
    EXPECT_TRUE(t.isTextured());
}

// KHR_materials_sheen as read from sheen.gltf: colour, roughness (the Charlie alpha as given),
// the colour map (sRGB) and the roughness map's alpha channel, and no "ignored" warning.
TEST(Gltf, SheenIsRead) {
    Warnings w;
    Scene s = load(kGltf + "sheen.gltf", &w);
    for (const std::string& m : w.messages()) EXPECT_EQ(m.find("ignored"), std::string::npos) << m;
    auto find = [&](const std::string& name) -> const Material& { return materialNamed(s, name); };
    EXPECT_EQ(find("Red").sheenColor, Spectrum(0.0f));
    EXPECT_EQ(find("Velvet").sheenColor, Spectrum(1.0f, 0.4f, 0.7f));
    EXPECT_NEAR(find("Velvet").sheenRoughness, 0.8f, 1e-6f);
    const Material& t = find("TexturedSheen");
    EXPECT_TRUE(t.sheenColorMap.used() && t.sheenRoughnessMap.used());
    EXPECT_EQ(t.sheenRoughnessMap.channel, TextureChannel::Alpha);
    EXPECT_TRUE((*s.textures)[t.sheenColorMap.texture].colour) << "sheenColorTexture is sRGB";
    EXPECT_TRUE(t.isTextured());
}

// A white sheen over a black base under a uniform white environment reflects the sheen's
// directional albedo E (material/sheen.h): E(1, alpha) where the sphere faces the camera.
TEST(Gltf, SheenInAFurnace) {
    Scene s = whiteFurnace();
    Material velvet = dielectric(Spectrum(0.0f), 1.0f, 1.5f);
    velvet.specular = 0.0f;
    velvet.sheenColor = Spectrum(1.0f);
    velvet.sheenRoughness = 1.0f;
    addIcosphere(s, Vec3(0), 1.0f, 5, addMaterial(s, velvet), false, true);
    Rendered r = render(s, 16, 16, 256);
    const float e = sheenAlbedo(1.0f, 1.0f);
    EXPECT_NEAR(e, 0.164f, 0.002f);
    expectNear(regionStats(r, 7, 7, 9, 9), Spectrum(e), 4.0f, 0.03f, "white sheen over black, facing");
    s.materials[0].sheenColor = Spectrum(0.5f, 0.0f, 0.0f);
    RegionStats tinted = regionStats(render(s, 16, 16, 256), 7, 7, 9, 9);
    EXPECT_NEAR(tinted.mean.x, 0.5f * e, 0.03f * e);
    EXPECT_EQ(tinted.mean.y, 0.0f);
}

// KHR_materials_unlit as read from unlit.gltf: flagged, no emission, the billboard's texture
// kept, and no warning about the extension.
TEST(Gltf, UnlitIsRead) {
    Warnings w;
    Scene s = load(kGltf + "unlit.gltf", &w);
    for (const std::string& m : w.messages()) EXPECT_EQ(m.find("unlit"), std::string::npos) << m;
    EXPECT_TRUE(materialNamed(s, "UnlitOrange").unlit);
    EXPECT_EQ(materialNamed(s, "UnlitOrange").kd, Spectrum(1.0f, 0.45f, 0.1f));
    EXPECT_TRUE(materialNamed(s, "UnlitBillboard").unlit && materialNamed(s, "UnlitBillboard").kdMap.used());
    EXPECT_FALSE(materialNamed(s, "Grey").unlit);
}

// KHR_materials_volume and the specular and transmission textures as read from volume.gltf:
// sigma = -ln(attenuationColor) / attenuationDistance, each map with its channel, no "ignored"
// warning, and the one thin-walled warning the bubble (transmission without a volume) earns.
TEST(Gltf, VolumeAndExtensionTexturesAreRead) {
    Warnings w;
    Scene s = load(kGltf + "volume.gltf", &w);
    int thin = 0;
    for (const std::string& m : w.messages()) {
        EXPECT_EQ(m.find("ignored"), std::string::npos) << m;
        if (m.find("thin-walled") != std::string::npos) {
            ++thin;
            EXPECT_NE(m.find("ThinBubble"), std::string::npos) << m;
        }
    }
    EXPECT_EQ(thin, 1);
    auto find = [&](const std::string& name) -> const Material& { return materialNamed(s, name); };
    EXPECT_TRUE(find("Clear").volume);
    EXPECT_EQ(find("Clear").attenuation, Spectrum(0.0f));
    const Material& amber = find("Amber");
    EXPECT_TRUE(amber.volume);
    EXPECT_NEAR(amber.attenuation.x, -std::log(0.9f) / 0.3f, 1e-5f);
    EXPECT_NEAR(amber.attenuation.z, -std::log(0.1f) / 0.3f, 1e-5f);
    EXPECT_FALSE(find("Floor").volume);
    const Material& banded = find("BandedTransmission");
    EXPECT_TRUE(banded.transmissionMap.used());
    EXPECT_EQ(banded.transmissionMap.channel, TextureChannel::R);
    const Material& spec = find("SpecularMaps");
    EXPECT_TRUE(spec.specularMap.used());
    EXPECT_EQ(spec.specularMap.channel, TextureChannel::Alpha);
    EXPECT_TRUE(spec.ksMap.used());
    EXPECT_EQ(spec.ks, Spectrum(2.0f));
    EXPECT_TRUE(spec.isTextured() && banded.isTextured());
}

// The analytic case of the issue: a smooth coat over a black base under a uniform white
// environment reflects Fc = 0.04 + 0.96 (1 - cos)^5, which is 0.04 where the sphere faces the
// camera; over a white Lambert base it keeps all the light (Fc + (1 - Fc) 1 = 1).
TEST(Gltf, ClearcoatInAFurnace) {
    Scene s = whiteFurnace();
    Material coat = dielectric(Spectrum(0.0f), 0.25f, 1.5f);
    coat.specular = 0.0f;
    coat.clearcoat = 1.0f;
    addIcosphere(s, Vec3(0), 1.0f, 5, addMaterial(s, coat), false, true);
    Rendered black = render(s, 16, 16, 256);
    expectNear(regionStats(black, 7, 7, 9, 9), Spectrum(0.04f), 4.0f, 0.02f, "smooth coat over black, facing");
    s.materials[0].kd = Spectrum(1.0f);
    Rendered white1 = render(s, 16, 16, 256);
    expectNear(regionStats(white1, 4, 4, 12, 12), Spectrum(1.0f), 4.0f, 2e-3f, "smooth coat over white Lambert");
}

} // namespace
} // namespace pt::test
