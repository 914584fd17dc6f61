#include "cli/denoising.h"

#include "cli/args.h"

#include <algorithm>

namespace pt::cli {
namespace {

constexpr const char* kDenoiserAttributes[] = {kDenoiserAttribute, "pt:denoiserVersion", "pt:denoiseSeconds"};

bool isDenoiserAttribute(const ImageAttribute& a) {
    return std::any_of(std::begin(kDenoiserAttributes), std::end(kDenoiserAttributes),
                       [&](const char* n) { return a.name == n; });
}

} // namespace

std::unique_ptr<Denoiser> openDenoiser(const char* command, int threads, FILE* err, int& status) {
    try {
        std::string missing;
        std::unique_ptr<Denoiser> d = Denoiser::open(threads, missing);
        if (!d) {
            std::fprintf(err, "%s: %s\n", command, missing.c_str());
            status = 2;
        }
        return d;
    } catch (const DenoiseError& e) {
        std::fprintf(err, "%s: error: %s\n", command, e.what());
        status = 1;
        return nullptr;
    }
}

std::string denoiseImage(const Denoiser& denoiser, Image& image, std::vector<float> albedo, std::vector<float> normal,
                         const DenoiseOptions& options, DenoiseReport& report) {
    std::vector<float> color = image.rgb;
    DenoiseImages in{image.width, image.height, &color, std::move(albedo), std::move(normal)};
    try {
        report = denoiser.denoise(in, options);
    } catch (const DenoiseError& e) {
        return e.what();
    } catch (const std::bad_alloc&) {
        return "out of memory while denoising a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image";
    }
    image.layers.insert(image.layers.begin(), ImageLayer{kNoisyLayer, {"R", "G", "B"}, std::move(image.rgb)});
    image.rgb = std::move(color);
    std::erase_if(image.metadata, isDenoiserAttribute);
    image.metadata.push_back(ImageAttribute::string(kDenoiserAttribute, report.description));
    image.metadata.push_back(ImageAttribute::string("pt:denoiserVersion", denoiser.version()));
    image.metadata.push_back(ImageAttribute::floatValue("pt:denoiseSeconds", report.seconds));
    return "";
}

bool restoreRawEstimate(Image& image, std::string& error) {
    if (std::none_of(image.metadata.begin(), image.metadata.end(), isDenoiserAttribute)) return false;
    auto noisy = std::find_if(image.layers.begin(), image.layers.end(), [](const ImageLayer& l) {
        return l.name == kNoisyLayer && l.channels == std::vector<std::string>{"R", "G", "B"};
    });
    if (noisy == image.layers.end()) {
        error = "it is denoised (pt:denoiser) but holds no raw estimate (layer noisy.R, noisy.G, noisy.B)";
        return true;
    }
    image.rgb = std::move(noisy->pixels);
    image.layers.erase(noisy);
    std::erase_if(image.channelNames, [](const std::string& c) { return c.rfind(std::string(kNoisyLayer) + ".", 0) == 0; });
    std::erase_if(image.metadata, isDenoiserAttribute);
    return true;
}

DenoiseQuality parseQuality(const std::string& option, const std::string& value) {
    if (value == "high") return DenoiseQuality::High;
    if (value == "balanced") return DenoiseQuality::Balanced;
    if (value == "fast") return DenoiseQuality::Fast;
    throw UsageError("option " + option + ": expected high, balanced or fast, got \"" + value + "\"");
}

} // namespace pt::cli
