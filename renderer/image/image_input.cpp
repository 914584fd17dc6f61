#include "image/image_input.h"

#include "image/exr_header.h"
#include "io/input_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace pt {
namespace {

const char* const kKnownFormats = "PNG, JPEG, OpenEXR, Radiance HDR, TIFF, BMP, GIF, PNM/PFM, WebP or TGA";

bool startsWith(const unsigned char* head, size_t size, const char* magic, size_t length) {
    return size >= length && std::memcmp(head, magic, length) == 0;
}

// Opens `name` (or `proxy`'s bytes) with `format`'s reader. `head` holds the first bytes of the
// file (up to kMaxExrHeaderBytes), `fileSize` its length: an EXR header is checked on them first.
std::unique_ptr<OIIO::ImageInput> openAs(const std::string& format, const std::string& name, OIIO::Filesystem::IOProxy* proxy,
                                         const unsigned char* head, size_t headSize, uint64_t fileSize, std::string& error) {
    if (format.empty()) {
        error = unknownImageFormat();
        return nullptr;
    }
    if (format == "openexr" && !(error = checkExrHeader(head, headSize, fileSize)).empty()) return nullptr;
    static const bool chunked = OIIO::attribute("read_chunk", 16); // see kImageReadChunk
    (void)chunked;
    auto in = OIIO::ImageInput::create(format);
    if (!in) {
        error = "this build of OpenImageIO has no " + format + " reader";
        return nullptr;
    }
    if (proxy && (!in->supports("ioproxy") || !in->set_ioproxy(proxy))) {
        error = "OpenImageIO's " + format + " reader cannot read from memory";
        return nullptr;
    }
    // Colour and alpha as stored: OpenImageIO premultiplies unassociated alpha (PNG, TIFF, TGA)
    // unless told not to, and glTF's alpha is coverage only, never a factor of the colour.
    OIIO::ImageSpec spec, config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (!in->open(name, spec, config)) {
        error = in->geterror();
        if (error.empty()) error = OIIO::geterror();
        if (error.empty()) error = "not a valid " + format + " file";
        return nullptr;
    }
    return in;
}

} // namespace

bool MemoryImageReader::seek(int64_t offset) {
    if (offset < 0 || uint64_t(offset) > size()) return false;
    m_pos = offset;
    return true;
}

size_t MemoryImageReader::read(void* buf, size_t size) {
    size_t n = pread(buf, size, m_pos);
    m_pos += int64_t(n);
    return n;
}

size_t MemoryImageReader::pread(void* buf, size_t size, int64_t offset) {
    if (offset < 0 || uint64_t(offset) >= this->size()) return 0;
    size_t n = std::min(size, this->size() - size_t(offset));
    std::memcpy(buf, m_buf.data() + offset, n);
    return n;
}

std::string imageFormatOf(const unsigned char* head, size_t size, const std::string& name) {
    if (startsWith(head, size, "\x89PNG", 4)) return "png";
    if (startsWith(head, size, "\xFF\xD8\xFF", 3)) return "jpeg";
    if (startsWith(head, size, "\x76\x2F\x31\x01", 4)) return "openexr";
    if (startsWith(head, size, "#?", 2)) return "hdr"; // #?RADIANCE, #?RGBE
    if (startsWith(head, size, "II*\0", 4) || startsWith(head, size, "MM\0*", 4)) return "tiff";
    if (startsWith(head, size, "BM", 2)) return "bmp";
    if (startsWith(head, size, "GIF8", 4)) return "gif";
    if (size >= 2 && head[0] == 'P' && std::strchr("123456Ff", head[1]) && head[1] != 0) return "pnm";
    if (startsWith(head, size, "RIFF", 4) && size >= 12 && std::memcmp(head + 8, "WEBP", 4) == 0) return "webp";
    std::string ext = std::filesystem::path(name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".tga" || ext == ".tpic") return "targa"; // the one format without a magic number
    return "";
}

std::string imageFormatOfFile(const std::string& path) {
    unsigned char head[16] = {};
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(head), sizeof head);
    return imageFormatOf(head, size_t(file.gcount()), path);
}

std::string unknownImageFormat() {
    return "not an image file pt reads (its first bytes are those of none of " + std::string(kKnownFormats) + ")";
}

std::unique_ptr<OIIO::ImageInput> openImageFile(const std::string& path, std::string& error) {
    std::vector<unsigned char> head(kMaxExrHeaderBytes);
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    head.resize(size_t(file.gcount()));
    std::error_code ec;
    uint64_t size = std::filesystem::file_size(path, ec);
    return openAs(imageFormatOf(head.data(), head.size(), path), path, nullptr, head.data(), head.size(), ec ? 0 : size, error);
}

std::string openImageWhole(const std::string& path, uint64_t maxBytes, WholeImageFile& file, bool& tooLarge) {
    tooLarge = false;
    if (imageFormatOfFile(path).empty()) return unknownImageFormat();
    std::error_code ec;
    if (uint64_t size = std::filesystem::file_size(path, ec); !ec && size > maxBytes) {
        tooLarge = true;
        char text[120];
        std::snprintf(text, sizeof text, "its file of %.3g GB is larger than the %.3g GB it may take", double(size) / 1e9,
                      double(maxBytes) / 1e9);
        return text;
    }
    if (std::string error = readRegularFile(path, maxBytes, file.bytes); !error.empty()) return error;
    file.reader = std::make_unique<MemoryImageReader>(file.bytes);
    std::string error;
    file.input = openImageMemory(file.bytes, *file.reader, path, error);
    return error;
}

std::string readPixels(OIIO::ImageInput& in, int channels, OIIO::TypeDesc type, void* data) {
    (void)in.geterror(); // clears what earlier calls left (a seek past the last subimage says so)
    bool read = in.read_image(0, 0, 0, channels, type, data);
    std::string error = in.geterror();
    if (read && error.empty()) return "";
    if (error.empty()) error = "the decoder failed without saying why";
    return read ? "the file is damaged or cut short (" + error + ")" : error;
}

std::unique_ptr<OIIO::ImageInput> openImageMemory(const std::vector<unsigned char>& bytes,
                                                  MemoryImageReader& reader, const std::string& name,
                                                  std::string& error) {
    return openAs(imageFormatOf(bytes.data(), bytes.size(), name), name, &reader, bytes.data(), bytes.size(), bytes.size(), error);
}

} // namespace pt
