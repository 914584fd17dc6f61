// The part of Intel Open Image Denoise 2.x's C API that pt calls, declared here because the
// library comes without headers (a PyPI wheel, tools/install-oidn) and is loaded at run time
// (denoiser.cpp): handle types, the enum values pt passes, and each function's signature as a
// pointer type. Values and signatures follow OIDN's API documentation (doc/api.md, 2.x).
#pragma once

#include <cstddef>

namespace pt::oidn {

using Device = struct DeviceImpl*;
using Filter = struct FilterImpl*;

enum DeviceType : int { kDeviceDefault = 0, kDeviceCpu = 1 };
enum Error : int {
    kErrorNone = 0,
    kErrorUnknown = 1,
    kErrorInvalidArgument = 2,
    kErrorInvalidOperation = 3,
    kErrorOutOfMemory = 4,
    kErrorUnsupportedHardware = 5,
    kErrorCancelled = 6,
};
enum Format : int { kFormatFloat3 = 3 };
// OIDNQuality: the RT filter's precision/speed trade.
enum Quality : int { kQualityDefault = 0, kQualityFast = 4, kQualityBalanced = 5, kQualityHigh = 6 };

using NewDeviceFn = Device (*)(DeviceType);
using ReleaseDeviceFn = void (*)(Device);
using SetDeviceIntFn = void (*)(Device, const char*, int);
using SetDeviceBoolFn = void (*)(Device, const char*, bool);
using GetDeviceIntFn = int (*)(Device, const char*);
using CommitDeviceFn = void (*)(Device);
using GetDeviceErrorFn = Error (*)(Device, const char**);
using NewFilterFn = Filter (*)(Device, const char*);
using ReleaseFilterFn = void (*)(Filter);
using SetSharedFilterImageFn = void (*)(Filter, const char* name, void* data, Format, size_t width, size_t height,
                                        size_t byteOffset, size_t pixelByteStride, size_t rowByteStride);
using SetFilterBoolFn = void (*)(Filter, const char*, bool);
using SetFilterIntFn = void (*)(Filter, const char*, int);
using SetFilterFloatFn = void (*)(Filter, const char*, float);
using CommitFilterFn = void (*)(Filter);
using ExecuteFilterFn = void (*)(Filter);

} // namespace pt::oidn
