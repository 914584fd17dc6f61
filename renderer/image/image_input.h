// Opening an image file for reading with the one OpenImageIO plugin its first bytes name. Its own
// ImageInput::open tries the plugin of the extension and then every other in turn, and a file that
// none recognises is read in tiny steps by several of them: 13 seconds for 100 MB of zeros, and
// minutes for the sparse file of gigabytes a glTF URI may name. So the format is decided here from
// the file's magic number (or, for TGA, which has none, its extension), and anything else is
// refused at once.
#pragma once

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

namespace pt {

// How many scanlines OpenImageIO reads at a time in read_image: its own default of 256 makes a
// buffer of 256 rows whatever the image's height (2.3 GB for a 4-row image 65528 wide with 34
// channels). pt asks for 16, which it rounds up to 64.
inline constexpr int kImageReadChunk = 64;

// OpenImageIO's reader of an image in memory, with its offsets checked: its own takes any seek,
// and OpenEXR seeks to the offsets a file's chunk table gives, so a table holding -1 read the
// byte before the buffer (the part fuzzer found it).
class MemoryImageReader final : public OIIO::Filesystem::IOMemReader {
public:
    MemoryImageReader(const std::vector<unsigned char>& bytes) : IOMemReader(bytes.data(), bytes.size()) {}
    bool seek(int64_t offset) override;
    size_t read(void* buf, size_t size) override;
    size_t pread(void* buf, size_t size, int64_t offset) override;
};

// The OpenImageIO format name ("png", "openexr", ...) for a file starting with `head` and named
// `name`; "" when pt does not read it.
std::string imageFormatOf(const unsigned char* head, size_t size, const std::string& name);

// The format of the file at `path` from its first bytes (see imageFormatOf), read alone: a file
// of gigabytes is judged before any more of it is read.
std::string imageFormatOfFile(const std::string& path);

// The message for a file whose format imageFormatOf does not know.
std::string unknownImageFormat();

// Opens the regular file `path`. Null with `error` set ("not an image file pt reads ...", or the
// plugin's message) when it cannot.
std::unique_ptr<OIIO::ImageInput> openImageFile(const std::string& path, std::string& error);

// An image file read whole and opened from memory: the bytes are exactly what is decoded, so
// their hash (io/input_file.h) names the content a render used, even if the file is replaced
// while pt loads.
struct WholeImageFile {
    std::vector<unsigned char> bytes;
    std::unique_ptr<MemoryImageReader> reader; // over `bytes`, for `input`
    std::unique_ptr<OIIO::ImageInput> input;
};

// Reads the regular file `path`, of at most `maxBytes`, and opens it; its format is judged from
// its first bytes before its size or the rest (it may be gigabytes of zeros). "" or why not;
// `tooLarge` says when the size was the reason.
std::string openImageWhole(const std::string& path, uint64_t maxBytes, WholeImageFile& file, bool& tooLarge);

// Opens an image held in memory (`reader` over its bytes, which must outlive the input); `name`
// stands for it in messages and supplies the extension where the bytes name no format.
std::unique_ptr<OIIO::ImageInput> openImageMemory(const std::vector<unsigned char>& bytes,
                                                  MemoryImageReader& reader, const std::string& name,
                                                  std::string& error);

// Reads channels [0, channels) of every pixel of the current subimage into `data`, as `type`.
// OpenImageIO's JPEG and TIFF readers report a file that is cut short or damaged only by an error
// message beside a read that succeeds (the missing part decoded as flat grey): that is a failure
// here too. "" or the decoder's message.
std::string readPixels(OIIO::ImageInput& in, int channels, OIIO::TypeDesc type, void* data);

} // namespace pt
