// A plausibility check of an OpenEXR file's header, before OpenEXR reads it. OpenEXR allocates
// the table of chunk offsets (8 bytes for each block of scanlines or tile) from the data window
// the header declares, before it reads any of it: a 200-byte file whose window is 2^31 lines
// high made pt merge take 2 GB of memory, and more would be a bare "out of memory". The table
// lies in the file, so a file shorter than its own table is refused here, and so is a header
// whose sides or chunks are larger than any image pt reads. Every attribute of every header (of
// each part, for a multipart file) must fill exactly the size it declares: OpenEXR reads many
// types by their contents, so a value that disagrees sends it elsewhere in the header, where a
// size of 1.4 GB was allocated from a 2 KB file (found by the part fuzzer). Deep images (several
// samples a pixel) are refused by name: pt reads flat ones.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pt {

// `head`: the file's first bytes (at least the whole header, or all of a smaller file), `size`
// their number, `fileSize` the whole file's. Returns "" or what is wrong.
std::string checkExrHeader(const unsigned char* head, size_t size, uint64_t fileSize);

// After OpenEXR has read a file's pixels: whether every chunk of the first part holds the pixels
// its header declares. OpenEXR's own reader takes a chunk that holds fewer (a data window
// widened in the header, a file patched or cut short) and gives the missing pixels as zeros
// without a word, for uncompressed, RLE and ZIP chunks. Each chunk's offset, its place in the
// image and its size are checked, and RLE and ZIP data are unpacked to count what they hold;
// the other compressions' decoders report a short chunk themselves. `data`: the whole file.
// Returns "" or what is wrong.
std::string checkExrChunks(const unsigned char* data, size_t size);

// How many first bytes checkExrHeader needs at most: a longer header is refused.
inline constexpr size_t kMaxExrHeaderBytes = size_t(1) << 20;
// The largest side, and the largest chunk (a block of scanlines or a tile, uncompressed), that
// pt reads: OpenEXR allocates a chunk's buffers from the header before reading its data.
inline constexpr int64_t kMaxExrSide = int64_t(1) << 18;
inline constexpr int64_t kMaxExrChunkBytes = int64_t(1) << 30;

} // namespace pt
