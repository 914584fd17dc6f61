#include "cli/progress_line.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace pt::cli {

void ProgressLine::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) {
        thread_.join();
        std::fputs("\r\033[K", stderr);
    }
}

void ProgressLine::run() {
    auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; })) {
        double total = double(std::max<uint64_t>(1, progress_.total));
        double f = double(progress_.done.load()) / total;
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // With a time budget the time is the measure of progress; with --noise the share of
        // pixels converged is shown, and no estimate of what is left (the samples are not known).
        if (budget_.seconds > 0.0) f = std::max(f, std::min(1.0, elapsed / budget_.seconds));
        char text[200];
        int n = std::snprintf(text, sizeof text, "%5.1f%%  %u/%u spp  %.1f s elapsed", 100.0 * f,
                              progress_.samplesComplete.load(), spp_, elapsed);
        if (budget_.adaptive() && n > 0 && size_t(n) < sizeof text)
            n += std::snprintf(text + n, sizeof text - size_t(n), ", %.1f%% of pixels converged",
                               100.0 * double(progress_.converged.load()) / double(std::max<uint64_t>(1, progress_.pixels)));
        if (f > 0.0 && !budget_.adaptive() && n > 0 && size_t(n) < sizeof text)
            std::snprintf(text + n, sizeof text - size_t(n), ", about %.1f s left",
                          budget_.seconds > 0.0 ? std::max(0.0, budget_.seconds - elapsed) : elapsed * (1.0 - f) / f);
        struct winsize ws {};
        size_t width = ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 ? ws.ws_col : 80;
        std::string line(text);
        if (line.size() >= width) line.resize(width - 1); // the cursor must not reach the last column
        std::fprintf(stderr, "\r\033[K%s", line.c_str());
        std::fflush(stderr);
    }
}

} // namespace pt::cli
