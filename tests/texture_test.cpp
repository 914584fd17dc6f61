// Texture lookups and the MTL map options: which way v runs, repeat against clamp, -s and -o.
#include "core/color.h"
#include "obj/mtl_loader.h"
#include "texture/texture_cache.h"
#include "texture/texture_io.h"
#include "tests/test_scenes.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <tuple>

namespace pt {
namespace {

const Spectrum kRed(1, 0, 0), kBlue(0, 0, 1), kGreen(0, 1, 0), kWhite(1);

Texture twoTexels(Spectrum first, Spectrum second, bool vertical) {
    // Row 0 is the top of the image.
    return Texture::fromFloats(vertical ? 1 : 2, vertical ? 2 : 1, 3, {first.x, first.y, first.z, second.x, second.y, second.z});
}

void expectColor(Spectrum got, Spectrum want, const char* what, float tolerance = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tolerance) << what;
    EXPECT_NEAR(got.y, want.y, tolerance) << what;
    EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

const Footprint kPoint; // a bilinear lookup in the finest level

TEST(Texture, VRunsUpFromTheBottomRow) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(twoTexels(kGreen, kWhite, true))); // green on top, white at the bottom
    m.wrapU = m.wrapV = TextureWrap::Clamp;
    expectColor(cache.color(m, Vec2(0.5f, 0.25f), kPoint), kWhite, "v 0.25 is the bottom texel");
    expectColor(cache.color(m, Vec2(0.5f, 0.75f), kPoint), kGreen, "v 0.75 is the top texel");
    expectColor(cache.color(m, Vec2(0.5f, 0.5f), kPoint), 0.5f * (kGreen + kWhite), "bilinear between them");
}

TEST(Texture, RepeatAndClamp) {
    TextureCache cache;
    TextureMap repeat = test::mapOf(cache.add(twoTexels(kRed, kBlue, false)));
    TextureMap clamp = repeat;
    clamp.wrapU = clamp.wrapV = TextureWrap::Clamp;
    expectColor(cache.color(repeat, Vec2(1.25f, 0.5f), kPoint), kRed, "repeat: u 1.25 is u 0.25");
    expectColor(cache.color(clamp, Vec2(1.25f, 0.5f), kPoint), kBlue, "clamp: u 1.25 is the right edge");
    expectColor(cache.color(clamp, Vec2(-3.0f, 0.5f), kPoint), kRed, "clamp: u -3 is the left edge");
    // At the border, repeat blends with the opposite edge and clamp does not.
    expectColor(cache.color(repeat, Vec2(0.0f, 0.5f), kPoint), 0.5f * (kRed + kBlue), "repeat at u 0");
    expectColor(cache.color(clamp, Vec2(0.0f, 0.5f), kPoint), kRed, "clamp at u 0");
}

// glTF's MIRRORED_REPEAT: [1, 2] is [0, 1] reversed, and so on, both ways; each axis wraps by
// its own mode.
TEST(Texture, MirrorAndWrapPerAxis) {
    TextureCache cache;
    TextureMap mirror = test::mapOf(cache.add(twoTexels(kRed, kBlue, false)));
    mirror.wrapU = TextureWrap::Mirror;
    expectColor(cache.color(mirror, Vec2(0.25f, 0.5f), kPoint), kRed, "mirror: u 0.25 as it is");
    expectColor(cache.color(mirror, Vec2(1.25f, 0.5f), kPoint), kBlue, "mirror: u 1.25 is u 0.75");
    expectColor(cache.color(mirror, Vec2(1.75f, 0.5f), kPoint), kRed, "mirror: u 1.75 is u 0.25");
    expectColor(cache.color(mirror, Vec2(-0.25f, 0.5f), kPoint), kRed, "mirror: u -0.25 is u 0.25");
    expectColor(cache.color(mirror, Vec2(2.25f, 0.5f), kPoint), kRed, "mirror: u 2.25 is u 0.25");
    // At the seam, mirroring meets the same texel: no blend with the opposite edge.
    expectColor(cache.color(mirror, Vec2(1.0f, 0.5f), kPoint), kBlue, "mirror at u 1");
    // Far from the unit square, the period 2 keeps the answer.
    expectColor(cache.color(mirror, Vec2(2e6f + 1.25f, 0.5f), kPoint), kBlue, "mirror: u 2e6 + 1.25 is u 0.75", 0.1f);
    // u mirrors, v (running across the image's two rows) clamps.
    TextureMap mixed = test::mapOf(cache.add(twoTexels(kGreen, kWhite, true)));
    mixed.wrapU = TextureWrap::Mirror;
    mixed.wrapV = TextureWrap::Clamp;
    expectColor(cache.color(mixed, Vec2(0.5f, 7.0f), kPoint), kGreen, "clamped v 7 is the top row");
    expectColor(cache.color(mixed, Vec2(0.5f, -7.0f), kPoint), kWhite, "clamped v -7 is the bottom row");
    mixed.wrapV = TextureWrap::Repeat;
    expectColor(cache.color(mixed, Vec2(0.5f, 1.25f), kPoint), kWhite, "repeated v 1.25 is v 0.25");
}

// A 4 x 4 texture of 16 distinct colours: texel (column i, row j from the top) holds (i, j, 1).
Texture sixteenTexels() {
    std::vector<float> texels;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) texels.insert(texels.end(), {float(i), float(j), 1.0f});
    return Texture::fromFloats(4, 4, 3, texels);
}

// KHR_texture_transform's own example: offset [0, 1], rotation pi/2 and scale [0.5, 0.5] read
// "only the lower left quadrant of the source image, rotated clockwise 90 degrees". Turned
// clockwise, the quadrant's top-left texel (0, 2) lands at the surface's top-right, its
// bottom-left (0, 3) at the top-left and its top-right (1, 2) at the bottom-right (pt's v up).
TEST(Texture, GltfTransformReadsTheSpecExample) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(sixteenTexels()));
    setGltfTransform(m, Vec2(0.0f, 1.0f), 1.57079632679f, Vec2(0.5f));
    expectColor(cache.color(m, Vec2(0.75f, 0.75f), kPoint), Spectrum(0, 2, 1), "top-right: the quadrant's top-left", 1e-3f);
    expectColor(cache.color(m, Vec2(0.25f, 0.75f), kPoint), Spectrum(0, 3, 1), "top-left: its bottom-left", 1e-3f);
    expectColor(cache.color(m, Vec2(0.75f, 0.25f), kPoint), Spectrum(1, 2, 1), "bottom-right: its top-right", 1e-3f);
    expectColor(cache.color(m, Vec2(0.25f, 0.25f), kPoint), Spectrum(1, 3, 1), "bottom-left: its bottom-right", 1e-3f);
    // Without rotation, offset and scale alone as before: [0.5, 0.5] from [0, 0.5] is the
    // lower-left quadrant upright, its top-left texel (0, 2) at the surface's top-left.
    setGltfTransform(m, Vec2(0.0f, 0.5f), 0.0f, Vec2(0.5f));
    expectColor(cache.color(m, Vec2(0.25f, 0.75f), kPoint), Spectrum(0, 2, 1), "upright: top-left", 1e-3f);
    expectColor(cache.color(m, Vec2(0.75f, 0.25f), kPoint), Spectrum(1, 3, 1), "upright: bottom-right", 1e-3f);
}

// A normal map's x and y follow the texture's s and t: unchanged by a positive scale, turned
// back by a rotation, and y mirrored by glTF's scale [1, -1].
TEST(Texture, NormalMapAxesFollowTheTransform) {
    TextureMap m;
    auto expectNear = [](Vec2 got, Vec2 want, const char* what) {
        EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
        EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
    };
    m.linear = scaleMatrix(Vec2(2.0f, 3.0f));
    expectNear(normalMapToUv(m, Vec2(0.6f, 0.8f)), Vec2(0.6f, 0.8f), "scale");
    setGltfTransform(m, Vec2(0.0f), 0.0f, Vec2(1.0f, -1.0f));
    expectNear(normalMapToUv(m, Vec2(0.6f, 0.8f)), Vec2(0.6f, -0.8f), "t mirrored");
    // Rotated by pi/2: s runs along the surface's -v and t (up the image) along +u, as the spec example's
    // clockwise turn of the image has it.
    setGltfTransform(m, Vec2(0.0f), 1.57079632679f, Vec2(1.0f));
    expectNear(normalMapToUv(m, Vec2(1.0f, 0.0f)), Vec2(0.0f, -1.0f), "s");
    expectNear(normalMapToUv(m, Vec2(0.0f, 1.0f)), Vec2(1.0f, 0.0f), "t");
}

TEST(Texture, ScaleAndOffset) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(twoTexels(kRed, kBlue, false)));
    m.offset = Vec2(0.5f, 0.0f);
    expectColor(cache.color(m, Vec2(0.25f, 0.5f), kPoint), kBlue, "-o 0.5 moves u 0.25 to 0.75");
    m.offset = Vec2(0.0f);
    m.linear = scaleMatrix(Vec2(2.0f, 1.0f));
    expectColor(cache.color(m, Vec2(0.375f, 0.5f), kPoint), kBlue, "-s 2 takes u 0.375 to 0.75");
    expectColor(cache.color(m, Vec2(0.625f, 0.5f), kPoint), kRed, "-s 2 takes u 0.625 to 1.25, repeated");
}

// A 64 x 64 checker of 8 x 8 squares, black and white: far away (a footprint of the whole
// texture) it must average to the mean of the light, 0.5, not to the mean of the encoded values.
TEST(Texture, MinificationAveragesLinearValues) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(test::checkerTexture()));
    Footprint whole{Vec2(1.0f, 0.0f), Vec2(0.0f, 1.0f)};
    expectColor(cache.color(m, Vec2(0.3f, 0.7f), whole), Spectrum(0.5f), "the coarsest level", 0.02f);
    // A footprint two squares wide, stretched 8:1, is still filtered (anisotropically) to the mean.
    Footprint grazing{Vec2(0.25f, 0.0f), Vec2(0.0f, 0.03125f)};
    expectColor(cache.color(m, Vec2(0.3f, 0.7f), grazing), Spectrum(0.5f), "anisotropic", 0.1f);
    // A tiny footprint keeps the texel.
    Footprint tiny{Vec2(1e-4f, 0.0f), Vec2(0.0f, 1e-4f)};
    expectColor(cache.color(m, Vec2(4.5f / 64, 1.0f - 4.5f / 64), tiny), Spectrum(0.0f), "finest level");
}

// -imfchan: r, g, b, alpha and luminance of an RGBA data texture.
TEST(Texture, ScalarChannels) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(Texture::fromFloats(1, 1, 4, {0.1f, 0.2f, 0.4f, 0.8f}, false)));
    const std::pair<TextureChannel, float> want[] = {{TextureChannel::R, 0.1f},
                                                     {TextureChannel::G, 0.2f},
                                                     {TextureChannel::B, 0.4f},
                                                     {TextureChannel::Alpha, 0.8f},
                                                     {TextureChannel::Luminance, 0.2126f * 0.1f + 0.7152f * 0.2f + 0.0722f * 0.4f}};
    for (auto [channel, value] : want) {
        m.channel = channel;
        EXPECT_NEAR(cache.scalar(m, Vec2(0.5f), kPoint), value, 1e-6f) << int(channel);
    }
}

// A height ramp rising by 1 across the texture in u: the lookup's derivative is 1 per unit u
// (and 2 with -s 2), and 0 in v; a rotation turns the gradient with the texture.
TEST(Texture, DerivativesOfARamp) {
    TextureCache cache;
    TextureMap m = test::mapOf(cache.add(test::rampTexture(32, 4)), TextureChannel::R);
    m.wrapU = m.wrapV = TextureWrap::Clamp;
    Vec2 d;
    float h = cache.scalar(m, Vec2(0.4f, 0.5f), kPoint, d);
    EXPECT_NEAR(h, 0.4f, 1e-5f);
    EXPECT_NEAR(d.x, 1.0f, 1e-3f);
    EXPECT_NEAR(d.y, 0.0f, 1e-3f);
    m.linear = scaleMatrix(Vec2(2.0f, 1.0f));
    cache.scalar(m, Vec2(0.2f, 0.5f), kPoint, d);
    EXPECT_NEAR(d.x, 2.0f, 2e-3f);
    // Turned by pi/2 (glTF's rotation, the image clockwise): s = 1 - v, so the height falls with
    // v and does not change with u.
    setGltfTransform(m, Vec2(0.0f), 1.57079632679f, Vec2(1.0f));
    h = cache.scalar(m, Vec2(0.5f, 0.6f), kPoint, d);
    EXPECT_NEAR(h, 0.4f, 1e-3f);
    EXPECT_NEAR(d.x, 0.0f, 1e-3f);
    EXPECT_NEAR(d.y, -1.0f, 1e-3f);
}

// The same 8-bit grey of 128 is sRGB-encoded as a colour map and linear as a data map; float and
// half files are linear either way. Each is held at its file's depth.
TEST(Texture, SrgbAgainstLinear) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(::testing::TempDir()) / "pt_texture_encoding";
    fs::create_directories(dir);
    std::string png = (dir / "grey.png").string(), exr = (dir / "grey.exr").string(), half = (dir / "grey_half.exr").string();
    ASSERT_EQ(std::system(("oiiotool --create 4x4 3 --fill:color=0.50196,0.50196,0.50196 4x4 -d uint8 -o " + png +
                           " >/dev/null 2>&1").c_str()), 0);
    ASSERT_EQ(std::system(("oiiotool --create 4x4 3 --fill:color=0.5,0.5,0.5 4x4 -d float -o " + exr +
                           " >/dev/null 2>&1").c_str()), 0);
    ASSERT_EQ(std::system(("oiiotool --create 4x4 3 --fill:color=0.5,0.5,0.5 4x4 -d half -o " + half +
                           " >/dev/null 2>&1").c_str()), 0);
    for (auto [file, colour, want, format] : std::vector<std::tuple<std::string, bool, float, TexelFormat>>{
             {png, true, srgbToLinear(128.0f / 255.0f), TexelFormat::Srgb8},
             {png, false, 128.0f / 255.0f, TexelFormat::Unorm8},
             {exr, true, 0.5f, TexelFormat::Float},
             {exr, false, 0.5f, TexelFormat::Float},
             {half, true, 0.5f, TexelFormat::Half}}) {
        Texture t;
        std::string error;
        bool tooLarge;
        ASSERT_TRUE(readTexture(file, colour, t, error, 1e9, tooLarge)) << error;
        EXPECT_NEAR(t.texel(0, 0, 0), want, 1e-4f) << file << (colour ? " as colour" : " as data");
        EXPECT_EQ(int(t.format), int(format)) << file << (colour ? " as colour" : " as data");
    }
}

// glTF colour and alpha are separate (unassociated): alpha drives coverage only, in MASK and BLEND.
// A PNG of sRGB 200 at alpha 255, 128 and 0 must read as the same colour in all three texels,
// as colour (RGB) and as data (RGBA, where the alpha channel is the fourth); OpenImageIO
// premultiplies by alpha unless asked not to, which darkened them to 0.57, 0.13 and 0.
TEST(Texture, AlphaDoesNotDarkenColour) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(::testing::TempDir()) / "pt_texture_alpha";
    fs::create_directories(dir);
    const std::string png = (dir / "alpha.png").string();
    {
        const unsigned char texels[3][4] = {{200, 200, 200, 255}, {200, 200, 200, 128}, {200, 200, 200, 0}};
        auto out = OIIO::ImageOutput::create(png);
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(3, 1, 4, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1); // write the bytes as given
        ASSERT_TRUE(out->open(png, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, texels));
        ASSERT_TRUE(out->close());
    }
    for (bool colour : {true, false}) {
        Texture t;
        std::string error;
        bool tooLarge;
        ASSERT_TRUE(readTexture(png, colour, t, error, 1e9, tooLarge)) << error;
        const float want = colour ? srgbToLinear(200.0f / 255.0f) : 200.0f / 255.0f;
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.texel(x, 0, c), want, 1e-4f) << (colour ? "colour" : "data") << " texel " << x;
        if (!colour)
            for (int x = 0; x < 3; ++x) EXPECT_NEAR(t.texel(x, 0, 3), (x == 0 ? 255 : x == 1 ? 128 : 0) / 255.0f, 1e-4f);
    }
}

// Each MTL line, in a material block, is an error whose message contains the given text.
void expectErrors(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& cases);

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
    EXPECT_EQ(m.linear, scaleMatrix(Vec2(2.0f, 3.0f)));
    EXPECT_EQ(m.offset, Vec2(0.5f, 0.25f));
    EXPECT_EQ(m.wrapU, TextureWrap::Clamp);
    EXPECT_EQ(m.wrapV, TextureWrap::Clamp);
    EXPECT_EQ((*p.scene.textures)[0].width, 128);
    ASSERT_EQ(p.warnings.messages().size(), 1u);
    EXPECT_NE(p.warnings.messages()[0].find("test.mtl:2: map_Kd: option -bm has no effect on this map"), std::string::npos);

    Parsed one = parse("newmtl A\nmap_Kd -s 4 my checker.png\n", dir.string());
    EXPECT_EQ(one.scene.materials.at(0).kdMap.linear, scaleMatrix(Vec2(4.0f, 1.0f))); // v keeps its default

    expectErrors(dir.string(), {
                   {"map_Kd -clamp maybe my checker.png", "test.mtl:2: map_Kd -clamp: expected on or off, found \"maybe\""},
                   {"map_Kd -zz my checker.png", "test.mtl:2: map_Kd: unknown texture option \"-zz\""},
                   {"map_Kd -s my checker.png", "test.mtl:2: map_Kd -s: expected a number"},
                   {"map_Kd -o 1 2", "test.mtl:2: map_Kd: expected a file name"},
                 });
}

void expectErrors(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& cases) {
    for (const auto& [line, message] : cases) {
        try {
            parse("newmtl A\n" + line + "\n", dir);
            ADD_FAILURE() << line << ": no error";
        } catch (const LoadError& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << line << ": " << e.what();
        }
    }
}

std::string messages(const Warnings& w) {
    std::string all;
    for (const std::string& m : w.messages()) all += m + "\n";
    return all;
}

// The data maps: which channel each reads, -bm, d as coverage with map_d, and the ways their
// input can be wrong.
TEST(Texture, DataMapKeywordsAndOptions) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(::testing::TempDir()) / "pt_texture_data_maps";
    fs::create_directories(dir);
    ASSERT_EQ(std::system(("oiiotool --create 4x4 4 --fill:color=0.2,0.4,0.6,0.5 4x4 -d uint8 -o " +
                           (dir / "rgba.png").string() + " >/dev/null 2>&1").c_str()), 0);
    ASSERT_EQ(std::system(("oiiotool --create 4x4 1 --fill:color=0.5 4x4 -d uint8 -o " + (dir / "grey.png").string() +
                           " >/dev/null 2>&1").c_str()), 0);
    Parsed p = parse("newmtl A\nd 0.5\nTr 0.25\nmap_d rgba.png\nmap_Pr -imfchan g rgba.png\nmap_Pm -imfchan r grey.png\n"
                     "bump -bm 0.02 grey.png\nmap_Ks grey.png\nmap_Kd rgba.png\n",
                     dir.string());
    ASSERT_EQ(p.scene.materials.size(), 1u);
    const Material& m = p.scene.materials[0];
    EXPECT_TRUE(m.alphaMap.used());
    EXPECT_EQ(m.alphaMap.channel, TextureChannel::Alpha) << "map_d reads the alpha channel when there is one";
    EXPECT_EQ(m.coverage, 0.5f) << "d scales coverage when map_d is given";
    EXPECT_EQ(m.transparency, 0.25f) << "and is no transparency then";
    EXPECT_EQ(m.roughnessMap.channel, TextureChannel::G);
    EXPECT_EQ(m.metallicMap.channel, TextureChannel::R);
    EXPECT_EQ(m.bumpMap.bumpScale, 0.02f);
    EXPECT_EQ(m.bumpMap.channel, TextureChannel::Luminance);
    EXPECT_EQ(m.ksMap.channel, TextureChannel::Rgb);
    // rgba.png as data and as colour, grey.png as data and as colour.
    EXPECT_EQ(p.scene.textures->size(), 4u);
    EXPECT_TRUE(p.warnings.messages().empty()) << messages(p.warnings);

    Parsed plain = parse("newmtl A\nd 0.5\n", dir.string());
    EXPECT_EQ(plain.scene.materials[0].transparency, 0.5f) << "without map_d, d is the lab's transparency";
    EXPECT_EQ(plain.scene.materials[0].coverage, 1.0f);
    Parsed grey = parse("newmtl A\nmap_d grey.png\n", dir.string());
    EXPECT_EQ(grey.scene.materials[0].alphaMap.channel, TextureChannel::Luminance);

    // A map that cannot be used warns, names the line and falls back to the plain value.
    for (const auto& [line, message] : std::vector<std::pair<std::string, std::string>>{
             {"map_d -imfchan m grey.png", "test.mtl:2: map_d: texture \"" + (dir / "grey.png").string() + "\" has no alpha channel"},
             {"norm grey.png", "test.mtl:2: norm: normal map \"" + (dir / "grey.png").string() + "\" has 1 channel(s); expected RGB"},
             {"map_Pr missing.png", "test.mtl:2: map_Pr: texture \"" + (dir / "missing.png").string() + "\" not found; using the plain value"}}) {
        Parsed q = parse("newmtl A\n" + line + "\n", dir.string());
        EXPECT_FALSE(q.scene.materials[0].isTextured() || q.scene.materials[0].hasCutout()) << line;
        ASSERT_EQ(q.warnings.messages().size(), 1u) << line;
        EXPECT_NE(q.warnings.messages()[0].find(message), std::string::npos) << q.warnings.messages()[0];
    }
    Parsed twice = parse("newmtl A\nmap_Pr missing.png\nnewmtl B\nmap_Pm missing.png\n", dir.string());
    EXPECT_EQ(twice.warnings.messages().size(), 1u) << "a missing file is reported once: " << messages(twice.warnings);
    Parsed both = parse("newmtl A\nnorm rgba.png\nbump grey.png\n", dir.string());
    EXPECT_FALSE(both.scene.materials[0].bumpMap.used());
    EXPECT_NE(messages(both.warnings).find("the bump map is ignored"), std::string::npos);

    expectErrors(dir.string(), {
                   {"map_Pr -imfchan z grey.png", "test.mtl:2: map_Pr -imfchan: expected r, g, b, m (alpha) or l (luminance), found \"z\" (depth"},
                   {"bump -imfchan grey.png", "test.mtl:2: bump -imfchan: expected r, g, b"},
                   {"bump -bm grey.png", "test.mtl:2: bump -bm: expected a number"},
                   {"bump -bm 1e30 grey.png", "test.mtl:2: bump -bm: 1e+30 is beyond 1e12"},
                 });
}

} // namespace
} // namespace pt
