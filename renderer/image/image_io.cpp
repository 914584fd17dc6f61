#include "image/image_io.h"

#include "image/exr_header.h"
#include "image/image_input.h"
#include "io/input_file.h"

#include "core/color.h"
#include "core/system.h"
#include "io/output_file.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace pt {

namespace fs = std::filesystem;

static std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext;
}

ImageFormat formatFromPath(const std::string& path) {
    std::string ext = lowerExtension(path);
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".png") return ImageFormat::Png;
    return ImageFormat::Unknown;
}

std::string checkOutputPath(const std::string& path) {
    if (formatFromPath(path) == ImageFormat::Unknown)
        return "output \"" + path + "\": unknown extension \"" + lowerExtension(path) + "\"; expected .exr or .png";
    return checkOutputLocation(path);
}

std::string ImageAttribute::asText() const {
    switch (type) {
    case Type::Int: return std::to_string(integer);
    case Type::Float: {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", number);
        return buf;
    }
    case Type::String: break;
    case Type::Other: return "(" + text + ")";
    }
    return text;
}

static void addAttributes(OIIO::ImageSpec& spec, const Image& image) {
    for (const ImageAttribute& a : image.metadata) {
        switch (a.type) {
        case ImageAttribute::Type::Int: spec.attribute(a.name, int(a.integer)); break;
        case ImageAttribute::Type::Float: spec.attribute(a.name, float(a.number)); break;
        case ImageAttribute::Type::String: spec.attribute(a.name, a.text); break;
        case ImageAttribute::Type::Other: {
            const OIIO::TypeDesc type(a.text);
            if (type.basetype != OIIO::TypeDesc::UNKNOWN && type.size() == a.bytes.size())
                spec.attribute(a.name, type, a.bytes.data());
            break;
        }
        }
    }
}

// Encodes the image in `format` into memory. Returns "" or the error.
static std::string encodeImage(ImageFormat format, const Image& image, std::vector<unsigned char>& bytes) {
    bytes.clear();
    // The format plugin is picked by a name; the bytes go to memory, and only OutputFile touches
    // the disk, checking every step (OpenImageIO's PNG writer does not report a full disk).
    const char* name = format == ImageFormat::Png ? "image.png" : "image.exr";
    auto out = OIIO::ImageOutput::create(name);
    if (!out) return std::string("cannot create an image writer: ") + OIIO::geterror();
    if (!out->supports("ioproxy")) return std::string("the ") + out->format_name() + " writer cannot write to memory";
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    size_t n = size_t(image.width) * image.height;

    if (format == ImageFormat::Png) {
        OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
        addAttributes(spec, image);
        std::vector<uint8_t> pixels(n * 3);
        for (size_t i = 0; i < n * 3; ++i) {
            float v = image.rgb[i];
            // Saturated as a display would: infinity is white; only NaN, which has no brightness, is black.
            v = std::isnan(v) ? 0.0f : std::clamp(linearToSrgb(std::clamp(v, 0.0f, 1.0f)), 0.0f, 1.0f);
            pixels[i] = uint8_t(std::lround(v * 255.0f));
        }
        if (!out->set_ioproxy(&proxy) || !out->open(name, spec) ||
            !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
            return out->geterror();
        return "";
    }

    // EXR: R, G, B first so that every viewer shows the beauty, then the layers.
    std::vector<std::string> names = {"R", "G", "B"};
    for (const ImageLayer& layer : image.layers)
        for (const std::string& c : layer.channels) names.push_back(layer.name.empty() ? c : layer.name + "." + c);
    int nc = int(names.size());
    OIIO::ImageSpec spec(image.width, image.height, nc, OIIO::TypeDesc::FLOAT);
    if (image.fullWidth > 0) {
        spec.x = image.x, spec.y = image.y;
        spec.full_x = spec.full_y = 0;
        spec.full_width = image.fullWidth, spec.full_height = image.fullHeight;
    }
    spec.channelnames = names;
    spec.attribute("compression", "zip");
    addAttributes(spec, image);
    std::vector<float> pixels(n * nc);
    for (size_t i = 0; i < n; ++i) {
        float* p = &pixels[i * nc];
        for (int c = 0; c < 3; ++c) p[c] = image.rgb[3 * i + c];
        int k = 3;
        for (const ImageLayer& layer : image.layers) {
            size_t lc = layer.channels.size();
            for (size_t c = 0; c < lc; ++c) p[k++] = layer.pixels[i * lc + c];
        }
    }
    if (!out->set_ioproxy(&proxy) || !out->open(name, spec) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
        return out->geterror();
    return "";
}

std::string writeImage(const std::string& path, const Image& image) {
    std::string check = checkOutputPath(path);
    if (!check.empty()) return check;
    OutputFile file;
    std::string error = file.open(path);
    return error.empty() ? writeImage(file, image) : error;
}

std::string writeImage(OutputFile& file, const Image& image) {
    std::vector<unsigned char> bytes;
    std::string error = encodeImage(formatFromPath(file.path()), image, bytes);
    if (!error.empty()) return "writing \"" + file.path() + "\" failed: " + error;
    return file.commit(bytes.data(), bytes.size());
}

// Reads the opened image `in`, which `path` names in messages, into `image`.
static std::string decodeImage(OIIO::ImageInput* in, const std::string& path, Image& image, double budgetBytes) {
    const OIIO::ImageSpec spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0) return "\"" + path + "\": empty image";
    // The file's pixels as float, then their copy into rgb and the layers: twice the bytes; and
    // OpenImageIO's buffer of the scanlines it reads at a time (image_input.h: 64 at most).
    double bytes = (2.0 * double(h) + double(kImageReadChunk)) * double(w) * double(nc) * sizeof(float);
    if (bytes > budgetBytes)
        return "\"" + path + "\": its header declares " + std::to_string(w) + "x" + std::to_string(h) + " pixels of " +
               std::to_string(nc) + " channels, about " + std::to_string(int(bytes / 1e9 + 0.5)) +
               " GB to read, more than half this machine's memory";
    int parts = 1;
    while (parts < 1000 && in->seek_subimage(parts, 0)) ++parts;
    if (!in->seek_subimage(0, 0)) return "cannot read \"" + path + "\": " + in->geterror();
    std::vector<float> pixels;
    try {
        pixels.resize(size_t(w) * h * nc);
    } catch (const std::bad_alloc&) {
        return "\"" + path + "\": out of memory for its " + std::to_string(w) + "x" + std::to_string(h) + " pixels";
    }
    if (std::string error = readPixels(*in, nc, OIIO::TypeDesc::FLOAT, pixels.data()); !error.empty())
        return "cannot read \"" + path + "\": " + error;

    image = Image{};
    image.width = w;
    image.height = h;
    if (spec.x != spec.full_x || spec.y != spec.full_y || spec.full_width != w || spec.full_height != h) {
        image.x = spec.x - spec.full_x, image.y = spec.y - spec.full_y;
        image.fullWidth = spec.full_width, image.fullHeight = spec.full_height;
    }
    image.parts = parts;
    for (int c = 0; c < nc; ++c)
        image.channelNames.push_back(c < int(spec.channelnames.size()) && !spec.channelnames[c].empty() ? spec.channelnames[c]
                                                                                                      : "channel" + std::to_string(c));
    size_t n = size_t(w) * h;
    int rgbIndex[3] = {-1, -1, -1};
    std::map<std::string, std::vector<std::pair<std::string, int>>> layerChannels;
    std::vector<std::string> layerOrder;
    for (int c = 0; c < nc; ++c) {
        const std::string& name = image.channelNames[size_t(c)];
        const auto dot = name.rfind('.');
        if (name == "R") rgbIndex[0] = c;
        else if (name == "G") rgbIndex[1] = c;
        else if (name == "B") rgbIndex[2] = c;
        else {
            std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
            if (!layerChannels.count(layer)) layerOrder.push_back(layer);
            layerChannels[layer].emplace_back(dot == std::string::npos ? name : name.substr(dot + 1), c);
        }
    }
    // No R, G, B: a grey image's one channel (Y, as OpenImageIO names a grey PNG's; or a file's
    // only channel) is the picture, in all three.
    if (rgbIndex[0] < 0 && rgbIndex[1] < 0 && rgbIndex[2] < 0) {
        auto& alone = layerChannels[""];
        auto grey = std::find_if(alone.begin(), alone.end(), [](const auto& c) { return c.first == "Y"; });
        if (grey == alone.end() && nc == 1 && !alone.empty()) grey = alone.begin();
        if (grey != alone.end()) {
            rgbIndex[0] = rgbIndex[1] = rgbIndex[2] = grey->second;
            image.beauty = Image::Beauty::Grey;
            alone.erase(grey);
        }
        if (alone.empty()) {
            layerChannels.erase("");
            std::erase(layerOrder, std::string());
        }
    }
    if (rgbIndex[0] < 0 || rgbIndex[1] < 0 || rgbIndex[2] < 0) image.beauty = Image::Beauty::Missing;
    bool srgb = spec.format.basetype != OIIO::TypeDesc::FLOAT && spec.format.basetype != OIIO::TypeDesc::HALF;
    image.rgb.assign(n * 3, 0.0f);
    if (image.beauty != Image::Beauty::Missing)
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) {
                float v = pixels[i * nc + rgbIndex[c]];
                image.rgb[3 * i + c] = srgb ? srgbToLinear(v) : v;
            }
    for (const std::string& name : layerOrder) {
        ImageLayer layer;
        layer.name = name;
        for (const auto& [cname, index] : layerChannels[name]) layer.channels.push_back(cname);
        layer.pixels.resize(n * layer.channels.size());
        const auto& chans = layerChannels[name];
        for (size_t i = 0; i < n; ++i)
            for (size_t c = 0; c < chans.size(); ++c) layer.pixels[i * chans.size() + c] = pixels[i * nc + chans[c].second];
        image.layers.push_back(std::move(layer));
    }
    // Every attribute with its own type: a v2f read as the string "0 0" and written back under
    // its name made OpenEXR throw (screenWindowCenter, in every pt denoise).
    for (const auto& attr : spec.extra_attribs) {
        const std::string name = attr.name().string();
        if (name.rfind("oiio:", 0) == 0 && name != "oiio:ColorSpace") continue; // the reader's facts (subimages), not the file's
        if (attr.type() == OIIO::TypeDesc::INT) image.metadata.push_back(ImageAttribute::integerValue(name, attr.get_int()));
        else if (attr.type() == OIIO::TypeDesc::FLOAT) image.metadata.push_back(ImageAttribute::floatValue(name, attr.get_float()));
        else if (attr.type() == OIIO::TypeDesc::STRING) image.metadata.push_back(ImageAttribute::string(name, attr.get_string()));
        else {
            ImageAttribute a{name, ImageAttribute::Type::Other, attr.type().c_str()};
            const auto* data = static_cast<const unsigned char*>(attr.data());
            a.bytes.assign(data, data + attr.type().size() * size_t(attr.nvalues()));
            image.metadata.push_back(std::move(a));
        }
    }
    return "";
}

std::string readImage(const std::string& path, Image& image) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) return "cannot read \"" + path + "\": " + std::strerror(errno);
    if (S_ISDIR(st.st_mode)) return "cannot read \"" + path + "\": it is a folder, not an image";
    if (!S_ISREG(st.st_mode)) return "cannot read \"" + path + "\": not a regular file (a device or pipe?)";
    const double budget = 0.5 * physicalMemoryBytes();
    // An EXR is read whole, so that its chunks can be checked against its header after OpenEXR
    // has read them (checkExrChunks); its file is no larger than its pixels, which the budget
    // bounds.
    if (imageFormatOfFile(path) == "openexr") {
        std::vector<unsigned char> bytes;
        if (std::string error = readRegularFile(path, uint64_t(budget), bytes); !error.empty())
            return "cannot read \"" + path + "\": " + error;
        return readImageFromMemory(bytes, path, image, budget);
    }
    std::string error;
    auto in = openImageFile(path, error);
    if (!in) return "cannot read \"" + path + "\": " + error;
    return decodeImage(in.get(), path, image, budget);
}

std::string readImageFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, Image& image,
                                double budgetBytes) {
    MemoryImageReader reader(bytes);
    std::string error;
    auto in = openImageMemory(bytes, reader, name, error);
    if (!in) return "cannot read \"" + name + "\": " + error;
    if (error = decodeImage(in.get(), name, image, budgetBytes); !error.empty()) return error;
    if (std::string(in->format_name()) == "openexr")
        if (error = checkExrChunks(bytes.data(), bytes.size()); !error.empty()) {
            image = Image{};
            return "cannot read \"" + name + "\": " + error;
        }
    return "";
}

std::string missingRgb(const Image& image) {
    if (image.beauty != Image::Beauty::Missing) return "";
    std::string have, channels;
    for (const char* c : {"R", "G", "B"})
        if (std::find(image.channelNames.begin(), image.channelNames.end(), c) != image.channelNames.end())
            have += std::string(have.empty() ? "" : " and ") + c;
    for (const std::string& c : image.channelNames) channels += (channels.empty() ? "" : ", ") + c;
    std::string lacks;
    for (const char* c : {"R", "G", "B"})
        if (std::find(image.channelNames.begin(), image.channelNames.end(), c) == image.channelNames.end())
            lacks += std::string(lacks.empty() ? "" : " or ") + c;
    return (have.empty() ? "no R, G or B channel" : have + " but no " + lacks) + " (its channels: " + channels + ")";
}


} // namespace pt
