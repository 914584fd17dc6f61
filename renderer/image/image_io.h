// Writing and reading rendered images through OpenImageIO. The format follows the extension:
// .exr is linear float RGB plus any extra layers and metadata; .png is sRGB-encoded 8-bit RGB.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pt {

class OutputFile;

struct ImageLayer {
    std::string name;       // channel prefix: "variance" gives variance.R, variance.G, ...; "" the
                            // channels named alone beside R, G, B (A, Z), written as they were
    std::vector<std::string> channels; // e.g. {"R","G","B"} or {"Z"}
    std::vector<float> pixels;          // interleaved, channels.size() values per pixel
};

// One metadata attribute, written with its type (EXR keeps ints, floats and strings apart).
struct ImageAttribute {
    // Other: any other type a file holds (a v2f, a matrix), kept as its OpenImageIO type name
    // and bytes, so that it is written back as it was read.
    enum class Type { String, Int, Float, Other };
    std::string name;
    Type type = Type::String;
    std::string text;  // String; Other: the type's name ("float2", "matrix")
    long long integer = 0;
    double number = 0.0;
    std::vector<unsigned char> bytes; // Other

    static ImageAttribute string(std::string n, std::string v) { return {std::move(n), Type::String, std::move(v)}; }
    static ImageAttribute integerValue(std::string n, long long v) { return {std::move(n), Type::Int, {}, v}; }
    static ImageAttribute floatValue(std::string n, double v) { return {std::move(n), Type::Float, {}, 0, v}; }
    std::string asText() const; // the value, whatever its type, for messages and lookups
};

struct Image {
    int width = 0, height = 0;
    // Where these pixels lie in a larger image (an EXR's data window inside its display window,
    // as pbrt and Nuke write crops): origin (x, y) in a fullWidth x fullHeight image. 0: none.
    int x = 0, y = 0, fullWidth = 0, fullHeight = 0;
    std::vector<float> rgb; // interleaved linear RGB, row 0 at the top
    std::vector<ImageLayer> layers;
    std::vector<ImageAttribute> metadata;
    std::vector<std::string> channelNames; // as read from a file, in its order (readImage only)
    // What rgb holds of a file read (readImage): its R, G and B channels; its one grey channel
    // (Y, or a file's only channel) in all three; or nothing (zeros), the file having no R, G, B
    // or only some of them (missingRgb() says which).
    enum class Beauty { Rgb, Grey, Missing };
    Beauty beauty = Beauty::Rgb;
    int parts = 1;                         // subimages in the file read (multipart EXR)
};

enum class ImageFormat { Exr, Png, Unknown };
ImageFormat formatFromPath(const std::string& path);

// Checks before rendering that `path` can be written: a known extension, and a folder that
// exists and is writable (io/output_file.h). Returns an empty string or the reason it cannot.
std::string checkOutputPath(const std::string& path);

// Encodes the image and writes it through an OutputFile (io/output_file.h): a failed write never
// leaves a truncated file or replaces a good one. Returns an empty string or the error.
std::string writeImage(const std::string& path, const Image& image);
// Same, into an OutputFile opened earlier (before rendering), in the format of its path.
std::string writeImage(OutputFile& file, const Image& image);

// Reads an image (any format OpenImageIO knows) into `image`: R, G, B into rgb (a grey image's
// channel into all three; image.beauty says which) and the other channels grouped into layers by
// their "prefix." name, those named alone (A, Z) into the layer ""; of a multipart EXR, the first
// part. Refuses what is not a regular file (a FIFO or /dev/zero would block or never end) and an
// image whose header declares more pixels than half this machine's memory holds, before reading
// them. Returns "" or the error.
std::string readImage(const std::string& path, Image& image);
// Where a file read has no RGB beauty (Image::Beauty::Missing), what it lacks, for a message:
// "no R, G or B channel (its channels: albedo.R, albedo.G, ...)", "R and G but no B (...)".
std::string missingRgb(const Image& image);
// The same for an image file held in memory, which `name` stands for, with the bytes its pixels
// may take (the part fuzzer's entry, with a fuzzer's memory).
std::string readImageFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, Image& image,
                                double budgetBytes);

} // namespace pt
