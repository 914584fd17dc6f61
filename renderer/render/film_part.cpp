#include "render/film_part.h"

#include "core/system.h"
#include "render/film_image.h"

#include <charconv>
#include <cmath>

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
    kHits{"ptHits", {"N"}}, kConverged{"ptConverged", {"N"}};

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

const ImageLayer* find(const Image& image, const std::string& name, size_t channels, size_t pixels) {
    for (const ImageLayer& l : image.layers)
        if (l.name == name && l.channels.size() == channels && l.pixels.size() == pixels * channels) return &l;
    return nullptr;
}

const ImageAttribute* attribute(const Image& image, const std::string& name) {
    for (const ImageAttribute& a : image.metadata)
        if (a.name == name) return &a;
    return nullptr;
}

// An integer field in [lo, hi]: an int attribute, or text of digits alone (a part may come from
// a tool that wrote it as a string). "" or what is wrong with it.
std::string integerField(const Image& image, const std::string& field, long long lo, long long hi, long long& value) {
    const ImageAttribute* a = attribute(image, field);
    if (!a) return field + " is missing";
    bool ok = false;
    if (a->type == ImageAttribute::Type::Int) {
        value = a->integer, ok = true;
    } else if (a->type == ImageAttribute::Type::String) {
        const std::string& t = a->text;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        ok = ec == std::errc() && end == t.data() + t.size() && !t.empty();
    }
    if (ok && value >= lo && value <= hi) return "";
    return field + " is " + (a->type == ImageAttribute::Type::String ? "\"" + a->text.substr(0, 40) + "\"" : a->asText()) +
           "; expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

// A number field in [lo, hi], 0 where it is absent. "" or what is wrong with it.
std::string numberField(const Image& image, const std::string& field, double lo, double hi, double& value) {
    value = 0.0;
    const ImageAttribute* a = attribute(image, field);
    if (!a) return "";
    value = a->type == ImageAttribute::Type::Float ? a->number : a->type == ImageAttribute::Type::Int ? double(a->integer) : NAN;
    if (a->type == ImageAttribute::Type::String) {
        const std::string& t = a->text;
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec != std::errc() || end != t.data() + t.size()) value = NAN;
    }
    if (value >= lo && value <= hi) return "";
    return field + " is " + a->asText().substr(0, 40) + "; expected a number in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]";
}

// The longest text a part's attribute may hold: its fields are names, paths and numbers.
constexpr size_t kMaxAttributeBytes = 65536;

} // namespace

void addPartLayers(Image& image, const Film& film) {
    size_t n = size_t(film.width()) * film.height();
    ImageLayer count{kCount.name, kCount.channels, std::vector<float>(n)};
    for (size_t p = 0; p < n; ++p) count.pixels[p] = float(film.count(p)); // exact: spp <= 2^24
    image.layers.push_back(std::move(count));
    addSplit(image, kSum, n, [&](size_t p, size_t c) { return film.sum(p)[int(c)]; });
    addSplit(image, kSumSq, n, [&](size_t p, size_t c) { return film.sumSq(p)[int(c)]; });
    if (film.hasConvergence()) { // adaptive sampling's state, for --resume
        ImageLayer converged{kConverged.name, kConverged.channels, std::vector<float>(n)};
        for (size_t p = 0; p < n; ++p) converged.pixels[p] = film.converged(p) ? 1.0f : 0.0f;
        image.layers.push_back(std::move(converged));
        image.metadata.push_back(ImageAttribute::integerValue("pt:decidedAt", film.decidedAt));
    }
    if (!film.hasFirstHitLayers()) return;
    addSplit(image, kAlbedo, n, [&](size_t p, size_t c) { return film.albedoSum(p)[int(c)]; });
    addSplit(image, kNormal, n, [&](size_t p, size_t c) { return film.normalSum(p)[int(c)]; });
    addSplit(image, kDepth, n, [&](size_t p, size_t) { return film.depthSum(p); });
    ImageLayer hits{kHits.name, kHits.channels, std::vector<float>(n)};
    for (size_t p = 0; p < n; ++p) hits.pixels[p] = float(film.hits(p));
    image.layers.push_back(std::move(hits));
}

std::string partFromImage(const Image& image, const std::string& name, Film& film, PartInfo& info) {
    auto fail = [&](const std::string& what) { return name + ": " + what; };
    if (!attribute(image, "pt:part"))
        return fail("it is not a part of a split render (pt render writes parts with --samples or --crop, and "
                    ".partial.exr files when interrupted)");
    for (const ImageAttribute& a : image.metadata)
        if (a.text.size() > kMaxAttributeBytes)
            return fail("its attribute " + a.name.substr(0, 40) + " holds " + std::to_string(a.text.size()) +
                        " bytes; a part's fields are at most 65536");

    // The fields, each in its range, then against each other.
    long long spp, first, last, width, height;
    std::string error = integerField(image, "pt:sppRequested", 1, 1 << 24, spp);
    if (error.empty()) error = integerField(image, "pt:samplesFirst", 0, spp - 1, first);
    if (error.empty()) error = integerField(image, "pt:samplesLast", first + 1, spp, last);
    if (error.empty()) error = integerField(image, "pt:fullWidth", 1, 65536, width);
    if (error.empty()) error = integerField(image, "pt:fullHeight", 1, 65536, height);
    if (error.empty()) error = numberField(image, "pt:exposure", -kMaxExposure, kMaxExposure, info.exposure);
    if (error.empty()) error = numberField(image, "pt:renderSeconds", 0.0, 1e12, info.seconds);
    if (!error.empty()) return fail(error);
    info.spp = uint32_t(spp), info.first = uint32_t(first), info.last = uint32_t(last);
    info.fullWidth = int(width), info.fullHeight = int(height);
    // What the merge allocates for the full image: count, sums and the first-hit layers.
    double bytes = double(width) * double(height) * (sizeof(uint32_t) * 2 + sizeof(double) * 13);
    if (bytes > 0.5 * physicalMemoryBytes())
        return fail("pt:fullWidth x pt:fullHeight, " + std::to_string(width) + "x" + std::to_string(height) + ", would take " +
                    shortNumber(bytes / 1e9) + " GB to merge, more than half this machine's memory");
    bool windowed = image.fullWidth > 0;
    if (windowed && (image.fullWidth != width || image.fullHeight != height))
        return fail("its EXR display window is " + std::to_string(image.fullWidth) + "x" + std::to_string(image.fullHeight) +
                    ", not its pt:fullWidth x pt:fullHeight " + std::to_string(width) + "x" + std::to_string(height));
    info.x0 = windowed ? image.x : 0, info.y0 = windowed ? image.y : 0;
    info.x1 = info.x0 + image.width, info.y1 = info.y0 + image.height;
    if (info.x0 < 0 || info.y0 < 0 || info.x1 > width || info.y1 > height || image.width <= 0 || image.height <= 0)
        return fail("its pixels [" + std::to_string(info.x0) + ", " + std::to_string(info.x1) + ") x [" +
                    std::to_string(info.y0) + ", " + std::to_string(info.y1) + ") pass its " + std::to_string(width) + "x" +
                    std::to_string(height) + " image");

    size_t n = size_t(image.width) * image.height;
    auto both = [&](const PartLayer& l, const ImageLayer*& hi, const ImageLayer*& lo) {
        hi = find(image, l.name, l.channels.size(), n);
        lo = find(image, std::string(l.name) + "Lo", l.channels.size(), n);
        return hi && lo;
    };
    const ImageLayer *count = find(image, kCount.name, 1, n), *sum, *sumLo, *sq, *sqLo;
    if (!count || !both(kSum, sum, sumLo) || !both(kSumSq, sq, sqLo))
        return fail("it is not a part of a split render (it has no ptCount, ptSum and ptSumSq layers; pt render writes "
                    "them with --samples, --crop or when interrupted)");
    const ImageLayer *albedo, *albedoLo, *normal, *normalLo, *depth, *depthLo, *hits = find(image, kHits.name, 1, n);
    bool layers = both(kAlbedo, albedo, albedoLo) && both(kNormal, normal, normalLo) && both(kDepth, depth, depthLo) && hits;
    film = Film(image.width, image.height);
    if (layers) film.enableFirstHitLayers();
    const ImageLayer* converged = find(image, kConverged.name, 1, n);
    long long decidedAt = 0;
    if (converged) {
        if (error = integerField(image, "pt:decidedAt", 0, last - first, decidedAt); !error.empty()) return fail(error);
        film.enableConvergence();
        film.decidedAt = uint32_t(decidedAt);
    }

    // Each pixel's sums must be those of its count of samples: radiance is never negative, a
    // pixel without samples has nothing, and the sum of squares is at least the square of the sum
    // over the count (with room for the float pairs' rounding).
    auto value = [](const ImageLayer* hi, const ImageLayer* lo, size_t i) { return double(hi->pixels[i]) + double(lo->pixels[i]); };
    const double range = double(last - first);
    for (size_t p = 0; p < n; ++p) {
        auto pixel = [&] { // for a message: only made when one is needed
            return "pixel (" + std::to_string(info.x0 + int(p % size_t(image.width))) + ", " +
                   std::to_string(info.y0 + int(p / size_t(image.width))) + ")";
        };
        double c = count->pixels[p];
        if (!(c >= 0.0 && c <= range && c == std::floor(c)))
            return fail(pixel() + " holds " + shortNumber(c) + " samples; its range " + std::to_string(first) + ":" +
                        std::to_string(last) + " has " + shortNumber(range));
        glm::dvec3 s, q;
        for (int k = 0; k < 3; ++k) s[k] = value(sum, sumLo, 3 * p + k), q[k] = value(sq, sqLo, 3 * p + k);
        for (int k = 0; k < 3; ++k)
            if (!(std::isfinite(s[k]) && std::isfinite(q[k]) && s[k] >= 0.0 && q[k] >= 0.0 &&
                  (c > 0.0 || (s[k] == 0.0 && q[k] == 0.0)) && s[k] * s[k] <= c * q[k] * (1.0 + 1e-6) + 1e-300))
                return fail(pixel() + ": its sums (" + shortNumber(s[k]) + ", of squares " + shortNumber(q[k]) +
                            ") cannot be those of " + shortNumber(c) + " samples of radiance");
        film.add(p, s, q, uint32_t(c));
        if (converged) {
            float v = converged->pixels[p];
            if (!(v == 0.0f || (v == 1.0f && c <= double(decidedAt))))
                return fail(pixel() + ": its ptConverged is " + shortNumber(v) + "; expected 0, or 1 for a pixel of at most "
                            "pt:decidedAt (" + std::to_string(decidedAt) + ") samples");
            if (v == 1.0f) film.setConverged(p);
        }
        if (!layers) continue;
        glm::dvec3 a, nm;
        for (int k = 0; k < 3; ++k) a[k] = value(albedo, albedoLo, 3 * p + k), nm[k] = value(normal, normalLo, 3 * p + k);
        double h = hits->pixels[p], d = value(depth, depthLo, p);
        bool sound = h >= 0.0 && h <= c && h == std::floor(h) && d >= 0.0 && std::isfinite(d) && isFinite(Vec3(a)) &&
                     a.x >= 0.0 && a.y >= 0.0 && a.z >= 0.0 && glm::length(nm) <= h * (1.0 + 1e-6);
        if (!sound)
            return fail(pixel() + ": its first-hit sums (albedo, normal, depth, hits) cannot be those of " + shortNumber(c) +
                        " samples");
        film.addFirstHit(p, a, nm, d, uint32_t(h));
    }
    return "";
}

std::string readPart(const std::string& path, Image& image, Film& film, PartInfo& info) {
    std::string error = readImage(path, image);
    return error.empty() ? partFromImage(image, path, film, info) : error;
}

} // namespace pt
