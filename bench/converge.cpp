#include "bench/bench_common.h"

namespace pt::bench {

int runConverge(int, char**) {
    std::fputs("pt-bench converge: not built yet\n", stderr);
    return 2;
}

} // namespace pt::bench
