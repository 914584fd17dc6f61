// Where pt's own messages go. With -q, file descriptor 2 is pointed at /dev/null so that the
// libraries' own lines (libpng warnings, TBB notices) stay quiet too, while pt's errors still
// reach the real stderr through errorStream().
#pragma once

#include <cstdio>

namespace pt::cli {

// pt's stderr: the real one, even after silenceLibraryOutput().
FILE* errorStream();
// Its file descriptor, for signal handlers (which cannot use stdio).
int errorFd();
// Sends everything the libraries write to fd 2 to /dev/null from now on.
void silenceLibraryOutput();

} // namespace pt::cli
