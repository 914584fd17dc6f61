#include "image/texture_io.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

namespace pt {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

bool readTexture(const std::string& path, Texture& texture, std::string& error) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) { // a pipe or device could block forever
        error = "texture \"" + path + "\" " + (std::filesystem::exists(path, ec) ? "is not a regular file" : "not found");
        return false;
    }
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        error = "cannot read texture \"" + path + "\": " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0 || size_t(w) * size_t(h) > (size_t(1) << 28)) {
        error = "texture \"" + path + "\" has an unusable size " + std::to_string(w) + "x" + std::to_string(h);
        return false;
    }
    std::vector<float> pixels(size_t(w) * h * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, pixels.data())) {
        error = "cannot read texture \"" + path + "\": " + in->geterror();
        return false;
    }
    bool isLinear = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF;
    texture.path = path;
    texture.width = w;
    texture.height = h;
    texture.texels.resize(size_t(w) * h);
    for (size_t i = 0; i < texture.texels.size(); ++i) {
        const float* p = &pixels[i * nc];
        Spectrum c = nc >= 3 ? Spectrum(p[0], p[1], p[2]) : Spectrum(p[0]);
        if (!isLinear) c = Spectrum(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z));
        texture.texels[i] = isFinite(c) ? glm::max(c, Spectrum(0.0f)) : Spectrum(0.0f);
    }
    return true;
}

} // namespace pt
