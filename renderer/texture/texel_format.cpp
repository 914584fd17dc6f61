#include "texture/texel_format.h"

#include "core/color.h"

#include <algorithm>
#include <cmath>

namespace pt {

SrgbTable::SrgbTable() {
    for (int i = 0; i < 256; ++i) linear[i] = srgbToLinear(float(i) / 255.0f);
    for (int i = 0; i < 256; ++i) midpoint[i] = i < 255 ? 0.5f * (linear[i] + linear[i + 1]) : INFINITY;
    for (int k = 0, code = 0; k <= 4096; ++k) {
        while (code < 255 && midpoint[code] < float(k) / 4096.0f) ++code;
        below[k] = uint8_t(code);
    }
}
const SrgbTable srgbTable;

uint16_t floatToHalf(float v) {
    uint32_t x;
    std::memcpy(&x, &v, 4);
    uint16_t sign = uint16_t((x >> 16) & 0x8000u);
    x &= 0x7fffffffu;
    if (x >= 0x7f800000u) return uint16_t(sign | 0x7c00u | (x > 0x7f800000u ? 0x200u : 0u)); // inf, NaN
    if (x >= 0x477ff000u) return uint16_t(sign | 0x7c00u);                                   // rounds past 65504
    if (x < 0x38800000u) { // below 2^-14: a subnormal half, in steps of 2^-24
        float a;
        std::memcpy(&a, &x, 4);
        return uint16_t(sign | uint32_t(std::nearbyint(a * 16777216.0f)));
    }
    x += 0x0fffu + ((x >> 13) & 1u); // round the 13 dropped bits to nearest, ties to even
    return uint16_t(sign | ((x - (112u << 23)) >> 13));
}

void storeTexel(TexelFormat f, float v, uint8_t* p) {
    switch (f) {
    case TexelFormat::Srgb8: {
        // The nearest code in linear terms is the first whose midpoint with the next is not
        // below v; the table gives the code at the start of v's 1/4096 bucket, a step or two away.
        float c = v > 0.0f ? std::min(v, 1.0f) : 0.0f;
        int code = srgbTable.below[int(c * 4096.0f)];
        while (srgbTable.midpoint[code] < c) ++code;
        *p = uint8_t(code);
        break;
    }
    case TexelFormat::Unorm8: *p = uint8_t(std::lround((v > 0.0f ? std::min(v, 1.0f) : 0.0f) * 255.0f)); break; // NaN: 0
    case TexelFormat::Half: {
        uint16_t h = floatToHalf(v);
        std::memcpy(p, &h, 2);
        break;
    }
    case TexelFormat::Float: std::memcpy(p, &v, 4); break;
    }
}

} // namespace pt
