// Writing and reading rendered images through OpenImageIO. The format follows the extension:
// .exr is linear float RGB plus any extra layers and metadata; .png is sRGB-encoded 8-bit RGB.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pt {

struct ImageLayer {
    std::string name;       // channel prefix: "variance" gives variance.R, variance.G, ...
    std::vector<std::string> channels; // e.g. {"R","G","B"} or {"Z"}
    std::vector<float> pixels;          // interleaved, channels.size() values per pixel
};

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb; // interleaved linear RGB, row 0 at the top
    std::vector<ImageLayer> layers;
    std::vector<std::pair<std::string, std::string>> metadata; // written as string attributes
};

enum class ImageFormat { Exr, Png, Unknown };
ImageFormat formatFromPath(const std::string& path);

// Checks before rendering that `path` can be written: a known extension and a folder that
// exists and is writable. Returns an empty string or the reason it cannot.
std::string checkOutputPath(const std::string& path);

// Writes to a temporary file beside `path` and renames it into place, so a failed write never
// leaves a truncated file or replaces a good one. Returns an empty string or the error.
std::string writeImage(const std::string& path, const Image& image);

// Reads an image (any format OpenImageIO knows) into `image`: R, G, B into rgb (grey replicated)
// and other channels grouped into layers by their "prefix." name. Returns "" or the error.
std::string readImage(const std::string& path, Image& image);

} // namespace pt
