// Denoising a rendered image with Intel Open Image Denoise (OIDN), loaded at run time: pt builds
// and runs without it, and only --denoise and pt denoise need it (tools/install-oidn).
//
// The RT filter on the CPU, guided by the albedo and normal features (the film's first-hit
// layers, gathered through mirrors and smooth glass to the first surface that is not perfectly
// specular). The features are noisy too (antialiasing, glass's Fresnel choice, textures), so
// they are denoised first and the beauty then trusts them (cleanAux), as OIDN's documentation
// recommends for final frames.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt {

// A library that was found but cannot serve (not OIDN 2.x, a device that fails, an error or
// out-of-memory inside the filter), with OIDN's own message where it gave one.
class DenoiseError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// OIDN's quality modes: high (full precision), balanced (lower precision where the CPU has it:
// bfloat16 on AVX-512 BF16), fast (a smaller network for the beauty).
enum class DenoiseQuality { High, Balanced, Fast };
const char* qualityName(DenoiseQuality q); // "high", "balanced", "fast"

struct DenoiseOptions {
    DenoiseQuality quality = DenoiseQuality::High;
    // Denoise the albedo and normal before the beauty, which then trusts them (cleanAux);
    // off, the beauty filter is given the noisy features as they are.
    bool prefilter = true;
};

// An image to denoise: interleaved RGB floats, width x height each. The color is denoised in
// place; albedo (in [0, 1]) and normal (in [-1, 1], 0 where nothing was hit) guide it.
struct DenoiseImages {
    int width = 0, height = 0;
    std::vector<float>* color = nullptr;
    std::vector<float> albedo, normal;
};

struct DenoiseReport {
    double seconds = 0.0;     // the filters, their set-up included
    size_t replaced = 0;      // colour values that were NaN, infinite or negative, given 0
    std::string description;  // for the metadata: "OIDN 2.5.1 RT, quality high, prefiltered albedo and normal"
};

class Denoiser {
public:
    // Loads OIDN 2.x and opens its CPU device with `threads` threads. Where no library is found,
    // returns null and says in `missing` what was looked for and how to install it; a library
    // that is found but unusable throws DenoiseError. Search order: the file PT_OIDN_LIBRARY
    // names; .deps/oidn-2.5.1/lib of the checkout pt was built from (tools/install-oidn);
    // libOpenImageDenoise.so.2 on the system's library path.
    static std::unique_ptr<Denoiser> open(int threads, std::string& missing);
    ~Denoiser();
    Denoiser(const Denoiser&) = delete;
    Denoiser& operator=(const Denoiser&) = delete;

    const std::string& version() const { return version_; } // "2.5.1"
    const std::string& libraryPath() const { return path_; }

    // Denoises the colour guided by the albedo and normal (prefiltered first if asked); throws
    // DenoiseError with OIDN's message on failure (the colour is then left as it was).
    DenoiseReport denoise(DenoiseImages& images, const DenoiseOptions& options) const;

private:
    struct Api;
    Denoiser() = default;
    std::unique_ptr<Api> api_;
    void* device_ = nullptr;
    std::string version_, path_;
};

} // namespace pt
