#include "cli/console.h"

#include <fcntl.h>
#include <unistd.h>

namespace pt::cli {
namespace {
FILE* gErr = nullptr;
int gErrFd = STDERR_FILENO;
} // namespace

FILE* errorStream() { return gErr ? gErr : stderr; }
int errorFd() { return gErrFd; }

void silenceLibraryOutput() {
    if (gErr) return;
    int saved = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved < 0 || null < 0) return; // keep the libraries' lines rather than lose ours
    FILE* f = fdopen(saved, "w");
    if (!f) return;
    std::fflush(stderr);
    dup2(null, STDERR_FILENO);
    close(null);
    setvbuf(f, nullptr, _IOLBF, 0);
    gErr = f;
    gErrFd = saved;
}

} // namespace pt::cli
