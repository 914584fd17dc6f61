// How a texture stores one channel of one texel: at the file's own depth, so that an 8-bit map
// takes a byte per channel and not four. 8-bit colour stays sRGB-encoded and is decoded to
// linear in the lookup, by a table (exactly what decoding at load gave before).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace pt {

enum class TexelFormat : uint8_t {
    Srgb8,  // 8-bit colour, sRGB-encoded
    Unorm8, // 8-bit data, value / 255
    Half,   // 16-bit float (half EXR); 16-bit integer files are held as Float
    Float,  // 32-bit float
};

constexpr int bytesPerChannel(TexelFormat f) {
    return f == TexelFormat::Float ? 4 : f == TexelFormat::Half ? 2 : 1;
}

// IEEE half precision <-> float (half EXR texels; a header here rather than a link to Imath).
inline float halfToFloat(uint16_t h) {
    uint32_t sign = uint32_t(h & 0x8000u) << 16, exponent = (h >> 10) & 0x1fu, mantissa = h & 0x3ffu;
    if (exponent == 0) { // zero or subnormal: mantissa * 2^-24
        float v = float(mantissa) * (1.0f / 16777216.0f);
        return sign ? -v : v;
    }
    uint32_t bits = sign | (exponent == 31 ? 0x7f800000u | (mantissa << 13) : ((exponent + 112) << 23) | (mantissa << 13));
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
}
uint16_t floatToHalf(float v); // rounded to nearest even; beyond 65504 infinite

// Linear value of each sRGB-encoded byte.
struct SrgbTable {
    float linear[256];
    float midpoint[256]; // between code i and i + 1, in linear terms (the last: infinity)
    uint8_t below[4097]; // the first code whose midpoint is not below k / 4096: where encoding starts
    SrgbTable();
};
extern const SrgbTable srgbTable;

// The stored value at `p`, as linear float.
inline float loadTexel(TexelFormat f, const uint8_t* p) {
    switch (f) {
    case TexelFormat::Srgb8: return srgbTable.linear[*p];
    case TexelFormat::Unorm8: return float(*p) * (1.0f / 255.0f);
    case TexelFormat::Half: {
        uint16_t bits;
        std::memcpy(&bits, p, 2);
        return halfToFloat(bits);
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

// Calls f with `format` as a compile-time constant (a std::integral_constant): loops over texels
// then take the format's branch once, not once per channel.
template <typename F>
decltype(auto) withTexelFormat(TexelFormat format, F&& f) {
    switch (format) {
    case TexelFormat::Srgb8: return f(std::integral_constant<TexelFormat, TexelFormat::Srgb8>());
    case TexelFormat::Unorm8: return f(std::integral_constant<TexelFormat, TexelFormat::Unorm8>());
    case TexelFormat::Half: return f(std::integral_constant<TexelFormat, TexelFormat::Half>());
    default: return f(std::integral_constant<TexelFormat, TexelFormat::Float>());
    }
}

// Stores linear `v` at `p`, rounded to the nearest value the format holds (8-bit values clamp to [0, 1]).
void storeTexel(TexelFormat f, float v, uint8_t* p);

} // namespace pt
