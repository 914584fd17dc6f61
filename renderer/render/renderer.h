// Orchestration of a render: the image is cut into tiles that a oneTBB pool takes dynamically;
// every pixel's samples come from its own (pixel, sample index, seed) streams, so the image does
// not depend on the thread count or on the order tiles finish.
#pragma once

#include "accel/accel.h"
#include "light/light_set.h"
#include "render/film.h"
#include "render/path_tracer.h"
#include "render/pinhole_camera.h"
#include "render/render_settings.h"
#include "render/sample_budget.h"

#include <atomic>

namespace pt {

// Shared between a render and whoever watches it (a progress line, a signal handler).
// Work is counted in tile-samples: a tile finishing n samples per pixel adds n.
struct RenderProgress {
    std::atomic<uint64_t> done{0};
    uint64_t total = 0;
    std::atomic<bool> cancel{false};
    std::atomic<uint32_t> samplesComplete{0}; // samples every pixel still sampling holds, after each full pass
    std::atomic<uint64_t> converged{0};       // pixels adaptive sampling has stopped
    uint64_t pixels = 0;
};

// A rectangle of pixels [x0, x1) x [y0, y1) of the full image, row 0 at the top.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

class Renderer {
public:
    static constexpr int kTileSize = 16;

    // `spp` is the render's total samples per pixel: texture footprints shrink with it (each sample
    // filters over 1 / sqrt(spp) of a pixel, at least an eighth), as the samples themselves average
    // over the pixel. Only the pixels of `window` (all of them when it is empty) are rendered, into
    // a film of the window's size; each keeps the random numbers it has in the full image.
    Renderer(const Scene& scene, const Accel& accel, const Camera& camera, int width, int height,
             const RenderSettings& settings, uint32_t spp, PixelWindow window = {});

    // Adds samples [first, last) of every pixel of the window to `film`, in parallel on the
    // calling thread's task arena; a pixel whose `startAt` entry is later starts there (resuming a
    // part). Returns the rays traced.
    RayCounts renderSamples(Film& film, uint32_t first, uint32_t last, RenderProgress* progress = nullptr,
                            const std::vector<uint32_t>* startAt = nullptr) const;

    // --guide: learns the path guide in passes of 1, 2, 4, ... samples per pixel of the whole
    // image (a crop's too, so that every part of a job learns the same guide), until
    // settings.guideSpp (at most the job's spp) are spent; the render's later samples are then guided by it. The passes
    // are the image's first samples: those in [keepFirst, keepLast) of the window's pixels (from a
    // pixel's `startAt` entry on, when given) go into `film`. Each pass draws under a seed of its
    // own, so that its samples are independent of the guide they are drawn by. Deterministic.
    // Returns the rays traced; stops early on a cancel request, and before a pass that would take
    // it past `seconds` (0: no limit; a --time render's share).
    RayCounts trainGuide(Film* film, uint32_t keepFirst, uint32_t keepLast, const std::vector<uint32_t>* startAt = nullptr,
                         RenderProgress* progress = nullptr, double seconds = 0.0);
    uint32_t guideSppTrained() const { return guideSppTrained_; }
    // Whether training stopped before settings.guideSpp because the guide had learnt to guide
    // almost none of the bounces (PathGuide::guidedFraction).
    bool guideSettled() const { return guideSettled_; }
    const PathGuide* guide() const { return guide_.get(); }
    // Guides the samples rendered from now on by `guide`, learnt elsewhere, instead of training
    // one: the render's samples are drawn as those after training are.
    void useGuide(std::unique_ptr<PathGuide> guide) {
        guide_ = std::move(guide);
        tracer_.setGuide(guide_.get());
    }

    size_t tileCount() const { return tilesIn(window_); }
    const PixelWindow& window() const { return window_; }

private:
    // One pass over the pixels of `window`: samples [first, last), drawn under `seed` at sample
    // indices from `indexBase` on. What goes into the film (over window_): a pixel's samples from
    // max(keepFirst, its startAt entry) to keepLast; in training, `recorders` take every sample.
    struct Pass {
        uint32_t first = 0, last = 0;
        uint64_t seed = 0;
        uint32_t indexBase = 0;
        PixelWindow window;
        uint32_t keepFirst = 0, keepLast = 0;
        std::vector<GuideRecorder>* recorders = nullptr;
    };
    template <typename Sampler>
    RayCounts renderSamplesWith(Film* film, const Pass& pass, RenderProgress* progress, const std::vector<uint32_t>* startAt) const;
    RayCounts renderPass(Film* film, const Pass& pass, RenderProgress* progress, const std::vector<uint32_t>* startAt) const;
    static size_t tilesIn(const PixelWindow& w) {
        return size_t((w.width() + kTileSize - 1) / kTileSize) * size_t((w.height() + kTileSize - 1) / kTileSize);
    }

    const Scene& scene_;
    const Accel& accel_;
    RenderSettings settings_;
    std::vector<ShadingTriangle> triangles_;
    std::vector<CornerTangent> tangents_;
    LightSet lights_;
    PinholeCamera camera_;
    PathTracer tracer_;
    std::unique_ptr<PathGuide> guide_; // --guide
    uint32_t guideSppTrained_ = 0;
    bool guideSettled_ = false;
    uint32_t spp_; // the job's samples per pixel, all parts together
    int width_, height_;
    PixelWindow window_;
};

struct RenderResult {
    Film film;
    RayCounts rays;
    double seconds = 0.0; // wall-clock time of rendering, excluding scene load and BVH build
    bool cancelled = false;
    bool outOfTime = false; // stopped by the budget's seconds before the cap (or convergence)
    // --guide: samples per pixel the guide learnt from, the memory it took, and whether that
    // reached the guide's bound (its regions then stopped splitting).
    uint32_t guideSpp = 0;
    size_t guideBytes = 0;
    bool guideLimited = false;
    // --guide: training stopped early, the guide guiding this fraction of the bounces.
    bool guideSettled = false;
    double guidedFraction = 0.0;
};

// What share of a job to render: samples [first, last) (last 0: all spp) of the pixels in
// `window` (all of them when empty), continuing `resume` when given: a film over the same window
// whose pixels hold a prefix of the range each (a part), whose samples are kept.
struct RenderRange {
    uint32_t first = 0, last = 0;
    PixelWindow window;
    const Film* resume = nullptr;
};

// Renders `spp` samples per pixel with `threads` threads (0: all hardware threads), in passes so
// that progress can be reported and a cancel request is honoured within one tile's pass. Passes
// double in size from one sample, so a render stopped at any moment has at least half of the
// samples it traced in complete passes over the whole image.
// `firstHitLayers` also accumulates the albedo, normal and depth layers. The film covers
// `range.window`.
// `budget` may stop it earlier: at the last pass boundary its seconds allow (the first pass is
// always rendered, so every pixel has a sample), and pixel by pixel at the pass boundaries where
// a pixel's noise falls below its target (each pixel keeps samples 0, 1, ... n-1 of the range).
RenderResult renderImage(const Scene& scene, const Accel& accel, const Camera& camera, int width, int height,
                         uint32_t spp, int threads, const RenderSettings& settings,
                         RenderProgress* progress = nullptr, bool firstHitLayers = false, const RenderRange& range = {},
                         const SampleBudget& budget = {});

} // namespace pt
