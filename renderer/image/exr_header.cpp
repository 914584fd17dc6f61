#include "image/exr_header.h"

#include <algorithm>
#include <cstring>

namespace pt {
namespace {

int32_t int32At(const unsigned char* p) {
    uint32_t v = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    int32_t s;
    std::memcpy(&s, &v, sizeof s);
    return s;
}

// Scanlines per chunk of each compression (OpenEXR's Compression enum); the largest for others.
int64_t linesPerChunk(int compression) {
    switch (compression) {
    case 0: case 1: case 2: return 1;   // none, RLE, ZIPS
    case 3: case 5: return 16;          // ZIP, PXR24
    case 4: case 6: case 7: case 8: return 32; // PIZ, B44, B44A, DWAA
    default: return 256;                // DWAB, or unknown: the fewest chunks
    }
}

} // namespace

std::string checkExrHeader(const unsigned char* head, size_t size, uint64_t fileSize) {
    if (size < 8) return "its OpenEXR header is cut short";
    const bool tiled = head[5] & 0x02, longNames = head[5] & 0x04;
    const size_t maxName = longNames ? 256 : 32;
    bool haveWindow = false, haveTiles = false, haveChunkCount = false;
    int64_t bytesPerPixel = 0; // of every channel in chlist, uncompressed
    int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1, tileX = 1, tileY = 1, chunkCount = 0;
    int compression = 0;
    size_t at = 8;
    auto text = [&](std::string& out) { // a NUL-terminated name, shorter than maxName
        const void* end = std::memchr(head + at, 0, std::min(size - at, maxName));
        if (!end) return false;
        out.assign(reinterpret_cast<const char*>(head + at), static_cast<const unsigned char*>(end) - (head + at));
        at += out.size() + 1;
        return true;
    };
    for (;;) {
        if (at >= size) return "its OpenEXR header does not end within its first " + std::to_string(size) + " bytes";
        if (head[at] == 0) break; // the end of the (first) header
        std::string name, type;
        if (!text(name) || !text(type) || size - at < 4) return "its OpenEXR header holds a malformed attribute";
        int32_t length = int32At(head + at);
        at += 4;
        if (length < 0 || uint64_t(length) > size - at) return "its OpenEXR attribute \"" + name + "\" runs past its header";
        const unsigned char* v = head + at;
        if (name == "dataWindow" && type == "box2i" && length == 16)
            x0 = int32At(v), y0 = int32At(v + 4), x1 = int32At(v + 8), y1 = int32At(v + 12), haveWindow = true;
        else if (name == "compression" && length == 1)
            compression = v[0];
        else if (name == "tiles" && type == "tiledesc" && length == 9)
            tileX = uint32_t(int32At(v)), tileY = uint32_t(int32At(v + 4)), haveTiles = true;
        else if (name == "chunkCount" && length == 4)
            chunkCount = int32At(v), haveChunkCount = true;
        else if (name == "channels" && type == "chlist")
            for (size_t c = 0; c < size_t(length) && v[c] != 0;) { // name, then type, pLinear, 3 reserved, two samplings
                const void* end = std::memchr(v + c, 0, size_t(length) - c);
                if (!end || size_t(static_cast<const unsigned char*>(end) - v) + 17 > size_t(length))
                    return "its OpenEXR channel list is malformed";
                c = size_t(static_cast<const unsigned char*>(end) - v) + 1;
                bytesPerPixel += int32At(v + c) == 1 ? 2 : 4; // half, or uint and float
                c += 16;
            }
        at += size_t(length);
    }
    if (!haveWindow) return "its OpenEXR header has no dataWindow";
    int64_t width = x1 - x0 + 1, height = y1 - y0 + 1;
    if (width <= 0 || height <= 0) return "its OpenEXR data window is empty";
    int64_t chunks;
    if (haveChunkCount) chunks = chunkCount;
    else if (tiled && haveTiles && tileX > 0 && tileY > 0) chunks = ((width + tileX - 1) / tileX) * ((height + tileY - 1) / tileY);
    else chunks = (height + linesPerChunk(compression) - 1) / linesPerChunk(compression);
    if (width > kMaxExrSide || height > kMaxExrSide)
        return "its OpenEXR data window is " + std::to_string(width) + "x" + std::to_string(height) +
               "; pt reads images of at most 262144 pixels a side";
    // What OpenEXR allocates for one chunk, uncompressed, before it reads a byte of it.
    int64_t chunkPixels = tiled && haveTiles ? std::min(tileX, width) * std::min(tileY, height)
                                             : width * std::min(linesPerChunk(compression), height);
    if (chunkPixels * bytesPerPixel > kMaxExrChunkBytes)
        return "its OpenEXR chunks hold " + std::to_string(chunkPixels * bytesPerPixel) + " bytes each, uncompressed; pt "
               "reads chunks of at most 1 GB";
    if (chunks < 0 || uint64_t(chunks) * 8 > fileSize)
        return "its OpenEXR header declares a " + std::to_string(width) + "x" + std::to_string(height) + " data window in " +
               std::to_string(chunks) + " chunks, whose table of offsets alone needs " + std::to_string(chunks * 8) +
               " bytes; the file has " + std::to_string(fileSize) + " (truncated or corrupt)";
    return "";
}

} // namespace pt
