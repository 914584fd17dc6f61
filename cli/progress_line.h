// The one line of progress pt render redraws on a terminal.
#pragma once

#include "render/renderer.h"

#include <condition_variable>
#include <mutex>
#include <thread>

namespace pt::cli {

// Redraws one progress line on stderr until told to stop, cut to the terminal's width so that
// it never wraps onto a second line.
class ProgressLine {
public:
    ProgressLine(const RenderProgress& progress, uint32_t spp, const SampleBudget& budget, bool enabled)
        : progress_(progress), spp_(spp), budget_(budget) {
        if (enabled) thread_ = std::thread([this] { run(); });
    }
    ~ProgressLine() { stop(); }
    // Joins the drawing thread and clears the line; idempotent.
    void stop();

private:
    void run();

    const RenderProgress& progress_;
    uint32_t spp_;
    SampleBudget budget_;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
};

} // namespace pt::cli
