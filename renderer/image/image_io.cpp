#include "image/image_io.h"

#include "image/texture_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <unistd.h>

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
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return "output \"" + path + "\": folder \"" + dir.string() + "\" does not exist";
    if (access(dir.c_str(), W_OK) != 0) return "output \"" + path + "\": folder \"" + dir.string() + "\" is not writable";
    if (fs::is_directory(path, ec)) return "output \"" + path + "\" is a folder";
    return "";
}

static std::string writeTo(const std::string& path, const std::string& tmp, const Image& image) {
    ImageFormat format = formatFromPath(path);
    auto out = OIIO::ImageOutput::create(path); // the real name picks the format plugin
    if (!out) return "cannot create a writer for \"" + path + "\": " + OIIO::geterror();
    size_t n = size_t(image.width) * image.height;

    if (format == ImageFormat::Png) {
        OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
        for (const auto& [k, v] : image.metadata) spec.attribute(k, v);
        std::vector<uint8_t> pixels(n * 3);
        for (size_t i = 0; i < n * 3; ++i) {
            float v = image.rgb[i];
            v = std::isfinite(v) ? std::clamp(linearToSrgb(std::max(v, 0.0f)), 0.0f, 1.0f) : 0.0f;
            pixels[i] = uint8_t(std::lround(v * 255.0f));
        }
        if (!out->open(tmp, spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
            return out->geterror();
        return "";
    }

    // EXR: R, G, B first so that every viewer shows the beauty, then the layers.
    std::vector<std::string> names = {"R", "G", "B"};
    for (const ImageLayer& layer : image.layers)
        for (const std::string& c : layer.channels) names.push_back(layer.name + "." + c);
    int nc = int(names.size());
    OIIO::ImageSpec spec(image.width, image.height, nc, OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", "zip");
    for (const auto& [k, v] : image.metadata) spec.attribute(k, v);
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
    if (!out->open(tmp, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
        return out->geterror();
    return "";
}

std::string writeImage(const std::string& path, const Image& image) {
    std::string check = checkOutputPath(path);
    if (!check.empty()) return check;
    fs::path p(path);
    std::string tmp = (p.parent_path() / ("." + p.stem().string() + ".tmp-" + std::to_string(getpid()) +
                                          p.extension().string())).string();
    std::string error = writeTo(path, tmp, image);
    if (error.empty()) {
        std::error_code ec;
        fs::rename(tmp, path, ec);
        if (ec) error = "cannot rename \"" + tmp + "\" to \"" + path + "\": " + ec.message();
    }
    if (!error.empty()) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        return "writing \"" + path + "\" failed: " + error;
    }
    return "";
}

std::string readImage(const std::string& path, Image& image) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return "cannot read \"" + path + "\": " + OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0) return "\"" + path + "\": empty image";
    std::vector<float> pixels(size_t(w) * h * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, pixels.data()))
        return "cannot read \"" + path + "\": " + in->geterror();

    image = Image{};
    image.width = w;
    image.height = h;
    size_t n = size_t(w) * h;
    int rgbIndex[3] = {-1, -1, -1};
    std::map<std::string, std::vector<std::pair<std::string, int>>> layerChannels;
    std::vector<std::string> layerOrder;
    for (int c = 0; c < nc; ++c) {
        std::string name = c < int(spec.channelnames.size()) ? spec.channelnames[c] : "";
        if (name == "R") rgbIndex[0] = c;
        else if (name == "G") rgbIndex[1] = c;
        else if (name == "B") rgbIndex[2] = c;
        else if (auto dot = name.rfind('.'); dot != std::string::npos) {
            std::string layer = name.substr(0, dot);
            if (!layerChannels.count(layer)) layerOrder.push_back(layer);
            layerChannels[layer].emplace_back(name.substr(dot + 1), c);
        }
    }
    if (rgbIndex[0] < 0) { // unnamed channels (PNG, JPEG): first three, or grey
        for (int c = 0; c < 3; ++c) rgbIndex[c] = std::min(c, nc - 1);
        if (nc == 2) rgbIndex[1] = rgbIndex[2] = 0; // grey + alpha
    }
    for (int c = 0; c < 3; ++c)
        if (rgbIndex[c] < 0) rgbIndex[c] = rgbIndex[0];
    bool srgb = spec.format.basetype != OIIO::TypeDesc::FLOAT && spec.format.basetype != OIIO::TypeDesc::HALF;
    image.rgb.resize(n * 3);
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
    for (const auto& attr : spec.extra_attribs)
        image.metadata.emplace_back(attr.name().string(), attr.get_string());
    return "";
}

} // namespace pt
