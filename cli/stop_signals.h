// SIGINT and SIGTERM, the signals a user's Ctrl-C and a scheduler's time limit send. While a
// render is running, the first one asks it to stop (its finished samples are kept); at any other
// moment, and at a second signal, the process quits at once: every temporary output file is
// removed, a line says what happened, and the exit status is 128 + the signal. So a signal while
// a scene loads, or while pt merge reads or writes, never waits for the work to finish and never
// leaves a file behind.
#pragma once

#include <atomic>

namespace pt::cli {

// Installs the handlers (a signal the parent ignores stays ignored, as for a background job).
// `quitMessage` is printed when the process quits at once with nothing written, `writtenMessage`
// when it quits after its output was put in place (a signal in the last moments of a command);
// both must outlive the process.
void installStopHandlers(const char* quitMessage, const char* writtenMessage);

// While `cancel` is set, the first signal stores true into it instead of quitting; nullptr: quit.
void setStopTarget(std::atomic<bool>* cancel);

// The signal received so far, or 0.
int stopSignal();

} // namespace pt::cli
