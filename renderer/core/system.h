// Facts about the machine and small text helpers shared by the loaders, the image readers and the
// command line.
#pragma once

#include <cstdio>
#include <string>
#include <unistd.h>

namespace pt {

// Bytes of physical memory, or 0 when the system does not say. Inputs are checked against it
// before they are read, so that a file declaring more than fits is refused with its name.
inline double physicalMemoryBytes() {
    double bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    return bytes > 0 ? bytes : 0.0;
}

// A number for a message: "1e+38", "0.5", never "100000000000000000000000000000000000000.000000".
inline std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

} // namespace pt
