#include "texture/texture_io.h"

#include "core/color.h"
#include "core/system.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pt {

double textureMemoryBudget() {
    double physical = physicalMemoryBytes();
    return physical > 0 ? 0.25 * physical : 4e9;
}

bool readTexture(const std::string& path, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge) {
    tooLarge = false;
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
    const OIIO::ImageSpec spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0) {
        error = "texture \"" + path + "\" has an unusable size " + std::to_string(w) + "x" + std::to_string(h);
        return false;
    }
    // RGB float texels, plus one float channel while a grey image is expanded.
    double bytes = double(w) * double(h) * (sizeof(Spectrum) + (nc < 3 ? sizeof(float) : 0));
    if (bytes > budgetBytes) {
        tooLarge = true;
        char what[160];
        std::snprintf(what, sizeof what, "%dx%d, %.1f GB as float texels, beyond the %.1f GB left for textures "
                      "(a quarter of this machine's memory)", w, h, bytes / 1e9, std::max(0.0, budgetBytes) / 1e9);
        error = "texture \"" + path + "\" is too large: " + what;
        return false;
    }
    try {
        texture.texels.assign(size_t(w) * h, Spectrum(0.0f));
        std::vector<float> grey(nc < 3 ? size_t(w) * h : 0);
        // RGB straight into the texels (alpha and further channels are not read).
        bool ok = nc >= 3 ? in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, texture.texels.data())
                          : in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, grey.data());
        if (!ok) {
            error = "cannot read texture \"" + path + "\": " + in->geterror();
            texture.texels.clear();
            return false;
        }
        for (size_t i = 0; i < grey.size(); ++i) texture.texels[i] = Spectrum(grey[i]);
    } catch (const std::bad_alloc&) {
        tooLarge = true;
        error = "texture \"" + path + "\": out of memory for its " + std::to_string(w) + "x" + std::to_string(h) + " texels";
        texture.texels.clear();
        return false;
    }
    bool isLinear = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF;
    texture.path = path;
    texture.width = w;
    texture.height = h;
    for (Spectrum& c : texture.texels) {
        if (!isLinear) c = Spectrum(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z));
        c = isFinite(c) ? glm::max(c, Spectrum(0.0f)) : Spectrum(0.0f);
    }
    return true;
}

} // namespace pt
