// What pt checks of a shared library before dlopen loads it: the dynamic loader maps a file's
// segments without reading them, so a library cut short (a failed copy, a full disk) kills the
// process with SIGBUS the moment its missing bytes are touched, with no message; a FIFO named as
// a library blocks the loader forever. These checks read the file's ELF headers and refuse it
// first, with a message naming the file.
#pragma once

#include <string>
#include <vector>

namespace pt {

struct SharedLibraryInfo {
    std::string error;               // "" when the file passed; else why it cannot be loaded
    std::vector<std::string> needed; // its DT_NEEDED entries (libraries it loads in turn)
};

// Checks that `path` (links followed) is a regular file holding an x86-64 ELF shared object
// whose program headers, loaded segments and dynamic section lie inside the file, and lists the
// libraries it needs. Never blocks: a FIFO or device is refused from its stat.
SharedLibraryInfo inspectSharedLibrary(const std::string& path);

} // namespace pt
