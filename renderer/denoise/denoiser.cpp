#include "denoise/denoiser.h"

#include "denoise/oidn_api.h"
#include "denoise/shared_library.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#ifndef PT_OIDN_DEFAULT_DIR
#define PT_OIDN_DEFAULT_DIR ""
#endif

namespace pt {

const char* qualityName(DenoiseQuality q) {
    return q == DenoiseQuality::High ? "high" : q == DenoiseQuality::Balanced ? "balanced" : "fast";
}

// The functions pt calls, looked up by name in the loaded library.
struct Denoiser::Api {
    oidn::NewDeviceFn newDevice;
    oidn::ReleaseDeviceFn releaseDevice;
    oidn::SetDeviceIntFn setDeviceInt;
    oidn::SetDeviceBoolFn setDeviceBool;
    oidn::GetDeviceIntFn getDeviceInt;
    oidn::CommitDeviceFn commitDevice;
    oidn::GetDeviceErrorFn getDeviceError;
    oidn::NewFilterFn newFilter;
    oidn::ReleaseFilterFn releaseFilter;
    oidn::SetSharedFilterImageFn setSharedFilterImage;
    oidn::SetFilterBoolFn setFilterBool;
    oidn::SetFilterIntFn setFilterInt;
    oidn::SetFilterFloatFn setFilterFloat;
    oidn::CommitFilterFn commitFilter;
    oidn::ExecuteFilterFn executeFilter;
};

namespace {

constexpr const char* kSoname = "libOpenImageDenoise.so.2";
constexpr const char* kInstall = "install it with tools/install-oidn (tools/install-deps runs it), or name the library "
                                 "file with PT_OIDN_LIBRARY=/path/to/libOpenImageDenoise.so.2";

// Checks the library at `file`, and the OIDN libraries it brings with it from its folder (its
// core, which it needs, and the device modules OIDN opens there), before any of them is loaded:
// a damaged one would kill pt inside dlopen (shared_library.h). Throws DenoiseError naming it.
void checkLibraryFiles(const std::string& file) {
    namespace fs = std::filesystem;
    const SharedLibraryInfo info = inspectSharedLibrary(file);
    if (!info.error.empty()) throw DenoiseError(info.error + "; it cannot be loaded as Intel Open Image Denoise");
    std::error_code ec;
    const fs::path folder = fs::canonical(file, ec).parent_path();
    if (ec) return;
    std::vector<std::string> companions;
    for (const std::string& n : info.needed)
        if (n.rfind("libOpenImageDenoise", 0) == 0) companions.push_back((folder / n).string());
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
        if (e.path().filename().string().rfind("libOpenImageDenoise_device_", 0) == 0) companions.push_back(e.path().string());
    for (const std::string& c : companions) {
        if (!fs::exists(fs::symlink_status(c, ec))) continue; // not beside it: the loader looks elsewhere, and says so
        const SharedLibraryInfo companion = inspectSharedLibrary(c);
        if (!companion.error.empty())
            throw DenoiseError(companion.error + "; Intel Open Image Denoise (" + file + ") loads it, so it cannot be used");
    }
}

// Where the dynamic loader would find `soname` without a path: LD_LIBRARY_PATH, then the folders
// of /etc/ld.so.conf.d and the system's own; "" if in none. pt checks and loads that file by its
// path, so that what is checked is what is loaded.
std::string findOnLibraryPath(const std::string& soname) {
    namespace fs = std::filesystem;
    std::vector<std::string> folders;
    if (const char* env = std::getenv("LD_LIBRARY_PATH"))
        for (std::string_view rest = env; !rest.empty();) {
            const size_t colon = rest.find(':');
            folders.emplace_back(rest.substr(0, colon));
            rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
        }
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator("/etc/ld.so.conf.d", ec)) {
        if (e.path().extension() != ".conf") continue;
        std::ifstream conf(e.path());
        for (std::string line; std::getline(conf, line);)
            if (!line.empty() && line[0] == '/') folders.push_back(line.substr(0, line.find_first_of(" \t#")));
    }
    for (const char* f : {"/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu", "/lib64", "/usr/lib64", "/lib", "/usr/lib"})
        folders.emplace_back(f);
    for (const std::string& f : folders) {
        if (f.empty()) continue;
        const fs::path candidate = fs::path(f) / soname;
        if (fs::exists(fs::symlink_status(candidate, ec))) return candidate.string();
    }
    return "";
}

// The library stays loaded for the life of the process: its thread pool may outlive a device.
void* loadLibrary(std::string& path, std::string& missing) {
    auto load = [&](const std::string& file) -> void* {
        checkLibraryFiles(file);
        void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            throw DenoiseError(file + " cannot be loaded as Intel Open Image Denoise: " + (why ? why : "unknown error"));
        }
        path = file;
        return handle;
    };
    std::error_code ec;
    if (const char* named = std::getenv("PT_OIDN_LIBRARY"); named && *named) {
        // A name that leads nowhere is a library not installed (a usage matter); a link loop, a
        // pipe or a damaged file is a library that is there and wrong (checkLibraryFiles).
        if (!std::filesystem::exists(std::filesystem::symlink_status(named, ec))) {
            missing = std::string("PT_OIDN_LIBRARY names ") + named + ", which does not exist; " + kInstall;
            return nullptr;
        }
        struct stat st {};
        if (stat(named, &st) != 0 && errno == ENOENT) {
            missing = std::string("PT_OIDN_LIBRARY names ") + named + ", a symbolic link to a file that does not exist; " + kInstall;
            return nullptr;
        }
        return load(named);
    }
    const std::string bundled = std::string(PT_OIDN_DEFAULT_DIR) + "/" + kSoname;
    if (*PT_OIDN_DEFAULT_DIR && std::filesystem::exists(bundled, ec)) return load(bundled);
    if (const std::string system = findOnLibraryPath(kSoname); !system.empty()) return load(system);
    missing = std::string("--denoise needs Intel Open Image Denoise 2.x, which was not found (looked for ") +
              (*PT_OIDN_DEFAULT_DIR ? bundled + " and " : std::string()) + kSoname +
              " on the library path; PT_OIDN_LIBRARY is not set); " + kInstall;
    return nullptr;
}

template <typename Fn>
void bind(void* handle, const std::string& path, const char* name, Fn& fn) {
    fn = reinterpret_cast<Fn>(dlsym(handle, name));
    if (!fn)
        throw DenoiseError(path + " is not Intel Open Image Denoise 2.x: it has no function " + name +
                           " (pt needs OIDN 2.x; tools/install-oidn installs 2.5.1)");
}

// Any pixel value the filter must not see (NaN, Inf, negative colour) becomes 0; a feature is
// brought into the range OIDN expects. Returns how many colour values were replaced.
size_t sanitize(DenoiseImages& images) {
    size_t replaced = 0;
    for (float& v : *images.color)
        if (!(v >= 0.0f && v <= 3.0e38f)) v = 0.0f, ++replaced;
    for (float& v : images.albedo) v = v >= 0.0f ? std::min(v, 1.0f) : 0.0f; // NaN too
    for (float& v : images.normal) v = v >= -1.0f ? std::min(v, 1.0f) : 0.0f;
    return replaced;
}

// The scale that brings the image to the brightness OIDN's HDR networks were trained at: a
// log-average luminance of 0.18 over blocks of 16 x 16 pixels. OIDN's own (inputScale left NaN)
// does the same but passes over blocks darker than 1e-8, so an image rendered at --exposure -28
// or scaled by 1e-9 reached the network as black, and came back 5 to 180 times its brightness.
// Here every block with light counts, in double: the filter's input is the same picture at any
// scale, to float rounding.
float inputScale(const std::vector<float>& color, size_t width, size_t height) {
    constexpr size_t kBlock = 16;
    double logSum = 0.0;
    size_t blocks = 0;
    for (size_t by = 0; by < height; by += kBlock)
        for (size_t bx = 0; bx < width; bx += kBlock) {
            double sum = 0.0;
            const size_t y1 = std::min(by + kBlock, height), x1 = std::min(bx + kBlock, width);
            for (size_t y = by; y < y1; ++y)
                for (size_t x = bx; x < x1; ++x) {
                    const float* p = &color[3 * (y * width + x)];
                    sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
                }
            const double mean = sum / double((y1 - by) * (x1 - bx));
            if (mean > 0.0 && std::isfinite(mean)) logSum += std::log2(mean), ++blocks;
        }
    if (blocks == 0) return 1.0f; // black: any scale gives black
    return float(std::clamp(0.18 / std::exp2(logSum / double(blocks)), 1e-30, 1e30));
}

} // namespace

std::unique_ptr<Denoiser> Denoiser::open(int threads, std::string& missing) {
    std::string path;
    void* handle = loadLibrary(path, missing);
    if (!handle) return nullptr;
    std::unique_ptr<Denoiser> d(new Denoiser);
    d->api_ = std::make_unique<Api>();
    Api& a = *d->api_;
    d->path_ = path;
    bind(handle, path, "oidnNewDevice", a.newDevice);
    bind(handle, path, "oidnReleaseDevice", a.releaseDevice);
    bind(handle, path, "oidnSetDeviceInt", a.setDeviceInt);
    bind(handle, path, "oidnSetDeviceBool", a.setDeviceBool);
    bind(handle, path, "oidnGetDeviceInt", a.getDeviceInt);
    bind(handle, path, "oidnCommitDevice", a.commitDevice);
    bind(handle, path, "oidnGetDeviceError", a.getDeviceError);
    bind(handle, path, "oidnNewFilter", a.newFilter);
    bind(handle, path, "oidnReleaseFilter", a.releaseFilter);
    bind(handle, path, "oidnSetSharedFilterImage", a.setSharedFilterImage);
    bind(handle, path, "oidnSetFilterBool", a.setFilterBool);
    bind(handle, path, "oidnSetFilterInt", a.setFilterInt);
    bind(handle, path, "oidnSetFilterFloat", a.setFilterFloat);
    bind(handle, path, "oidnCommitFilter", a.commitFilter);
    bind(handle, path, "oidnExecuteFilter", a.executeFilter);

    oidn::Device device = a.newDevice(oidn::kDeviceCpu);
    if (!device) {
        const char* message = nullptr;
        a.getDeviceError(nullptr, &message);
        throw DenoiseError("Intel Open Image Denoise (" + path + ") could not open its CPU device: " +
                           (message ? message : "no reason given"));
    }
    d->device_ = device;
    // The render's thread count, and no pinning: pt shares the process (and the machine) with it.
    if (threads > 0) a.setDeviceInt(device, "numThreads", threads);
    a.setDeviceBool(device, "setAffinity", false);
    a.commitDevice(device);
    const char* message = nullptr;
    if (a.getDeviceError(device, &message) != oidn::kErrorNone)
        throw DenoiseError("Intel Open Image Denoise (" + path + "): " + (message ? message : "device error"));
    int version = a.getDeviceInt(device, "version"); // 20501 for 2.5.1
    d->version_ = std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." +
                  std::to_string(version % 100);
    if (version < 20000 || version >= 30000)
        throw DenoiseError(path + " is Intel Open Image Denoise version " + d->version_ +
                           "; pt needs 2.x (tools/install-oidn installs 2.5.1)");
    return d;
}

Denoiser::~Denoiser() {
    if (device_) api_->releaseDevice(oidn::Device(device_));
}

DenoiseReport Denoiser::denoise(DenoiseImages& images, const DenoiseOptions& options) const {
    const Api& a = *api_;
    oidn::Device device = oidn::Device(device_);
    const size_t w = size_t(images.width), h = size_t(images.height), n = w * h * 3;
    if (images.color->size() != n || images.albedo.size() != n || images.normal.size() != n)
        throw DenoiseError("denoise: the colour, albedo and normal images differ in size");
    auto start = std::chrono::steady_clock::now();
    DenoiseReport report;
    report.replaced = sanitize(images);
    const float scale = inputScale(*images.color, w, h);
    const DenoiseQuality quality = options.quality;
    const int q = quality == DenoiseQuality::High       ? oidn::kQualityHigh
                  : quality == DenoiseQuality::Balanced ? oidn::kQualityBalanced
                                                        : oidn::kQualityFast;
    auto check = [&](const char* stage) {
        const char* message = nullptr;
        oidn::Error e = a.getDeviceError(device, &message);
        if (e == oidn::kErrorNone) return;
        std::string what = e == oidn::kErrorOutOfMemory ? "out of memory" : "error";
        throw DenoiseError("Intel Open Image Denoise " + version_ + ", " + stage + ": " + what + ": " +
                           (message ? message : "no message"));
    };
    // Released on every path out, an exception's included.
    struct FilterHandle {
        const Api& a;
        oidn::Filter f;
        ~FilterHandle() {
            if (f) a.releaseFilter(f);
        }
    };
    // One RT filter per image: the feature filters take the feature as their only input.
    std::vector<float> out(n);
    auto run = [&](const char* stage, std::vector<float>* feature, bool beauty) {
        FilterHandle filter{a, a.newFilter(device, "RT")};
        check(stage);
        auto image = [&](const char* name, std::vector<float>& v) {
            a.setSharedFilterImage(filter.f, name, v.data(), oidn::kFormatFloat3, w, h, 0, 0, 0);
        };
        if (beauty) {
            image("color", *images.color);
            image("albedo", images.albedo);
            image("normal", images.normal);
            a.setFilterBool(filter.f, "hdr", true);
            a.setFilterBool(filter.f, "cleanAux", options.prefilter);
            a.setFilterFloat(filter.f, "inputScale", scale);
        } else {
            image(feature == &images.albedo ? "albedo" : "normal", *feature);
        }
        image("output", out);
        a.setFilterInt(filter.f, "quality", q);
        a.commitFilter(filter.f);
        check(stage);
        a.executeFilter(filter.f);
        check(stage);
    };
    if (options.prefilter) {
        run("prefiltering the albedo", &images.albedo, false);
        images.albedo.swap(out);
        for (float& v : images.albedo) v = std::clamp(v, 0.0f, 1.0f); // the filter may overshoot at edges
        run("prefiltering the normal", &images.normal, false);
        images.normal.swap(out);
    }
    run("denoising the image", nullptr, true);
    // A filter that fails inside without saying so (a damaged library, a CPU it mishandles) must
    // not have its output taken for the image.
    const size_t bad = size_t(std::count_if(out.begin(), out.end(), [](float v) { return !std::isfinite(v); }));
    if (bad > 0)
        throw DenoiseError("Intel Open Image Denoise " + version_ + " returned " + std::to_string(bad) +
                           " NaN or infinite values of " + std::to_string(n) + "; the denoised image was not used");
    images.color->swap(out);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.description = "OIDN " + version_ + " RT, quality " + qualityName(quality) + ", albedo and normal " +
                         (options.prefilter ? "prefiltered" : "as rendered");
    return report;
}

} // namespace pt
