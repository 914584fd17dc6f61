#include "environment/environment_map.h"

#include "image/image_input.h"
#include "io/input_file.h"

#include "core/system.h"
#include "io/load_error.h"
#include "io/scene_limits.h"
#include "texture/texture_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pt {

Vec2 EnvironmentMap::directionToUv(const Vec3& d) {
    float u = 0.5f + std::atan2(d.z, d.x) * (0.5f / kPi);
    float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) * (1.0f / kPi);
    return Vec2(u - std::floor(u), v);
}

Vec3 EnvironmentMap::uvToDirection(Vec2 uv) {
    float phi = 2.0f * kPi * (uv.x - 0.5f), theta = kPi * uv.y;
    float sinTheta = std::sin(theta);
    return Vec3(sinTheta * std::cos(phi), std::cos(theta), sinTheta * std::sin(phi));
}

// Rotation by `rotation` about +y, right-handed (+x turns towards -z).
Vec3 EnvironmentMap::toWorld(const Vec3& d) const {
    return Vec3(cos_ * d.x + sin_ * d.z, d.y, -sin_ * d.x + cos_ * d.z);
}
Vec3 EnvironmentMap::toMap(const Vec3& d) const {
    return Vec3(cos_ * d.x - sin_ * d.z, d.y, sin_ * d.x + cos_ * d.z);
}

Spectrum EnvironmentMap::lookup(Vec2 uv) const {
    // Texel centres sit at (i + 0.5) / size.
    float x = uv.x * float(width) - 0.5f, y = uv.y * float(height) - 0.5f;
    float fx = std::floor(x), fy = std::floor(y);
    float tx = x - fx, ty = y - fy;
    int x0 = int(fx), y0 = int(fy);
    // uv in [0, 1] puts the columns in [-1, width]: wrapped by compares there, sparing the
    // escaping path two integer divisions per column.
    auto wrapX = [&](int i) {
        if (i >= 0 && i < width) return i;
        if (i == -1) return width - 1;
        if (i == width) return 0;
        return ((i % width) + width) % width;
    };
    auto clampY = [&](int j) { return std::clamp(j, 0, height - 1); };
    int xa = wrapX(x0), xb = wrapX(x0 + 1), ya = clampY(y0), yb = clampY(y0 + 1);
    return (1.0f - ty) * ((1.0f - tx) * texel(xa, ya) + tx * texel(xb, ya)) +
           ty * ((1.0f - tx) * texel(xa, yb) + tx * texel(xb, yb));
}

EnvironmentMap readEnvironmentMap(const std::string& path, float rotationDegrees, float scale, std::string& warning) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        std::string problem = pathProblem(path);
        throw LoadError("environment map \"" + path + "\" " + (problem.empty() ? "is not a regular file" : problem));
    }
    WholeImageFile file;
    bool tooLarge;
    if (std::string error = openImageWhole(path, uint64_t(textureMemoryBudget()), file, tooLarge); !error.empty())
        throw LoadError("cannot read environment map \"" + path + "\": " + error);
    OIIO::ImageInput* in = file.input.get();
    const OIIO::ImageSpec spec = in->spec();
    int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0)
        throw LoadError("environment map \"" + path + "\" has an unusable size " + std::to_string(w) + "x" + std::to_string(h));
    auto type = spec.format.basetype;
    if (type != OIIO::TypeDesc::FLOAT && type != OIIO::TypeDesc::HALF && type != OIIO::TypeDesc::DOUBLE)
        throw LoadError("environment map \"" + path + "\" holds " + spec.format.c_str() +
                        " values; expected float or half radiance (EXR, Radiance HDR, float TIFF)");
    double bytes = double(w) * double(h) * sizeof(float) * (nc >= 3 ? 3 : 1);
    if (bytes > textureMemoryBudget())
        throw LoadError("environment map \"" + path + "\" is too large: " + std::to_string(w) + "x" + std::to_string(h));

    EnvironmentMap map;
    map.path = path;
    map.sourceHash = contentHash(file.bytes.data(), file.bytes.size());
    map.width = w;
    map.height = h;
    map.setRotation(rotationDegrees * (kPi / 180.0f));
    map.scale = scale;
    int read = nc >= 3 ? 3 : 1;
    std::vector<float> values(size_t(w) * size_t(h) * size_t(read));
    if (std::string error = readPixels(*in, read, OIIO::TypeDesc::FLOAT, values.data()); !error.empty())
        throw LoadError("cannot read environment map \"" + path + "\": " + error);
    for (size_t i = 0; i < values.size(); ++i) {
        float v = values[i];
        if (!std::isfinite(v) || v < 0.0f) {
            size_t pixel = i / size_t(read);
            char what[160];
            std::snprintf(what, sizeof what, "pixel (%zu, %zu) channel %zu is %g; radiance must be finite and not negative",
                          pixel % size_t(w), pixel / size_t(w), i % size_t(read), double(v));
            throw LoadError("environment map \"" + path + "\": " + what);
        }
    }
    // Scaled, the brightest texel must stay a radiance whose samples fit in float, as emitters do.
    double peak = values.empty() ? 0.0 : double(*std::max_element(values.begin(), values.end())) * scale;
    if (!(peak <= kMaxRadiance))
        throw LoadError("environment map \"" + path + "\": its brightest texel, times its scale " + shortNumber(scale) +
                        ", is a radiance of " + shortNumber(peak) + ", beyond the 1e18 whose samples fit in float");
    if (read == 3) {
        map.rgb = std::move(values);
    } else {
        map.rgb.resize(values.size() * 3);
        for (size_t i = 0; i < values.size(); ++i) map.rgb[3 * i] = map.rgb[3 * i + 1] = map.rgb[3 * i + 2] = values[i];
    }
    if (w != 2 * h)
        warning = "environment map \"" + path + "\" is " + std::to_string(w) + "x" + std::to_string(h) +
                  ", not twice as wide as high; it is stretched over the sphere";
    return map;
}

} // namespace pt
