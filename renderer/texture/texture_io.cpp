#include "texture/texture_io.h"

#include "core/color.h"
#include "core/system.h"
#include "image/image_input.h"
#include "io/input_file.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace pt {

double textureMemoryBudget() {
    double physical = physicalMemoryBytes();
    return physical > 0 ? 0.25 * physical : 4e9;
}

namespace {

// Decodes an opened image into `texture`; `path` names it in messages and in the texture.
bool decodeTexture(OIIO::ImageInput& imageInput, const std::string& path, bool colour, Texture& texture,
                   std::string& error, double budgetBytes, bool& tooLarge) {
    OIIO::ImageInput* in = &imageInput;
    const OIIO::ImageSpec spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0) {
        error = "texture \"" + path + "\" has an unusable size " + std::to_string(w) + "x" + std::to_string(h);
        return false;
    }
    // Colour: RGB (grey read as one channel, then replicated). Data: up to four channels as stored.
    int stored = colour ? 3 : std::min(nc, 4);
    int read = colour ? (nc >= 3 ? 3 : 1) : stored;
    // Stored at the file's depth: 8 bits as 8 bits, half as half, anything else as float.
    OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    TexelFormat format = base == OIIO::TypeDesc::UINT8 ? (colour ? TexelFormat::Srgb8 : TexelFormat::Unorm8)
                         : base == OIIO::TypeDesc::HALF ? TexelFormat::Half
                                                        : TexelFormat::Float;
    bool isLinear = base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE;
    int bpc = bytesPerChannel(format);
    // The pyramid adds a third; a grey colour map is read once more before it is replicated.
    double texels = double(w) * double(h);
    double bytes = texels * bpc * (stored * 4.0 / 3.0 + (read < stored ? read : 0));
    if (bytes > budgetBytes) {
        tooLarge = true;
        char what[200];
        std::snprintf(what, sizeof what, "%dx%d, %.1f GB as %d-byte texels with their mip levels, beyond the %.1f GB "
                      "left for textures (a quarter of this machine's memory)", w, h, bytes / 1e9, stored * bpc,
                      std::max(0.0, budgetBytes) / 1e9);
        error = "texture \"" + path + "\" is too large: " + what;
        return false;
    }
    const OIIO::TypeDesc type = format == TexelFormat::Float ? OIIO::TypeDesc::FLOAT
                                : format == TexelFormat::Half ? OIIO::TypeDesc::HALF
                                                              : OIIO::TypeDesc::UINT8;
    const size_t texelBytes = size_t(stored) * size_t(bpc);
    try {
        texture.data.assign(size_t(w) * size_t(h) * texelBytes, 0);
        std::vector<uint8_t> grey(read < stored ? size_t(w) * size_t(h) * size_t(bpc) : 0);
        uint8_t* target = grey.empty() ? texture.data.data() : grey.data();
        if (std::string problem = readPixels(*in, read, type, target); !problem.empty()) {
            error = "cannot read texture \"" + path + "\": " + problem;
            texture.data.clear();
            return false;
        }
        for (size_t i = 0; i < size_t(w) * size_t(h) && !grey.empty(); ++i)
            for (int c = 0; c < 3; ++c) std::memcpy(&texture.data[i * texelBytes + size_t(c * bpc)], &grey[i * size_t(bpc)], size_t(bpc));
    } catch (const std::bad_alloc&) {
        tooLarge = true;
        error = "texture \"" + path + "\": out of memory for its " + std::to_string(w) + "x" + std::to_string(h) + " texels";
        texture.data.clear();
        return false;
    }
    texture.path = path;
    texture.colour = colour;
    texture.width = w;
    texture.height = h;
    texture.channels = stored;
    texture.format = format;
    texture.levels = {MipLevel{w, h, 0}};
    if (bpc == 1) return true; // every byte is a finite, non-negative value
    // 16-bit and wider integer colour files are sRGB-encoded; float values must be finite (and,
    // as colour, not negative), checked in order so that the first bad texel is named.
    const size_t count = size_t(w) * size_t(h) * size_t(stored);
    for (size_t i = 0; i < count; ++i) {
        uint8_t* at = texture.data.data() + i * size_t(bpc);
        float v = loadTexel(format, at);
        if (colour && !isLinear) {
            v = srgbToLinear(v);
            storeTexel(format, v, at);
        }
        if (std::isfinite(v) && (v >= 0.0f || !colour)) continue; // data may be signed
        size_t pixel = i / size_t(stored);
        char what[200];
        std::snprintf(what, sizeof what, "texel (%zu, %zu) channel %zu is %g; %s", pixel % size_t(w), pixel / size_t(w),
                      i % size_t(stored), double(v), colour ? "a colour must be finite and not negative" : "values must be finite");
        error = "texture \"" + path + "\": " + what;
        texture.data.clear();
        return false;
    }
    return true;
}

} // namespace

bool readTexture(const std::string& path, bool colour, Texture& texture, std::string& error, double budgetBytes,
                 bool& tooLarge) {
    tooLarge = false;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) { // a pipe or device could block forever
        std::string problem = pathProblem(path);
        error = "texture \"" + path + "\" " + (problem.empty() ? "is not a regular file" : problem);
        return false;
    }
    // A file holds no fewer bytes than its texels take, so the budget bounds it.
    WholeImageFile file;
    if (std::string openError = openImageWhole(path, uint64_t(std::max(0.0, budgetBytes)), file, tooLarge); !openError.empty()) {
        error = tooLarge ? "texture \"" + path + "\" is too large: " + openError + " (textures may take a quarter of this "
                           "machine's memory, all together)"
                         : "cannot read texture \"" + path + "\": " + openError;
        return false;
    }
    texture.sourceHash = contentHash(file.bytes.data(), file.bytes.size());
    return decodeTexture(*file.input, path, colour, texture, error, budgetBytes, tooLarge);
}

bool readTextureFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, const std::string& format,
                           bool colour, Texture& texture, std::string& error, double budgetBytes, bool& tooLarge) {
    tooLarge = false;
    MemoryImageReader reader(bytes);
    auto in = openImageMemory(bytes, reader, "image" + format, error);
    if (!in) {
        error = "cannot decode " + name + ": " + error;
        return false;
    }
    return decodeTexture(*in, name, colour, texture, error, budgetBytes, tooLarge);
}

} // namespace pt
