#include "obj/mtl_loader.h"
#include "environment/environment_map.h"
#include "material/lab_bsdf.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

struct Parsed {
    Scene scene;
    std::unordered_map<std::string, uint32_t> index;
    Warnings warnings;

    const Material& material(const std::string& name) const { return scene.materials.at(index.at(name)); }
};

Parsed parse(const std::string& text, const std::string& path = "/nowhere/test.mtl") {
    Parsed p;
    parseMtl(text, path, p.scene, p.index, p.warnings);
    return p;
}

std::string errorOf(const std::string& text, const std::string& path = "/nowhere/test.mtl") {
    try {
        parse(text, path);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Mtl, Defaults) {
    Parsed p = parse("newmtl Plain\n");
    const Material& m = p.material("Plain");
    EXPECT_EQ(m.kd, Spectrum(0.7f));
    EXPECT_FALSE(m.kdMap.used());
    EXPECT_EQ(m.ks, Spectrum(1.0f));
    EXPECT_EQ(m.r0, Spectrum(0.0f));
    EXPECT_EQ(m.blend, 0.0f);
    EXPECT_EQ(m.transparency, 0.0f);
    EXPECT_EQ(m.eta, 1.0f);
    EXPECT_FLOAT_EQ(m.roughnessAlpha, 0.001f);
    EXPECT_EQ(m.emission, Spectrum(0.0f));
}

// The lab's long names and the standard short ones set the same fields, in any letter case.
TEST(Mtl, BothDialectsAndCaseInsensitivity) {
    Parsed lab = parse("newmtl L\n"
                       "diffuseReflectance 0.1 0.2 0.3\n"
                       "specularReflectance 0.4 0.5 0.6\n"
                       "reflat0deg 0.25\n"
                       "reflat90deg 0.75\n"
                       "transparency 0.5\n"
                       "indexofrefraction 1.33\n"
                       "specularroughness 0.2\n"
                       "emittance 1 2 3\n");
    Parsed std = parse("NEWMTL S\n"
                       "kd 0.1 0.2 0.3\n"
                       "KS 0.4 0.5 0.6\n"
                       "ReflAt0Deg 0.25\n"
                       "REFLAT90DEG 0.75\n"
                       "tr 0.5\n"
                       "ni 1.33\n"
                       "SpecularRoughness 0.2\n"
                       "ke 1 2 3\n");
    for (const Material* m : {&lab.material("L"), &std.material("S")}) {
        EXPECT_EQ(m->kd, Spectrum(0.1f, 0.2f, 0.3f));
        EXPECT_EQ(m->ks, Spectrum(0.4f, 0.5f, 0.6f));
        EXPECT_EQ(m->r0, Spectrum(0.25f));
        EXPECT_EQ(m->blend, 0.75f);
        EXPECT_EQ(m->transparency, 0.5f);
        EXPECT_FLOAT_EQ(m->eta, 1.33f);
        EXPECT_FLOAT_EQ(m->roughnessAlpha, 0.2f);
        EXPECT_EQ(m->emission, Spectrum(1.0f, 2.0f, 3.0f));
    }
}

TEST(Mtl, DissolveIsOneMinusTransparency) {
    Parsed p = parse("newmtl A\nd 0.25\n");
    EXPECT_FLOAT_EQ(p.material("A").transparency, 0.75f);
}

// Pm builds the tree, when the material is evaluated, as R0 = mix(((eta-1)/(eta+1))^2, Ks, m),
// w = 1, Spec colour 1, Diffuse colour Kd (1 - m), whatever order the lines come in.
TEST(Mtl, MetallicRewritesTheTree) {
    Parsed p = parse("newmtl Half\nPm 0.5\nKd 0.8 0.6 0.4\nKs 0.9 0.5 0.1\nNi 1.5\n"
                     "newmtl Metal\nKd 0 0 0\nKs 0.9 0.9 0.9\nNi 1.55\nPm 1.0\n"
                     "newmtl Dielectric\nKd 0.8 0.8 0.2\nKs 0.04 0.04 0.04\nNi 1.55\nPm 0.0\n"
                     "newmtl Plain\nKd 0.5\n");
    auto lab = [&](const char* name) { return labParameters(p.material(name), p.material(name).kd); };
    LabParameters half = lab("Half");
    float f0 = 0.04f; // ((1.5 - 1) / 2.5)^2
    EXPECT_NEAR(half.r0.x, 0.5f * f0 + 0.5f * 0.9f, 1e-6f);
    EXPECT_NEAR(half.r0.y, 0.5f * f0 + 0.5f * 0.5f, 1e-6f);
    EXPECT_NEAR(half.r0.z, 0.5f * f0 + 0.5f * 0.1f, 1e-6f);
    EXPECT_EQ(half.blend, 1.0f);
    EXPECT_EQ(half.ks, Spectrum(1.0f));
    EXPECT_EQ(half.kd, Spectrum(0.4f, 0.3f, 0.2f));
    EXPECT_NEAR(lab("Metal").r0.x, 0.9f, 1e-6f);
    EXPECT_EQ(lab("Metal").kd, Spectrum(0.0f));
    EXPECT_NEAR(lab("Dielectric").r0.x, std::pow(0.55f / 2.55f, 2.0f), 1e-6f);
    EXPECT_EQ(lab("Dielectric").kd, Spectrum(0.8f, 0.8f, 0.2f));
    EXPECT_LT(p.material("Plain").metallic, 0.0f); // without Pm the tree is as written
}

// specularroughness is GGX alpha as is; Pr is perceptual roughness, alpha = Pr^2.
TEST(Mtl, Roughness) {
    Parsed p = parse("newmtl A\nspecularroughness 0.3\nnewmtl B\nPr 0.5\nnewmtl C\nKd 1\n");
    EXPECT_FLOAT_EQ(p.material("A").roughnessAlpha, 0.3f);
    EXPECT_FLOAT_EQ(p.material("B").roughnessAlpha, 0.25f);
    EXPECT_FLOAT_EQ(p.material("C").roughnessAlpha, 0.001f);
}

TEST(Mtl, LightsAndCameras) {
    Parsed p = parse("newlight Key\n\tlightposition -0.7 0.7 -0.7\n\tlightcolor 1.0 0.8 0.8\n"
                     "\tlightradius 0.2\n\tlightintensity 2.0\n"
                     "newlight Dot\n\tlightposition 1 2 3\n"
                     "newcamera Cam\n\tcameraposition 0 0 3\n\tcameratarget 0 0 0\n\tcameraup 1 1 0\n"
                     "\tcamerafov 30\n");
    ASSERT_EQ(p.scene.lights.size(), 2u);
    const LocalLight& key = p.scene.lights[0];
    EXPECT_EQ(key.name, "Key");
    EXPECT_EQ(key.center, Vec3(-0.7f, 0.7f, -0.7f));
    EXPECT_FLOAT_EQ(key.radius, 0.2f);
    EXPECT_EQ(key.intensity, Spectrum(2.0f, 1.6f, 1.6f)); // intensity times colour
    EXPECT_NEAR(key.radiance().x, 2.0f / (kPi * 0.04f), 1e-4f);
    const LocalLight& dot = p.scene.lights[1]; // defaults: point light of intensity 1
    EXPECT_TRUE(dot.isPoint());
    EXPECT_EQ(dot.intensity, Spectrum(1.0f));
    ASSERT_EQ(p.scene.cameras.size(), 1u);
    const Camera& c = p.scene.cameras[0];
    EXPECT_EQ(c.name, "Cam");
    EXPECT_EQ(c.position, Vec3(0, 0, 3));
    EXPECT_EQ(c.up, Vec3(1, 1, 0));
    EXPECT_EQ(c.fovY, 30.0f);
}

TEST(Mtl, TextureLoadsAndMissingTextureWarns) {
    Parsed ok = parse("newmtl T\nmap_Kd " PT_SOURCE_DIR "/scenes/checker.png\n"
                      "newmtl U\ndiffuseReflectanceMap " PT_SOURCE_DIR "/scenes/checker.png\n");
    ASSERT_EQ(ok.scene.textures->size(), 1u); // loaded once, shared
    EXPECT_EQ(ok.material("T").kdMap.texture, 0);
    EXPECT_EQ(ok.material("U").kdMap.texture, 0);
    const Texture& t = (*ok.scene.textures)[0];
    EXPECT_EQ(t.width, 128);
    // The checker's bright squares are sRGB 0.9 (linear 0.787).
    EXPECT_NEAR(t.texel(0, 0, 0), 0.787f, 0.01f);

    Parsed missing = parse("newmtl T\nmap_Kd nothere.png\n");
    EXPECT_FALSE(missing.material("T").kdMap.used());
    ASSERT_EQ(missing.warnings.messages().size(), 1u);
    EXPECT_NE(missing.warnings.messages()[0].find("test.mtl:2: map_Kd: texture \"/nowhere/nothere.png\" not found"), std::string::npos)
        << missing.warnings.messages()[0];
}

TEST(Mtl, UnknownKeywordsWarnOnce) {
    Parsed p = parse("newmtl A\nillum 2\nNs 10\nillum 3\nKd 0.5\n");
    EXPECT_EQ(p.material("A").kd, Spectrum(0.5f));
    ASSERT_EQ(p.warnings.messages().size(), 2u); // illum once, Ns once
    EXPECT_NE(p.warnings.messages()[0].find("test.mtl:2: unknown keyword \"illum\""), std::string::npos);
}

TEST(Mtl, ErrorsNameFileLineAndExpectation) {
    struct Case {
        const char* text;
        const char* expected;
    };
    for (const Case& c : std::vector<Case>{
             {"Kd 1 1 1\n", "test.mtl:1: Kd outside a newmtl block"},
             {"newmtl A\nKd 1 1\n", "test.mtl:2: Kd: expected a number, found end of line"},
             {"newmtl A\nKd -1 0 0\n", "test.mtl:2: Kd: expected values >= 0"},
             {"newmtl A\nTr 1.5\n", "test.mtl:2: Tr: expected a value in [0, 1]"},
             {"newmtl A\nNi 0\n", "test.mtl:2: Ni: expected an index of refraction > 0"},
             {"newmtl A\nKd 1 1 1 1\n", "test.mtl:2: Kd: unexpected \"1\" at the end of the line"},
             {"newmtl\n", "test.mtl:1: newmtl: expected a name"},
             {"newmtl A\nlightradius 1\n", "test.mtl:2: lightradius outside a newlight block"},
             {"newlight L\nlightradius -1\n", "test.mtl:2: lightradius: expected a value >= 0"},
             {"newcamera C\ncameraposition 0 0 0\ncameratarget 0 0 0\n",
              "test.mtl:3: camera \"C\": cameraposition equals cameratarget"},
             {"newcamera C\ncameraposition 0 0 1\ncameraup 0 0 1\n", "test.mtl:3: camera \"C\": cameraup is zero or parallel"},
             {"newcamera C\ncameraposition 0 0 1\ncamerafov 180\n", "test.mtl:3: camera \"C\": camerafov must be in (0, 180)"},
         }) {
        std::string e = errorOf(c.text);
        EXPECT_NE(e.find(c.expected), std::string::npos) << "got: " << e << "\nfor: " << c.text;
    }
}

// The environment block: a scene can carry its lighting. The map files are the repository's own.
const std::string kScenesMtl = PT_SOURCE_DIR "/scenes/test.mtl";

TEST(EnvironmentMtl, BlockReadsTheMapBesideTheMtl) {
    const Scene s = parse("newenvironment Sky\n\tEnvMap env_marker.exr\n\tenvrotate 90\n\tENVSCALE 2\nnewmtl A\n", kScenesMtl).scene;
    ASSERT_TRUE(s.environment.map);
    EXPECT_EQ(s.environment.map->width, 64);
    EXPECT_NEAR(s.environment.map->rotation(), 0.5f * kPi, 1e-6f);
    EXPECT_EQ(s.environment.map->scale, 2.0f);
    // Turned by 90 degrees and doubled: what was along +x (green, 8) comes from -z.
    const float lift = std::cos(kPi * 15.5f / 32.0f);
    Spectrum L = s.environment.map->radiance(glm::normalize(Vec3(0, lift, -1)));
    EXPECT_NEAR(L.y, 16.0f, 0.2f);
    EXPECT_EQ(s.sources.back().path, PT_SOURCE_DIR "/scenes/env_marker.exr");
    EXPECT_EQ(s.sources.back().hash, s.environment.map->sourceHash);
}

TEST(EnvironmentMtl, ErrorsNameTheLine) {
    EXPECT_NE(errorOf("envmap env_marker.exr\n", kScenesMtl).find("test.mtl:1: envmap outside a newenvironment block"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\nenvmap env_marker.exr\nnewenvironment B\n", kScenesMtl)
                  .find("test.mtl:3: newenvironment: the scene already has one (line 1)"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\nenvrotate 10\n", kScenesMtl).find("test.mtl:1: newenvironment: the block has neither an envmap"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\n\nenvmap no_such.exr\n", kScenesMtl).find("test.mtl:3: environment map"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\nenvmap checker.png\n", kScenesMtl).find("test.mtl:2: environment map"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\nenvmap env_marker.exr\nenvscale -1\n", kScenesMtl).find("test.mtl:3: envscale"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment A\nenvmap env_marker.exr\nenvrotate x\n", kScenesMtl).find("test.mtl:3: envrotate"),
              std::string::npos);
    EXPECT_NE(errorOf("newenvironment\n", kScenesMtl).find("test.mtl:1: newenvironment: expected a name"), std::string::npos);
}

TEST(EnvironmentMtl, SkyBlockSetsTheSunAndHaze) {
    const Scene s =
        parse("newenvironment Day\n\tEnvSky\n\tSUNELEVATION 30\n\tsunazimuth 90\n\tturbidity 4\n\tskyscale 2\nnewmtl A\n",
              kScenesMtl).scene;
    ASSERT_TRUE(s.environment.preetham);
    EXPECT_FALSE(s.environment.map); // the sky is baked per render, by the light set
    ASSERT_TRUE(s.environment.sun);
    const SkyParameters& p = s.environment.preetham->parameters();
    // Elevation 30, azimuth 90: towards +x, raised by 30 degrees.
    EXPECT_NEAR(p.sunDirection.x, std::cos(kPi / 6.0f), 1e-6f);
    EXPECT_NEAR(p.sunDirection.y, 0.5f, 1e-6f);
    EXPECT_NEAR(p.sunDirection.z, 0.0f, 1e-6f);
    EXPECT_EQ(p.turbidity, 4.0f);
    EXPECT_EQ(p.scale, 2.0f);
    EXPECT_EQ(s.environment.sun->direction, p.sunDirection);

    const Scene d = parse("newenvironment Day\nenvsky\nsundir 0 2 -2\n", kScenesMtl).scene;
    ASSERT_TRUE(d.environment.preetham);
    EXPECT_NEAR(d.environment.preetham->parameters().sunDirection.y, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(d.environment.preetham->parameters().sunDirection.z, -std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(d.environment.preetham->parameters().turbidity, 3.0f); // the default
}

TEST(EnvironmentMtl, SkyErrorsNameTheLine) {
    struct Case {
        const char* text;
        const char* expected;
    } cases[] = {
        {"newenvironment A\nenvsky\nenvmap env_marker.exr\n", "test.mtl:3: envmap: the block is already the sky (envsky, line 2)"},
        {"newenvironment A\nenvsky\nenvrotate 10\n", "test.mtl:3: envrotate applies to an envmap"},
        {"newenvironment A\nenvsky\nsundir 0 1 0\nsunelevation 20\n", "test.mtl:4: sundir and sunelevation/sunazimuth"},
        {"newenvironment A\nenvmap env_marker.exr\nturbidity 3\n", "test.mtl:3: turbidity: applies to the sky"},
        {"newenvironment A\nsunelevation 10\n", "test.mtl:2: sunelevation: applies to the sky; the block needs an envsky line"},
        {"newenvironment A\nenvsky\nturbidity 1.5\n", "test.mtl:3: turbidity: expected a value in [1.7, 10]"},
        {"newenvironment A\nenvsky\nturbidity nan\n", "test.mtl:3: turbidity"},
        {"newenvironment A\nenvsky\nsunelevation 91\n", "test.mtl:3: sunelevation: expected degrees in [-90, 90]"},
        {"newenvironment A\nenvsky\nsundir 0 0 0\n", "test.mtl:3: sundir: expected a direction"},
        {"newenvironment A\nenvsky\nsundir 0 1\n", "test.mtl:3: sundir"},
        {"newenvironment A\nenvsky\nskyscale -2\n", "test.mtl:3: skyscale: expected a value >= 0"},
        {"newenvironment A\nenvsky 3\n", "test.mtl:2: envsky"},
        {"envsky\n", "test.mtl:1: envsky outside a newenvironment block"},
        {"newenvironment A\n", "test.mtl:1: newenvironment: the block has neither an envmap line"},
    };
    for (const Case& c : cases) {
        std::string e = errorOf(c.text, kScenesMtl);
        EXPECT_NE(e.find(c.expected), std::string::npos) << "got: " << e << "\nfor: " << c.text;
    }
}

} // namespace
} // namespace pt
