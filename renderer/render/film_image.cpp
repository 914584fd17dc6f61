#include "render/film_image.h"

#include "render/render_job.h"

#include <cmath>
#include <limits>

#include <algorithm>

namespace pt {
namespace {

// A double as two floats whose sum is it, to about 2^-48 relative.
void split(double v, float& hi, float& lo) {
    hi = float(v);
    lo = float(v - double(hi));
}

struct PartLayer {
    const char* name;
    std::vector<std::string> channels;
};
const PartLayer kSum{"ptSum", {"R", "G", "B"}}, kSumSq{"ptSumSq", {"R", "G", "B"}}, kCount{"ptCount", {"N"}},
    kAlbedo{"ptAlbedo", {"R", "G", "B"}}, kNormal{"ptNormal", {"X", "Y", "Z"}}, kDepth{"ptDepth", {"Z"}},
    kHits{"ptHits", {"N"}};

// Adds layer NAME and NAMELo holding value(pixel, channel) split in two.
template <typename Get>
void addSplit(Image& image, const PartLayer& layer, size_t n, Get value) {
    size_t nc = layer.channels.size();
    ImageLayer hi{layer.name, layer.channels, std::vector<float>(n * nc)};
    ImageLayer lo{std::string(layer.name) + "Lo", layer.channels, std::vector<float>(n * nc)};
    for (size_t p = 0; p < n; ++p)
        for (size_t c = 0; c < nc; ++c) split(value(p, c), hi.pixels[p * nc + c], lo.pixels[p * nc + c]);
    image.layers.push_back(std::move(hi));
    image.layers.push_back(std::move(lo));
}

const ImageLayer* find(const Image& image, const std::string& name, size_t channels) {
    for (const ImageLayer& l : image.layers)
        if (l.name == name && l.channels.size() == channels) return &l;
    return nullptr;
}

} // namespace

Image filmImage(const Film& film, const AovSelection& aovs, double exposure, size_t& overflowed) {
    Image image;
    image.width = film.width();
    image.height = film.height();
    image.rgb = film.mean();
    overflowed = 0;
    auto scale = [&](std::vector<float>& values, double gain) {
        for (float& v : values) {
            double x = double(v) * gain;
            if (!(std::abs(x) <= double(std::numeric_limits<float>::max()))) {
                ++overflowed;
                x = std::copysign(double(std::numeric_limits<float>::max()), x);
            }
            v = float(x);
        }
    };
    if (exposure != 0.0) scale(image.rgb, std::exp2(exposure));
    if (aovs.variance) {
        image.layers.push_back({"variance", {"R", "G", "B"}, film.varianceOfMean()});
        scale(image.layers.back().pixels, std::exp2(2.0 * exposure)); // a mean's variance scales by the square
    }
    if (aovs.albedo) image.layers.push_back({"albedo", {"R", "G", "B"}, film.albedo()});
    if (aovs.normal) image.layers.push_back({"normal", {"X", "Y", "Z"}, film.normal()});
    if (aovs.depth) image.layers.push_back({"depth", {"Z"}, film.depth()});
    return image;
}

void addPartLayers(Image& image, const Film& film) {
    size_t n = size_t(film.width()) * film.height();
    ImageLayer count{kCount.name, kCount.channels, std::vector<float>(n)};
    for (size_t p = 0; p < n; ++p) count.pixels[p] = float(film.count(p)); // exact: spp <= 2^24
    image.layers.push_back(std::move(count));
    addSplit(image, kSum, n, [&](size_t p, size_t c) { return film.sum(p)[int(c)]; });
    addSplit(image, kSumSq, n, [&](size_t p, size_t c) { return film.sumSq(p)[int(c)]; });
    if (!film.hasFirstHitLayers()) return;
    addSplit(image, kAlbedo, n, [&](size_t p, size_t c) { return film.albedoSum(p)[int(c)]; });
    addSplit(image, kNormal, n, [&](size_t p, size_t c) { return film.normalSum(p)[int(c)]; });
    addSplit(image, kDepth, n, [&](size_t p, size_t) { return film.depthSum(p); });
    ImageLayer hits{kHits.name, kHits.channels, std::vector<float>(n)};
    for (size_t p = 0; p < n; ++p) hits.pixels[p] = float(film.hits(p));
    image.layers.push_back(std::move(hits));
}

std::string filmFromPart(const Image& image, Film& film) {
    size_t n = size_t(image.width) * image.height;
    auto both = [&](const PartLayer& l, const ImageLayer*& hi, const ImageLayer*& lo) {
        hi = find(image, l.name, l.channels.size());
        lo = find(image, std::string(l.name) + "Lo", l.channels.size());
        return hi && lo;
    };
    const ImageLayer *count = find(image, kCount.name, 1), *sum, *sumLo, *sq, *sqLo;
    if (!count || !both(kSum, sum, sumLo) || !both(kSumSq, sq, sqLo))
        return "it is not a part of a split render (it has no ptCount, ptSum and ptSumSq layers; pt render writes them "
               "with --samples, --crop or when interrupted)";
    film = Film(image.width, image.height);
    const ImageLayer *albedo, *albedoLo, *normal, *normalLo, *depth, *depthLo, *hits = find(image, kHits.name, 1);
    bool layers = both(kAlbedo, albedo, albedoLo) && both(kNormal, normal, normalLo) && both(kDepth, depth, depthLo) && hits;
    if (layers) film.enableFirstHitLayers();
    auto value = [](const ImageLayer* hi, const ImageLayer* lo, size_t i) { return double(hi->pixels[i]) + double(lo->pixels[i]); };
    for (size_t p = 0; p < n; ++p) {
        float c = count->pixels[p];
        if (!(c >= 0.0f && c <= float(1 << 24) && c == std::floor(c))) return "pixel " + std::to_string(p) + " has a bad sample count";
        glm::dvec3 s, q;
        for (int k = 0; k < 3; ++k) s[k] = value(sum, sumLo, 3 * p + k), q[k] = value(sq, sqLo, 3 * p + k);
        if (!std::isfinite(s.x + s.y + s.z + q.x + q.y + q.z)) return "pixel " + std::to_string(p) + " has a sum that is not finite";
        film.add(p, s, q, uint32_t(c));
        if (!layers) continue;
        glm::dvec3 a, nm;
        for (int k = 0; k < 3; ++k) a[k] = value(albedo, albedoLo, 3 * p + k), nm[k] = value(normal, normalLo, 3 * p + k);
        film.addFirstHit(p, a, nm, value(depth, depthLo, p), uint32_t(hits->pixels[p]));
    }
    return "";
}

std::string readPart(const std::string& path, Image& image, Film& film) {
    std::string error = readImage(path, image);
    if (!error.empty()) return error;
    if (attributeText(image, "pt:part").empty())
        return path + ": it is not a part of a split render (pt render writes parts with --samples or --crop, and "
                      ".partial.exr files when interrupted)";
    error = filmFromPart(image, film);
    return error.empty() ? "" : path + ": " + error;
}

} // namespace pt
