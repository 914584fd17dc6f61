#include "image/image_input.h"
#include "image/image_io.h"

#include <OpenImageIO/deepdata.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace pt {
namespace {

namespace fs = std::filesystem;

TEST(ImageIo, ExrRoundTripsLayersAndMetadata) {
    std::string path = (fs::path(::testing::TempDir()) / "pt_roundtrip.exr").string();
    Image img;
    img.width = 3;
    img.height = 2;
    for (int i = 0; i < 18; ++i) img.rgb.push_back(0.1f * i);
    img.layers.push_back({"variance", {"R", "G", "B"}, std::vector<float>(18, 0.25f)});
    img.metadata.push_back(ImageAttribute::integerValue("pt:spp", 64));
    ASSERT_EQ(writeImage(path, img), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.rgb, img.rgb);
    ASSERT_EQ(back.layers.size(), 1u);
    EXPECT_EQ(back.layers[0].name, "variance");
    EXPECT_EQ(back.layers[0].pixels, img.layers[0].pixels);
    bool found = false;
    for (auto& a : back.metadata) found |= a.name == "pt:spp" && a.type == ImageAttribute::Type::Int && a.integer == 64;
    EXPECT_TRUE(found);
}

// Channels are read by name: R, G, B make the picture; a channel named alone beside them (A)
// comes back as it was, in the layer ""; a file without R, G, B has no picture (never its first
// channels taken for one), and says what it lacks; a grey file's Y is its picture.
TEST(ImageIo, ChannelsAreReadByName) {
    const std::string dir = fs::path(::testing::TempDir()).string();
    Image img;
    img.width = 2;
    img.height = 1;
    img.rgb = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
    img.layers.push_back({"", {"A"}, {1.0f, 0.5f}});
    img.layers.push_back({"albedo", {"R", "G", "B"}, std::vector<float>(6, 0.7f)});
    ASSERT_EQ(writeImage(dir + "/pt_rgba.exr", img), "");
    Image back;
    ASSERT_EQ(readImage(dir + "/pt_rgba.exr", back), "");
    EXPECT_EQ(back.beauty, Image::Beauty::Rgb);
    EXPECT_EQ(back.rgb, img.rgb);
    ASSERT_EQ(back.layers.size(), 2u);
    EXPECT_EQ(back.layers[0].name, "");
    EXPECT_EQ(back.layers[0].pixels, img.layers[0].pixels);
    EXPECT_EQ(missingRgb(back), "");

    // writeImage always writes R, G, B: files without them come from OpenImageIO's own writer.
    {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(dir + "/pt_norgb.exr");
        OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"albedo.R", "albedo.G", "albedo.B", "Y"};
        const float px[8] = {0.7f, 0.7f, 0.7f, 0.25f, 0.7f, 0.7f, 0.7f, 0.75f};
        ASSERT_TRUE(out && out->open(dir + "/pt_norgb.exr", spec) && out->write_image(OIIO::TypeDesc::FLOAT, px) && out->close());
        spec.channelnames = {"R", "G", "albedo.R"};
        spec.nchannels = 3;
        out = OIIO::ImageOutput::create(dir + "/pt_rg.exr");
        ASSERT_TRUE(out && out->open(dir + "/pt_rg.exr", spec) && out->write_image(OIIO::TypeDesc::FLOAT, px) && out->close());
    }
    Image grey;
    ASSERT_EQ(readImage(dir + "/pt_norgb.exr", grey), "");
    EXPECT_EQ(grey.beauty, Image::Beauty::Grey) << "Y is a grey picture";
    EXPECT_EQ(grey.rgb, (std::vector<float>{0.25f, 0.25f, 0.25f, 0.75f, 0.75f, 0.75f}));
    Image rg;
    ASSERT_EQ(readImage(dir + "/pt_rg.exr", rg), "");
    EXPECT_EQ(rg.beauty, Image::Beauty::Missing);
    EXPECT_EQ(missingRgb(rg), "R and G but no B (its channels: R, G, albedo.R)");
    EXPECT_EQ(rg.rgb, std::vector<float>(6, 0.0f)) << "no channel stands in for B";
}

// A file whose header declares more pixels than its chunks hold (its data window widened by 32
// pixels, the data left as it was) is damaged, not an image with zeros where the rest would be:
// OpenEXR read uncompressed, RLE and ZIP chunks so without a word.
TEST(ImageIo, AnExrHoldingFewerPixelsThanItsHeaderDeclaresIsRefused) {
    const std::string dir = fs::path(::testing::TempDir()).string();
    for (const char* compression : {"none", "rle", "zips", "zip"}) {
        const std::string path = dir + "/pt_wide_" + compression + ".exr";
        {
            std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
            OIIO::ImageSpec spec(32, 20, 3, OIIO::TypeDesc::FLOAT);
            spec.attribute("compression", compression);
            std::vector<float> px(32 * 20 * 3);
            for (size_t i = 0; i < px.size(); ++i) px[i] = 0.001f * float(i % 997) + 0.25f;
            ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close());
        }
        Image intact;
        ASSERT_EQ(readImage(path, intact), "") << compression;
        std::string bytes = [&] {
            std::ifstream in(path, std::ios::binary);
            return std::string(std::istreambuf_iterator<char>(in), {});
        }();
        const std::string key = std::string("dataWindow") + '\0' + "box2i" + '\0';
        const size_t at = bytes.find(key);
        ASSERT_NE(at, std::string::npos);
        int32_t x1;
        std::memcpy(&x1, &bytes[at + key.size() + 4 + 8], 4);
        x1 += 32;
        std::memcpy(&bytes[at + key.size() + 4 + 8], &x1, 4);
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
        Image wide;
        const std::string error = readImage(path, wide);
        EXPECT_NE(error, "") << compression; // OpenEXR's decoders catch some short RLE and ZIPS data themselves
        if (std::string(compression) == "none" || std::string(compression) == "zip")
            EXPECT_NE(error.find("bytes of pixels where its header declares"), std::string::npos) << compression << ": " << error;
        EXPECT_EQ(wide.width, 0) << compression << ": nothing of the damaged file is kept";
    }
}

TEST(ImageIo, ADeepExrIsRefusedByName) {
    const std::string path = (fs::path(::testing::TempDir()) / "pt_deep.exr").string();
    {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
        OIIO::ImageSpec spec(2, 2, 4, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"R", "G", "B", "Z"};
        spec.deep = true;
        OIIO::DeepData deep(spec);
        for (int p = 0; p < 4; ++p) deep.set_samples(p, 1);
        ASSERT_TRUE(out && out->open(path, spec) && out->write_deep_image(deep) && out->close()) << OIIO::geterror();
    }
    Image image;
    EXPECT_NE(readImage(path, image).find("it is a deep OpenEXR image"), std::string::npos);
}

// Attributes keep their types through a read and a write (as pt denoise does): a matrix and a
// v2f come back as they were, never as strings (a string written under screenWindowCenter, a v2f
// to OpenEXR, made it throw in every pt denoise).
TEST(ImageIo, AttributesOfAnyTypeRoundTrip) {
    const std::string dir = fs::path(::testing::TempDir()).string();
    Image img;
    img.width = img.height = 1;
    img.rgb = {0.5f, 0.5f, 0.5f};
    ImageAttribute m{"worldToCamera", ImageAttribute::Type::Other, "matrix"};
    for (int i = 0; i < 16; ++i) {
        const float v = float(i) + 0.5f;
        const auto* b = reinterpret_cast<const unsigned char*>(&v);
        m.bytes.insert(m.bytes.end(), b, b + 4);
    }
    img.metadata.push_back(m);
    ASSERT_EQ(writeImage(dir + "/pt_attrs.exr", img), "");
    Image once, twice;
    ASSERT_EQ(readImage(dir + "/pt_attrs.exr", once), "");
    ASSERT_EQ(writeImage(dir + "/pt_attrs2.exr", once), "");
    ASSERT_EQ(readImage(dir + "/pt_attrs2.exr", twice), "");
    for (const char* name : {"worldToCamera", "screenWindowCenter"}) {
        auto it = std::find_if(twice.metadata.begin(), twice.metadata.end(), [&](const ImageAttribute& a) { return a.name == name; });
        ASSERT_NE(it, twice.metadata.end()) << name;
        EXPECT_EQ(it->type, ImageAttribute::Type::Other) << name << " came back as " << it->asText();
        if (it->name == m.name) EXPECT_EQ(it->bytes, m.bytes);
    }
}

TEST(ImageIo, PngIsSrgbEncoded) {
    std::string path = (fs::path(::testing::TempDir()) / "pt_srgb.png").string();
    Image img;
    img.width = img.height = 1;
    img.rgb = {0.0f, 0.214f, 1.0f}; // linear 0.214 is sRGB 0.5
    ASSERT_EQ(writeImage(path, img), "");
    Image back;
    ASSERT_EQ(readImage(path, back), "");
    EXPECT_NEAR(back.rgb[1], 0.214f, 0.005f);
    EXPECT_EQ(back.rgb[0], 0.0f);
    EXPECT_NEAR(back.rgb[2], 1.0f, 1e-6f);
}

TEST(ImageIo, OutputPathsAreCheckedBeforeRendering) {
    EXPECT_NE(checkOutputPath("out.tiff").find("unknown extension"), std::string::npos);
    EXPECT_NE(checkOutputPath("/no/such/folder/out.exr").find("does not exist"), std::string::npos);
    EXPECT_EQ(checkOutputPath((fs::path(::testing::TempDir()) / "ok.png").string()), "");
}

// A failed write leaves the previous file untouched and no temporary behind.
TEST(ImageIo, FailedWriteKeepsTheOldFile) {
    fs::path dir = fs::path(::testing::TempDir()) / "pt_atomic";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string path = (dir / "keep.exr").string();
    std::ofstream(path) << "precious";
    Image bad; // 0 x 0: the writer refuses it
    EXPECT_NE(writeImage(path, bad), "");
    std::ifstream in(path);
    std::string content;
    in >> content;
    EXPECT_EQ(content, "precious");
    size_t files = 0;
    for (auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
    EXPECT_EQ(files, 1u);
}

} // namespace
} // namespace pt

// OpenImageIO's IOMemReader took any seek: an EXR whose chunk table held a negative offset read
// before its buffer (found by the part fuzzer). Ours refuses offsets outside the bytes.
TEST(ImageIo, MemoryReaderStaysInsideItsBytes) {
    std::vector<unsigned char> bytes = {1, 2, 3, 4};
    pt::MemoryImageReader reader(bytes);
    unsigned char out[8] = {};
    EXPECT_FALSE(reader.seek(-1));
    EXPECT_FALSE(reader.seek(5));
    EXPECT_EQ(reader.pread(out, 1, -1), 0u);
    EXPECT_EQ(reader.pread(out, 8, 4), 0u);
    EXPECT_EQ(reader.pread(out, 8, 2), 2u);
    EXPECT_EQ(out[0], 3);
    EXPECT_TRUE(reader.seek(3));
    EXPECT_EQ(reader.read(out, 8), 1u);
    EXPECT_EQ(out[0], 4);
    EXPECT_EQ(reader.read(out, 8), 0u);
}
