// Texture lookups and the MTL map options: which way v runs, repeat against clamp, -s and -o.
#include "scene/mtl_loader.h"
#include "texture/texture.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace pt {
namespace {

const Spectrum kRed(1, 0, 0), kBlue(0, 0, 1), kGreen(0, 1, 0), kWhite(1);

Texture twoTexels(Spectrum first, Spectrum second, bool vertical) {
    Texture t;
    t.width = vertical ? 1 : 2;
    t.height = vertical ? 2 : 1;
    t.texels = {first, second}; // row 0 is the top of the image
    return t;
}

void expectColor(Spectrum got, Spectrum want, const char* what) {
    EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
    EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
    EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

TEST(Texture, VRunsUpFromTheBottomRow) {
    Texture t = twoTexels(kGreen, kWhite, true); // green on top, white at the bottom
    expectColor(lookupTexture(t, Vec2(0.5f, 0.25f)), kWhite, "v 0.25 is the bottom texel");
    expectColor(lookupTexture(t, Vec2(0.5f, 0.75f)), kGreen, "v 0.75 is the top texel");
    expectColor(lookupTexture(t, Vec2(0.5f, 0.5f)), 0.5f * (kGreen + kWhite), "bilinear between them");
}

TEST(Texture, RepeatAndClamp) {
    std::vector<Texture> textures = {twoTexels(kRed, kBlue, false)};
    TextureMap repeat;
    repeat.texture = 0;
    TextureMap clamp = repeat;
    clamp.clamp = true;
    expectColor(lookupTexture(textures, repeat, Vec2(1.25f, 0.5f)), kRed, "repeat: u 1.25 is u 0.25");
    expectColor(lookupTexture(textures, clamp, Vec2(1.25f, 0.5f)), kBlue, "clamp: u 1.25 is the right edge");
    expectColor(lookupTexture(textures, clamp, Vec2(-3.0f, 0.5f)), kRed, "clamp: u -3 is the left edge");
    // At the border, repeat blends with the opposite edge and clamp does not.
    expectColor(lookupTexture(textures, repeat, Vec2(0.0f, 0.5f)), 0.5f * (kRed + kBlue), "repeat at u 0");
    expectColor(lookupTexture(textures, clamp, Vec2(0.0f, 0.5f)), kRed, "clamp at u 0");
}

TEST(Texture, ScaleAndOffset) {
    std::vector<Texture> textures = {twoTexels(kRed, kBlue, false)};
    TextureMap m;
    m.texture = 0;
    m.offset = Vec2(0.5f, 0.0f);
    expectColor(lookupTexture(textures, m, Vec2(0.25f, 0.5f)), kBlue, "-o 0.5 moves u 0.25 to 0.75");
    m.offset = Vec2(0.0f);
    m.scale = Vec2(2.0f, 1.0f);
    expectColor(lookupTexture(textures, m, Vec2(0.375f, 0.5f)), kBlue, "-s 2 takes u 0.375 to 0.75");
    expectColor(lookupTexture(textures, m, Vec2(0.625f, 0.5f)), kRed, "-s 2 takes u 0.625 to 1.25, repeated");
}

struct Parsed {
    Scene scene;
    std::unordered_map<std::string, uint32_t> index;
    Warnings warnings;
};

Parsed parse(const std::string& text, const std::string& dir) {
    Parsed p;
    parseMtl(text, dir + "/test.mtl", p.scene, p.index, p.warnings);
    return p;
}

TEST(Texture, MapOptionsAndNamesWithSpaces) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(::testing::TempDir()) / "pt_texture_options";
    fs::create_directories(dir);
    fs::copy_file(PT_SOURCE_DIR "/scenes/checker.png", dir / "my checker.png", fs::copy_options::overwrite_existing);
    Parsed p = parse("newmtl A\nmap_Kd -s 2 3 -o 0.5 0.25 1 -clamp on -bm 2 my checker.png\n", dir.string());
    const TextureMap& m = p.scene.materials.at(0).kdMap;
    ASSERT_TRUE(m.used()) << (p.warnings.messages().empty() ? "" : p.warnings.messages()[0]);
    EXPECT_EQ(m.scale, Vec2(2.0f, 3.0f));
    EXPECT_EQ(m.offset, Vec2(0.5f, 0.25f));
    EXPECT_TRUE(m.clamp);
    EXPECT_EQ(p.scene.textures.at(0).width, 128);
    ASSERT_EQ(p.warnings.messages().size(), 1u);
    EXPECT_NE(p.warnings.messages()[0].find("test.mtl:2: map_Kd: option -bm has no effect"), std::string::npos);

    Parsed one = parse("newmtl A\nmap_Kd -s 4 my checker.png\n", dir.string());
    EXPECT_EQ(one.scene.materials.at(0).kdMap.scale, Vec2(4.0f, 1.0f)); // v keeps its default

    for (const auto& [line, message] : std::vector<std::pair<std::string, std::string>>{
             {"map_Kd -clamp maybe my checker.png", "test.mtl:2: map_Kd -clamp: expected on or off, found \"maybe\""},
             {"map_Kd -zz my checker.png", "test.mtl:2: map_Kd: unknown texture option \"-zz\""},
             {"map_Kd -s my checker.png", "test.mtl:2: map_Kd -s: expected a number"},
             {"map_Kd -o 1 2", "test.mtl:2: map_Kd: expected a file name"}}) {
        try {
            parse("newmtl A\n" + line + "\n", dir.string());
            ADD_FAILURE() << line << ": no error";
        } catch (const LoadError& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << line << ": " << e.what();
        }
    }
}

} // namespace
} // namespace pt
