// libFuzzer target for the part reader of pt merge and --resume (render/film_part.h): any input
// must give a film and the part's fields, or an error, never a crash, a sanitizer report or an
// allocation beyond what the part's own checks allow. Inputs that start with OpenEXR's magic
// number are read as files, through OpenImageIO; the others build a part image field by field
// from their bytes (size, window, each metadata field as absent, int, float or text, each layer
// and its pixels), which reaches the checks far more often than mutated EXR bytes do.
#include "render/film_image.h"
#include "render/film_part.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

// The input read front to back; zeros once it runs out.
struct Bytes {
    const uint8_t* p;
    size_t n;
    uint8_t u8() { return n ? (--n, *p++) : 0; }
    uint32_t u32() { return uint32_t(u8()) | uint32_t(u8()) << 8 | uint32_t(u8()) << 16 | uint32_t(u8()) << 24; }
    float f32() {
        uint32_t bits = u32();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    std::string text() {
        std::string s(u8() % 24, ' ');
        for (char& c : s) c = char(u8());
        return s;
    }
};

pt::Image buildPart(Bytes& in) {
    pt::Image image;
    image.width = 1 + in.u8() % 8;
    image.height = 1 + in.u8() % 8;
    if (in.u8() & 1) { // a crop: a data window inside a display window
        image.x = int(in.u8() % 24) - 4, image.y = int(in.u8() % 24) - 4;
        image.fullWidth = in.u8() % 24, image.fullHeight = in.u8() % 24;
    }
    static const char* const kFields[] = {"pt:part",       "pt:sppRequested", "pt:samplesFirst", "pt:samplesLast",
                                          "pt:fullWidth",  "pt:fullHeight",   "pt:exposure",     "pt:renderSeconds",
                                          "pt:camera"};
    for (const char* field : kFields) {
        switch (in.u8() % 5) {
        case 0: break;
        case 1: image.metadata.push_back(pt::ImageAttribute::integerValue(field, int8_t(in.u8()))); break;
        case 2: image.metadata.push_back(pt::ImageAttribute::integerValue(field, int32_t(in.u32()))); break;
        case 3: image.metadata.push_back(pt::ImageAttribute::floatValue(field, in.f32())); break;
        default: image.metadata.push_back(pt::ImageAttribute::string(field, in.text())); break;
        }
    }
    static const std::pair<const char*, std::vector<std::string>> kLayers[] = {
        {"ptCount", {"N"}},        {"ptSum", {"R", "G", "B"}},     {"ptSumLo", {"R", "G", "B"}},
        {"ptSumSq", {"R", "G", "B"}}, {"ptSumSqLo", {"R", "G", "B"}}, {"ptAlbedo", {"R", "G", "B"}},
        {"ptAlbedoLo", {"R", "G", "B"}}, {"ptNormal", {"X", "Y", "Z"}}, {"ptNormalLo", {"X", "Y", "Z"}},
        {"ptDepth", {"Z"}},        {"ptDepthLo", {"Z"}},           {"ptHits", {"N"}}};
    for (const auto& [name, channels] : kLayers) {
        uint8_t how = in.u8();
        if (how % 8 == 0) continue; // absent
        pt::ImageLayer layer{name, channels, {}};
        // Mostly the right size; sometimes one value short, which the reader must not trust.
        size_t n = size_t(image.width) * image.height * channels.size() - (how % 8 == 1 ? 1 : 0);
        for (size_t i = 0; i < n; ++i) layer.pixels.push_back(how & 8 ? float(in.u8() % 8) : in.f32());
        image.layers.push_back(std::move(layer));
    }
    return image;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pt::Image image;
    if (size >= 4 && std::memcmp(data, "\x76\x2f\x31\x01", 4) == 0) {
        // Pixels within 256 MB, where pt allows half the machine's memory: the fuzzer's own limit is 2 GB.
        if (!pt::readImageFromMemory(std::vector<unsigned char>(data, data + size), "fuzz.exr", image, 256e6).empty())
            return 0;
    } else {
        Bytes in{data, size};
        image = buildPart(in);
    }
    pt::Film film(0, 0);
    pt::PartInfo info;
    if (!pt::partFromImage(image, "fuzz.exr", film, info).empty()) return 0;
    // What merge and --resume do next: the part's pixels into the full image, and an image of it.
    if (size_t(info.fullWidth) * size_t(info.fullHeight) <= 4096) {
        pt::Film merged(info.fullWidth, info.fullHeight);
        merged.enableFirstHitLayers();
        for (int y = info.y0; y < info.y1; ++y)
            for (int x = info.x0; x < info.x1; ++x)
                merged.addPixel(size_t(y) * size_t(info.fullWidth) + size_t(x), film,
                                size_t(y - info.y0) * size_t(film.width()) + size_t(x - info.x0));
    }
    size_t overflowed;
    pt::AovSelection all{true, true, true, true};
    if (!film.hasFirstHitLayers()) all.albedo = all.normal = all.depth = false;
    pt::Image out = pt::filmImage(film, all, info.exposure, overflowed);
    (void)out;
    return 0;
}
