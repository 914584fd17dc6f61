// Vectors of W 32-bit lanes (GCC vector extensions: elementwise arithmetic, comparisons giving
// lane masks, lanes indexed like an array), for code written once over its lane count. W = 1 is
// the scalar form of the same code; 4 fits SSE2 (any x86-64), 8 fits AVX2.
#pragma once

#include <cstdint>

namespace pt {

template <int W>
struct Lanes; // U32, I32 and F32: W lanes of uint32_t, int32_t and float

#define PT_DEFINE_LANES(W)                                               \
    template <>                                                          \
    struct Lanes<W> {                                                    \
        typedef uint32_t U32 __attribute__((vector_size(4 * W)));        \
        typedef int32_t I32 __attribute__((vector_size(4 * W)));         \
        typedef float F32 __attribute__((vector_size(4 * W)));           \
    };
PT_DEFINE_LANES(1)
PT_DEFINE_LANES(4)
PT_DEFINE_LANES(8)
#undef PT_DEFINE_LANES

} // namespace pt
