#include "render/renderer.h"

#include "render/convergence.h"
#include "scene/complete_scene.h"

#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <xmmintrin.h>
#include <pmmintrin.h>

#include <chrono>

namespace pt {

namespace {

// Angle between the camera rays of neighbouring pixels at the image centre, scaled for the
// samples that share a pixel.
float pixelSpread(const Camera& camera, int height, uint32_t spp) {
    if (camera.orthoHalfHeight > 0.0f) return 0.0f; // parallel rays: no spread (bilinear lookups)
    float pixel = 2.0f * std::tan(glm::radians(0.5f * camera.fovY)) / float(height);
    return pixel * std::max(0.125f, 1.0f / std::sqrt(float(std::max(spp, 1u))));
}

// Paths traced together through the stages of the path loop, at most. A tile's pass goes in
// batches of this many.
constexpr size_t kBatchPaths = 512;

// Samples a guide region takes in a training pass of one sample per pixel before it splits
// (Müller et al.'s c). Finer regions learn from fewer samples each: at 4000 the guide of
// cornellbottle2's walls was noisier, and no better at equal samples.
constexpr double kGuideSplitSamples = 12000.0;
// Training stops once it has taken at least kGuideMinTrainingSpp and fewer than kGuideStopBelow
// of the guidable vertices of its last pass fall in regions that learnt to be guided.
constexpr uint32_t kGuideMinTrainingSpp = 7;
constexpr double kGuideStopBelow = 0.05;

// One pixel's sums over the samples of a pass, in double so that long renders do not lose the
// small values to the large.
struct PixelSums {
    glm::dvec3 sum{0.0}, sumSq{0.0}, albedo{0.0}, normal{0.0};
    double depth = 0.0;
    uint32_t hits = 0, count = 0;

    void add(const Spectrum& radiance, const FirstHit& first) {
        ++count;
        glm::dvec3 L(radiance);
        sum += L;
        sumSq += L * L;
        albedo += glm::dvec3(first.albedo); // a miss's too: the sky's colour
        if (first.depth < kInf) {
            normal += glm::dvec3(first.normal);
            depth += first.depth;
            ++hits;
        }
    }
};

} // namespace

Renderer::Renderer(const Scene& scene, const Accel& accel, const Camera& camera, int width, int height,
                   const RenderSettings& settings, uint32_t spp, PixelWindow window)
    : scene_(scene), accel_(accel), settings_(settings), triangles_(buildShadingTriangles(scene)), tangents_(buildCornerTangents(scene)),
      lights_(scene, settings.lightChoice), camera_(camera, width, height),
      tracer_(scene, triangles_, tangents_, accel, lights_, settings_, pixelSpread(camera, height, spp)),
      spp_(spp), width_(width), height_(height), window_(window.empty() ? PixelWindow{0, 0, width, height} : window) {}

RayCounts Renderer::renderSamples(Film& film, uint32_t first, uint32_t last, RenderProgress* progress,
                                  const std::vector<uint32_t>* startAt) const {
    return renderPass(&film, Pass{first, last, settings_.seed, 0, window_, first, last, nullptr}, progress, startAt);
}

RayCounts Renderer::renderPass(Film* film, const Pass& pass, RenderProgress* progress, const std::vector<uint32_t>* startAt) const {
    if (settings_.sampler == SamplerKind::Sobol) return renderSamplesWith<SobolSampler>(film, pass, progress, startAt);
    return renderSamplesWith<IndependentSampler>(film, pass, progress, startAt);
}

RayCounts Renderer::trainGuide(Film* film, uint32_t keepFirst, uint32_t keepLast, const std::vector<uint32_t>* startAt,
                               RenderProgress* progress, double seconds) {
    RayCounts rays;
    if (settings_.guideSpp == 0) return rays;
    Vec3 lo, hi;
    sceneBounds(scene_, lo, hi);
    guide_ = std::make_unique<PathGuide>(lo, hi);
    tracer_.setGuide(guide_.get());
    const PixelWindow full{0, 0, width_, height_};
    std::vector<GuideRecorder> recorders(tilesIn(full));
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    uint32_t first = 0;
    double lastPass = 0.0;
    // Training's passes are the image's first samples: none past the job's spp, which no part keeps.
    const uint32_t trainable = std::min(settings_.guideSpp, spp_);
    for (uint32_t size = 1, k = 0; first + size <= trainable; first += size, size *= 2, ++k) {
        if (progress && progress->cancel.load()) break;
        if (seconds > 0.0 && elapsed() + 2.0 * lastPass > seconds) break; // the next pass is twice the last
        const double passStart = elapsed();
        // A seed per pass: the guide a pass draws by was learnt from the passes before, whose
        // samples a shared seed would correlate with this one's (Sobol's are stratified together).
        // Each pass's samples are the first indices of its sequence.
        const uint64_t seed = hashCombine(settings_.seed, 0x6775696465ULL + k);
        rays += renderPass(film, Pass{first, first + size, seed, first, full, keepFirst, keepLast, &recorders}, progress, startAt);
        lastPass = elapsed() - passStart;
        if (progress && progress->cancel.load()) break; // a pass cut short: some tiles recorded nothing
        for (GuideRecorder& r : recorders) { // in tile order: the same tree on every run
            guide_->add(r);
            r.clear();
        }
        // A region splits once a pass gives it more samples than this (Müller et al.'s
        // c sqrt(2^k), with c for pt's smaller images).
        guide_->endPass(uint64_t(kGuideSplitSamples * std::sqrt(double(size))));
        guideSppTrained_ = first + size;
        // Training that its own measure says guides almost nothing is stopped: the rest of the
        // render's samples are cheaper unguided.
        if (first + 3 * size <= trainable && guideSppTrained_ >= kGuideMinTrainingSpp &&
            guide_->guidedFraction() < kGuideStopBelow) {
            guideSettled_ = true;
            break;
        }
    }
    // A guide that guides no region would only cost its lookups at every bounce: the render's
    // samples are then drawn as unguided ones are.
    if (!guide_->guidesAnywhere()) tracer_.setGuide(nullptr);
    return rays;
}

template <typename Sampler>
RayCounts Renderer::renderSamplesWith(Film* film, const Pass& pass, RenderProgress* progress,
                                      const std::vector<uint32_t>* startAt) const {
    const uint32_t first = pass.first, last = pass.last;
    const PixelWindow& window = pass.window;
    std::vector<GuideRecorder>* recorders = pass.recorders;
    tbb::combinable<RayCounts> counts;
    tbb::enumerable_thread_specific<PathBatch<Sampler>> batches;
    const bool layers = film && film->hasFirstHitLayers();
    const int tilesX = (window.width() + kTileSize - 1) / kTileSize;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, tilesIn(window), 1),
        [&](const tbb::blocked_range<size_t>& range) {
            // Embree asks for flush-to-zero and denormals-are-zero on every tracing thread.
            _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
            _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
            RayCounts& local = counts.local();
            PathBatch<Sampler>& batch = batches.local();
            constexpr int kPacket = Accel::kPacket;
            for (size_t tile = range.begin(); tile != range.end(); ++tile) {
                if (progress && progress->cancel.load(std::memory_order_relaxed)) return;
                const int x0 = window.x0 + int(tile % tilesX) * kTileSize, y0 = window.y0 + int(tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, window.x1), y1 = std::min(y0 + kTileSize, window.y1);
                const int tileWidth = x1 - x0;
                // The sampler keys a pixel by its place in the full image, the film by its place in the window.
                auto inFilm = [&](int x, int y) { return x >= window_.x0 && x < window_.x1 && y >= window_.y0 && y < window_.y1; };
                auto filmPixel = [&](int x, int y) {
                    return size_t(y - window_.y0) * size_t(window_.width()) + size_t(x - window_.x0);
                };
                PixelSums sums[kTileSize * kTileSize];
                PixelKey keys[kTileSize * kTileSize];
                // Samples [begin, last) of a pixel are traced; those from keepFrom to keepLast kept.
                uint32_t begin[kTileSize * kTileSize], keepFrom[kTileSize * kTileSize], tileBegin = last;
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) {
                        const int k = (y - y0) * tileWidth + (x - x0);
                        keepFrom[k] = !inFilm(x, y) ? ~0u : startAt ? std::max(pass.keepFirst, (*startAt)[filmPixel(x, y)]) : pass.keepFirst;
                        begin[k] = recorders ? first : std::max(first, keepFrom[k]); // training learns from every sample
                        tileBegin = std::min(tileBegin, begin[k]);
                        keys[k] = Sampler::pixelKey(uint32_t(y) * uint32_t(width_) + uint32_t(x), pass.seed);
                    }
                // Paths go into the batch sample by sample, each sample's pixels row by row in
                // groups of kPacket, whose camera rays are traced as one packet. Results are summed
                // in the same order, so each pixel adds its samples in sample order.
                batch.clear();
                GuideRecorder* recorder = recorders ? &(*recorders)[tile] : nullptr;
                auto traceBatch = [&] {
                    tracer_.trace(batch, layers, local, recorder);
                    for (const PathState<Sampler>& p : batch.paths)
                        if (p.kept) sums[p.pixel].add(p.L, p.first);
                    batch.clear();
                };
                for (uint32_t s = tileBegin; s < last; ++s)
                    for (int y = y0; y < y1; ++y)
                        for (int gx = x0; gx < x1; gx += kPacket) {
                            const int lanes = std::min(kPacket, x1 - gx);
                            if (batch.paths.size() + size_t(lanes) > kBatchPaths) traceBatch();
                            Ray rays[kPacket];
                            bool active[kPacket] = {};
                            int count = 0, lane[kPacket];
                            const size_t start = batch.paths.size();
                            for (int i = 0; i < lanes; ++i) {
                                const int k = (y - y0) * tileWidth + (gx + i - x0);
                                if (s < begin[k]) continue;
                                active[i] = true;
                                lane[count++] = i;
                                PathState<Sampler>& p = batch.paths.emplace_back();
                                p.sampler = Sampler(keys[k], s - pass.indexBase);
                                p.pixel = uint32_t(k);
                                p.kept = s >= keepFrom[k] && s < pass.keepLast;
                            }
                            if (count == 0) continue;
                            // The position inside the pixel (a box filter: uniform there), for the
                            // group's paths together.
                            uint32_t slots[kPacket];
                            for (int j = 0; j < count; ++j) slots[j] = uint32_t(start) + uint32_t(j);
                            batch.chooseForDraws(slots, size_t(count));
                            batch.drawDimension(kPixelDimension, true);
                            for (int j = 0; j < count; ++j) {
                                const int i = lane[j];
                                rays[i] = batch.paths[start + size_t(j)].ray =
                                    camera_.generate(float(gx + i) + batch.drawX[size_t(j)], float(y) + batch.drawY[size_t(j)]);
                            }
                            Hit hits[kPacket];
                            accel_.intersectCameraRays(rays, active, lanes, hits);
                            for (int i = 0; i < lanes; ++i)
                                if (active[i]) batch.hits.push_back(hits[i]);
                        }
                if (!batch.paths.empty()) traceBatch();
                if (recorder) recorder->reduce();
                if (film) {
                    for (int y = y0; y < y1; ++y)
                        for (int x = x0; x < x1; ++x) {
                            const int k = (y - y0) * tileWidth + (x - x0);
                            const PixelSums& p = sums[k];
                            if (p.count == 0) continue; // a resumed pixel that already has them all, or none kept
                            film->add(filmPixel(x, y), p.sum, p.sumSq, p.count);
                            if (layers) film->addFirstHit(filmPixel(x, y), p.albedo, p.normal, p.depth, p.hits);
                        }
                }
                if (progress && !recorders) progress->done.fetch_add(last - first, std::memory_order_relaxed);
            }
        },
        tbb::simple_partitioner());
    RayCounts total;
    counts.combine_each([&](const RayCounts& c) { total += c; });
    return total;
}

namespace {

// The size of the pass after `done` samples of the range. Passes of 1, 1, 2, 4, ... samples, at
// most maxPass: a cancel request stops the render within one pass of a tile, and the film counts
// samples per pixel, so what was done stays usable. Adaptive sampling puts a boundary at minSpp,
// where pixels may first stop, and after it passes of a quarter of what a pixel holds, so that a
// pixel stops soon after its noise reaches the target.
uint32_t passSize(uint32_t done, uint32_t maxPass, const SampleBudget& budget) {
    const uint32_t doubling = std::clamp(done, 1u, maxPass);
    if (!budget.adaptive()) return doubling;
    if (done < budget.minSpp) return std::min(doubling, budget.minSpp - done);
    return std::clamp(done / 4, 1u, maxPass);
}

} // namespace

RenderResult renderImage(const Scene& scene, const Accel& accel, const Camera& camera, int width, int height,
                         uint32_t spp, int threads, const RenderSettings& settings, RenderProgress* progress,
                         bool firstHitLayers, const RenderRange& range, const SampleBudget& budgetAsked) {
    Renderer renderer(scene, accel, camera, width, height, settings, spp, range.window);
    const PixelWindow& window = renderer.window();
    RenderResult result{Film(window.width(), window.height()), {}};
    Film& film = result.film;
    if (firstHitLayers) film.enableFirstHitLayers();
    const uint32_t begin = range.first, end = range.last > 0 ? range.last : spp;
    SampleBudget budget = budgetAsked;
    budget.minSpp = std::clamp(budget.minSpp, 1u, end - begin);
    if (budget.adaptive()) film.enableConvergence();
    // The first sample index of each pixel still sampling, kNever for one that has stopped.
    // A resumed part's samples are kept; each pixel goes on from where it stopped.
    constexpr uint32_t kNever = ~0u;
    const size_t pixels = size_t(window.width()) * window.height();
    std::vector<uint32_t> startAt;
    if (range.resume || budget.adaptive()) startAt.assign(pixels, begin);
    if (range.resume) {
        const Film& part = *range.resume;
        for (size_t p = 0; p < pixels; ++p) {
            film.addPixel(p, part, p);
            startAt[p] = begin + part.count(p);
        }
        if (budget.adaptive() && part.hasConvergence()) {
            for (size_t p = 0; p < pixels; ++p)
                if (part.converged(p)) film.setConverged(p), startAt[p] = kNever;
            film.decidedAt = part.decidedAt;
        }
    }
    const uint32_t maxPass = std::max<uint32_t>(1, (end - begin) / 32);
    if (progress) {
        progress->total = uint64_t(end - begin) * renderer.tileCount();
        progress->pixels = pixels;
        progress->converged = film.convergedCount();
    }

    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    uint32_t renderFrom = begin; // after the guide's training samples
    arena.execute([&] {
        // The guide is learnt first, inside the time budget (a quarter of it at most): --guide's
        // cost is the render's. Its passes are the image's first samples, kept.
        result.rays += renderer.trainGuide(&film, begin, end, startAt.empty() ? nullptr : &startAt, progress, budget.seconds / 4.0);
        if (const PathGuide* guide = renderer.guide()) {
            const uint32_t trained = std::clamp(renderer.guideSppTrained(), begin, end);
            for (uint32_t& s : startAt)
                if (s != kNever) s = std::max(s, trained);
            if (progress) progress->done.fetch_add(uint64_t(trained - begin) * renderer.tileCount());
            if (progress) progress->samplesComplete.store(trained - begin);
            renderFrom = trained;
            result.guideSpp = renderer.guideSppTrained();
            result.guideBytes = guide->bytes();
            result.guideLimited = guide->limited();
            result.guideSettled = renderer.guideSettled();
            result.guidedFraction = guide->guidedFraction();
        }
        double secondsPerPixelSample = 0.0; // of the last pass, for the time budget
        for (uint32_t first = renderFrom; first < end;) {
            if (progress && progress->cancel.load()) break;
            size_t sampling = pixels;
            if (!startAt.empty()) sampling = size_t(std::count_if(startAt.begin(), startAt.end(), [&](uint32_t s) { return s < end; }));
            if (sampling == 0) break; // every pixel has converged (or holds the whole range)
            uint32_t size = std::min(end - first, passSize(first - begin, maxPass, budget));
            if (budget.seconds > 0.0 && secondsPerPixelSample > 0.0) {
                // Only whole passes: as many samples as the last pass's pace fits into what is left.
                double fits = (budget.seconds - elapsed()) / (secondsPerPixelSample * double(sampling));
                if (!(fits >= 1.0)) {
                    result.outOfTime = true;
                    break;
                }
                size = uint32_t(std::min(double(size), std::floor(fits)));
            }
            const uint32_t last = first + size;
            double work = double(pixels) * size; // pixel-samples this pass renders
            if (!startAt.empty()) {
                work = 0.0;
                for (uint32_t s : startAt) work += s < last ? double(last - std::max(first, s)) : 0.0;
            }
            const double passStart = elapsed();
            result.rays += renderer.renderSamples(film, first, last, progress, startAt.empty() ? nullptr : &startAt);
            if (work > 0.0) secondsPerPixelSample = std::max(1e-12, (elapsed() - passStart) / work);
            first = last;
            if (progress && progress->cancel.load()) break;
            if (budget.adaptive() && last - begin > film.decidedAt) {
                markConverged(film, budget, last - begin);
                for (size_t p = 0; p < pixels; ++p)
                    if (film.converged(p)) startAt[p] = kNever;
                if (progress) progress->converged = film.convergedCount();
            }
            if (progress) progress->samplesComplete.store(last - begin);
        }
        if (progress && progress->cancel.load()) result.cancelled = true;
    });
    result.seconds = elapsed();
    return result;
}

} // namespace pt
