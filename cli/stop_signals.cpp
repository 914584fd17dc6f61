#include "cli/stop_signals.h"

#include "cli/console.h"
#include "io/output_file.h"

#include <csignal>
#include <cstring>
#include <unistd.h>

namespace pt::cli {
namespace {

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<std::atomic<bool>*>::is_always_lock_free);
std::atomic<std::atomic<bool>*> gCancel{nullptr};
const char* gQuitMessage = "";
const char* gWrittenMessage = "";
volatile std::sig_atomic_t gSignal = 0;

void say(const char* text) {
    ssize_t ignored = write(errorFd(), text, std::strlen(text));
    (void)ignored;
}

extern "C" void onStopSignal(int sig) {
    std::atomic<bool>* cancel = gCancel.load();
    if (gSignal == 0 && cancel) {
        gSignal = sig;
        cancel->store(true); // lock-free, so safe in a handler
        return;
    }
    removeTemporaryOutputs();
    if (committedOutputs() > 0) say(gWrittenMessage);
    else say(gSignal != 0 ? "pt: second signal: stopped at once; no output file was written or left behind\n" : gQuitMessage);
    _exit(128 + sig);
}

} // namespace

void installStopHandlers(const char* quitMessage, const char* writtenMessage) {
    gQuitMessage = quitMessage;
    gWrittenMessage = writtenMessage;
    struct sigaction sa {};
    sa.sa_handler = onStopSignal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM}) {
        struct sigaction old {};
        sigaction(sig, nullptr, &old);
        if (old.sa_handler == SIG_IGN) continue; // ignored by whoever started us (a background job): keep it so
        sigaction(sig, &sa, nullptr);
    }
}

void setStopTarget(std::atomic<bool>* cancel) { gCancel.store(cancel); }

int stopSignal() { return int(gSignal); }

} // namespace pt::cli
