// A stand-in for Intel Open Image Denoise 2.x with the C functions pt binds (denoise/oidn_api.h),
// whose filter writes NaN into its output: what a library that fails inside without saying so
// would give. Built as a shared library for denoise_test.cpp, which loads it by PT_OIDN_LIBRARY.
#include <cmath>
#include <cstddef>

namespace {
struct Filter {
    float* output = nullptr;
    size_t values = 0;
};
int device; // the one device's handle: its address
} // namespace

extern "C" {
void* oidnNewDevice(int) { return &device; }
void oidnReleaseDevice(void*) {}
void oidnSetDeviceInt(void*, const char*, int) {}
void oidnSetDeviceBool(void*, const char*, bool) {}
int oidnGetDeviceInt(void*, const char*) { return 20501; }
void oidnCommitDevice(void*) {}
int oidnGetDeviceError(void*, const char** message) {
    if (message) *message = nullptr;
    return 0;
}
void* oidnNewFilter(void*, const char*) { return new Filter; }
void oidnReleaseFilter(void* f) { delete static_cast<Filter*>(f); }
void oidnSetSharedFilterImage(void* f, const char* name, void* data, int, size_t width, size_t height, size_t, size_t, size_t) {
    if (name[0] == 'o') static_cast<Filter*>(f)->output = static_cast<float*>(data), static_cast<Filter*>(f)->values = width * height * 3;
}
void oidnSetFilterBool(void*, const char*, bool) {}
void oidnSetFilterInt(void*, const char*, int) {}
void oidnSetFilterFloat(void*, const char*, float) {}
void oidnCommitFilter(void*) {}
void oidnExecuteFilter(void* f) {
    Filter* filter = static_cast<Filter*>(f);
    for (size_t i = 0; i < filter->values; ++i) filter->output[i] = i % 7 == 0 ? NAN : 0.5f;
}
}
