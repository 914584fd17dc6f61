// Facts about the machine and small text helpers shared by the loaders, the image readers and the
// command line.
#pragma once

#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>
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

// Case-insensitive ASCII comparison, for MTL keywords and file extensions.
inline bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower((unsigned char)a[i]) != std::tolower((unsigned char)b[i])) return false;
    return true;
}

inline std::string toLower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = char(std::tolower((unsigned char)c));
    return r;
}

} // namespace pt
