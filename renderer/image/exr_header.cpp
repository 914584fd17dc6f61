#include "image/exr_header.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <vector>

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

// The size of a value of each attribute type OpenEXR 3.1 reads whatever size the file declares;
// 0 for the types it reads by the declared size or by their contents.
int64_t fixedValueSize(const std::string& type) {
    static const std::pair<const char*, int64_t> kSizes[] = {
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
        {"envmap", 1}, {"lineOrder", 1}, {"double", 8}, {"float", 4}, {"int", 4}, {"keycode", 28},
        {"rational", 8}, {"timecode", 8}, {"tiledesc", 9}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
        {"m44d", 128}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};
    for (const auto& [name, bytes] : kSizes)
        if (type == name) return bytes;
    return 0;
}

// Whether OpenEXR reads exactly `length` bytes for a value of `type` at `v`, and allocates no
// more: it reads fixed-size types, channel lists and previews by their contents, string vectors
// by lengths inside them, and ID manifests as `length` - 4 bytes. A value that disagrees would
// make OpenEXR read the rest of the header from another place than this check, or allocate from
// a number the file never backs (a string of 2 GB in a 60-byte vector).
bool valueReadAsDeclared(const std::string& type, const unsigned char* v, int64_t length) {
    if (int64_t fixed = fixedValueSize(type)) return length == fixed;
    if (type == "chlist") { // name, NUL, type, pLinear, 3 reserved, two samplings; then NUL
        int64_t c = 0;
        while (c < length && v[c] != 0) {
            const void* end = std::memchr(v + c, 0, size_t(length - c));
            if (!end) return false;
            c = static_cast<const unsigned char*>(end) - v + 1 + 16;
        }
        return c + 1 == length;
    }
    if (type == "preview") // width, height, then 4 bytes a pixel
        return length >= 8 && uint64_t(uint32_t(int32At(v))) * uint32_t(int32At(v + 4)) * 4 == uint64_t(length - 8);
    if (type == "stringvector") { // each string: its length, then its bytes
        for (int64_t c = 0; c < length;) {
            if (length - c < 4) return false;
            int32_t n = int32At(v + c);
            if (n < 0 || n > length - c - 4) return false;
            c += 4 + n;
        }
        return true;
    }
    if (type == "idmanifest") return length >= 8;
    return true; // string, floatvector and types OpenEXR does not know: `length` bytes
}

// One header's facts, as far as the chunk table and a chunk's size go.
struct PartHeader {
    bool haveWindow = false, haveTiles = false, haveChunkCount = false;
    bool subsampled = false;   // a channel sampled at other than every pixel
    int64_t bytesPerPixel = 0; // of every channel in chlist, uncompressed
    int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1, tileX = 1, tileY = 1, chunkCount = 0;
    int compression = 0, levelMode = 0; // tiles: 0 one level, 1 mipmaps, 2 ripmaps
};

// Walks one header from `at` to its closing NUL (consumed), as OpenEXR reads it.
std::string readHeader(const unsigned char* head, size_t size, size_t maxName, size_t& at, PartHeader& h) {
    auto text = [&](std::string& out) { // a NUL-terminated name, shorter than maxName
        if (at >= size) return false;
        const void* end = std::memchr(head + at, 0, std::min(size - at, maxName));
        if (!end) return false;
        out.assign(reinterpret_cast<const char*>(head + at), static_cast<const unsigned char*>(end) - (head + at));
        at += out.size() + 1;
        return true;
    };
    for (;;) {
        if (at >= size) return "its OpenEXR header does not end within its first " + std::to_string(size) + " bytes";
        if (head[at] == 0) break;
        std::string name, type;
        if (!text(name) || !text(type) || size - at < 4) return "its OpenEXR header holds a malformed attribute";
        int32_t length = int32At(head + at);
        at += 4;
        if (length < 0 || uint64_t(length) > size - at) return "its OpenEXR attribute \"" + name + "\" runs past its header";
        const unsigned char* v = head + at;
        if (!valueReadAsDeclared(type, v, length))
            return "its OpenEXR attribute \"" + name + "\" of type " + type + " declares " + std::to_string(length) +
                   " bytes, which its value does not fill";
        if (name == "dataWindow" && type == "box2i")
            h.x0 = int32At(v), h.y0 = int32At(v + 4), h.x1 = int32At(v + 8), h.y1 = int32At(v + 12), h.haveWindow = true;
        else if (name == "compression" && type == "compression")
            h.compression = v[0];
        else if (name == "tiles" && type == "tiledesc")
            h.tileX = uint32_t(int32At(v)), h.tileY = uint32_t(int32At(v + 4)), h.levelMode = v[8] & 0x0f, h.haveTiles = true;
        else if (name == "chunkCount" && type == "int")
            h.chunkCount = int32At(v), h.haveChunkCount = true;
        else if (name == "channels" && type == "chlist")
            for (size_t c = 0; v[c] != 0;) {
                c = size_t(static_cast<const unsigned char*>(std::memchr(v + c, 0, size_t(length) - c)) - v) + 1;
                h.bytesPerPixel += int32At(v + c) == 1 ? 2 : 4; // half, or uint and float
                h.subsampled |= int32At(v + c + 8) != 1 || int32At(v + c + 12) != 1;
                c += 16;
            }
        at += size_t(length);
    }
    ++at;
    return "";
}

// The number of chunks of one part, or an error if the part could not be read within pt's limits.
std::string chunksOf(const PartHeader& h, bool tiled, int64_t& chunks) {
    if (!h.haveWindow) return "its OpenEXR header has no dataWindow";
    int64_t width = h.x1 - h.x0 + 1, height = h.y1 - h.y0 + 1;
    if (width <= 0 || height <= 0) return "its OpenEXR data window is empty";
    if (h.haveChunkCount) chunks = h.chunkCount;
    else if (tiled && h.haveTiles && h.tileX > 0 && h.tileY > 0)
        chunks = ((width + h.tileX - 1) / h.tileX) * ((height + h.tileY - 1) / h.tileY);
    else chunks = (height + linesPerChunk(h.compression) - 1) / linesPerChunk(h.compression);
    if (width > kMaxExrSide || height > kMaxExrSide)
        return "its OpenEXR data window is " + std::to_string(width) + "x" + std::to_string(height) +
               "; pt reads images of at most 262144 pixels a side";
    // What OpenEXR allocates for one chunk, uncompressed, before it reads a byte of it.
    int64_t chunkPixels = tiled && h.haveTiles ? std::min(h.tileX, width) * std::min(h.tileY, height)
                                               : width * std::min(linesPerChunk(h.compression), height);
    if (chunkPixels * h.bytesPerPixel > kMaxExrChunkBytes)
        return "its OpenEXR chunks hold " + std::to_string(chunkPixels * h.bytesPerPixel) + " bytes each, uncompressed; pt "
               "reads chunks of at most 1 GB";
    if (chunks < 0) return "its OpenEXR header declares " + std::to_string(chunks) + " chunks";
    return "";
}

} // namespace

std::string checkExrHeader(const unsigned char* head, size_t size, uint64_t fileSize) {
    if (size < 8) return "its OpenEXR header is cut short";
    if (head[5] & 0x08) return "it is a deep OpenEXR image (a varying number of samples a pixel); pt reads flat images only";
    const bool tiled = head[5] & 0x02, longNames = head[5] & 0x04, multipart = head[5] & 0x10;
    const size_t maxName = longNames ? 256 : 32;
    size_t at = 8;
    int64_t chunks = 0; // of every part: their tables of offsets lie one after another
    for (int part = 0;; ++part) {
        PartHeader h;
        if (std::string error = readHeader(head, size, maxName, at, h); !error.empty()) return error;
        int64_t partChunks = 0;
        if (std::string error = chunksOf(h, tiled, partChunks); !error.empty()) return error;
        chunks += partChunks;
        if (uint64_t(chunks) * 8 > fileSize)
            return "its OpenEXR header declares a " + std::to_string(h.x1 - h.x0 + 1) + "x" + std::to_string(h.y1 - h.y0 + 1) +
                   " data window in " + std::to_string(chunks) + " chunks, whose table of offsets alone needs " +
                   std::to_string(chunks * 8) + " bytes; the file has " + std::to_string(fileSize) + " (truncated or corrupt)";
        // A multipart file ends its list of headers with an empty one.
        if (!multipart || (at < size && head[at] == 0)) break;
        if (part >= 1024) return "its OpenEXR file declares more than 1024 parts";
    }
    return "";
}

namespace {

// The bytes OpenEXR's RLE data unpacks to (its rleUncompress), or -1 where it runs past its end.
int64_t rleUnpackedSize(const unsigned char* in, int64_t length) {
    int64_t out = 0;
    while (length > 0) {
        const int count = int(static_cast<signed char>(*in));
        if (count < 0) {
            if (length < 1 - count) return -1;
            out += -count, in += 1 - count, length -= 1 - count;
        } else {
            if (length < 2) return -1;
            out += count + 1, in += 2, length -= 2;
        }
    }
    return out;
}

// The bytes zlib data unpacks to, counted up to `limit` + 1; -1 if it is not zlib data.
int64_t zipUnpackedSize(const unsigned char* in, int64_t length, int64_t limit, std::vector<unsigned char>& buffer) {
    buffer.resize(size_t(std::min<int64_t>(limit + 1, int64_t(1) << 20)));
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return -1;
    z.next_in = const_cast<unsigned char*>(in);
    z.avail_in = uInt(length);
    int64_t out = 0;
    int status = Z_OK;
    while (status == Z_OK && out <= limit) {
        z.next_out = buffer.data();
        z.avail_out = uInt(buffer.size());
        status = inflate(&z, Z_NO_FLUSH);
        out += int64_t(buffer.size() - z.avail_out);
        if (status == Z_BUF_ERROR && z.avail_in == 0) break; // the input ended before the stream did
    }
    inflateEnd(&z);
    return status == Z_STREAM_END || status == Z_OK ? out : -1;
}

} // namespace

std::string checkExrChunks(const unsigned char* data, size_t size) {
    if (size < 8 || (data[5] & 0x10)) return ""; // multipart: each part's reader checks what it reads
    const bool tiled = data[5] & 0x02;
    size_t at = 8;
    PartHeader h;
    if (std::string error = readHeader(data, size, data[5] & 0x04 ? 256 : 32, at, h); !error.empty()) return error;
    int64_t chunks = 0;
    if (std::string error = chunksOf(h, tiled, chunks); !error.empty()) return error;
    if (h.subsampled || (tiled && (!h.haveTiles || h.levelMode != 0 || h.tileX <= 0 || h.tileY <= 0)))
        return ""; // sizes pt does not work out; OpenEXR reads them as it can
    const int64_t width = h.x1 - h.x0 + 1, height = h.y1 - h.y0 + 1;
    const int64_t lines = linesPerChunk(h.compression);
    const int64_t tilesX = tiled ? (width + h.tileX - 1) / h.tileX : 1;
    if (uint64_t(at) + uint64_t(chunks) * 8 > size) return "its OpenEXR table of chunk offsets is cut short";
    std::vector<unsigned char> buffer;
    for (int64_t k = 0; k < chunks; ++k) {
        uint64_t offset = 0;
        for (int b = 7; b >= 0; --b) offset = offset << 8 | data[at + size_t(8 * k + b)];
        // Where the chunk lies and how many bytes its pixels take unpacked.
        int64_t unpacked = 0, headerBytes = 0;
        bool placed = false;
        if (tiled) {
            const int64_t tx = k % tilesX, ty = k / tilesX;
            unpacked = std::min(h.tileX, width - tx * h.tileX) * std::min(h.tileY, height - ty * h.tileY) * h.bytesPerPixel;
            headerBytes = 20; // tile x, y, level x, y, data size
            placed = offset <= size - std::min<uint64_t>(size, 20) && int32At(data + offset) == tx &&
                     int32At(data + offset + 4) == ty && int32At(data + offset + 8) == 0 && int32At(data + offset + 12) == 0;
        } else {
            const int64_t y = h.y0 + k * lines;
            unpacked = std::min(lines, h.y1 - y + 1) * width * h.bytesPerPixel;
            headerBytes = 8; // first scanline, data size
            placed = offset <= size - std::min<uint64_t>(size, 8) && int32At(data + offset) == y;
        }
        const std::string which = "its OpenEXR chunk " + std::to_string(k) + " of " + std::to_string(chunks);
        if (!placed || offset < at + uint64_t(chunks) * 8)
            return which + " is not where its table of offsets says (the file is damaged or cut short)";
        const int64_t length = int32At(data + offset + uint64_t(headerBytes) - 4);
        if (length < 0 || uint64_t(length) > size - offset - uint64_t(headerBytes))
            return which + " runs past the end of the file (cut short?)";
        if (length > unpacked)
            return which + " holds " + std::to_string(length) + " bytes, more than the " + std::to_string(unpacked) +
                   " of the pixels its header declares";
        if (length == unpacked) continue; // stored as it is (OpenEXR does so where packing gains nothing)
        const unsigned char* packed = data + offset + headerBytes;
        int64_t got = unpacked; // compressions whose decoders check the size themselves
        if (h.compression == 0) got = length;
        else if (h.compression == 1) got = rleUnpackedSize(packed, length);
        else if (h.compression == 2 || h.compression == 3) got = zipUnpackedSize(packed, length, unpacked, buffer);
        if (got != unpacked)
            return which + " holds " + (got < 0 ? std::string("damaged data") : std::to_string(got) + " bytes of pixels") +
                   " where its header declares " + std::to_string(unpacked) + " (a data window larger than the file holds?)";
    }
    return "";
}

} // namespace pt
