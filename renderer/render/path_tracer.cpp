#include "render/path_tracer.h"

#include "material/evaluate_material.h"
#include "render/surface_hit.h"

namespace pt {
namespace {

// Veach's power heuristic (beta = 2) for two strategies with one sample each.
// Written with the ratio of the pdfs, since their squares overflow float for a light whose solid
// angle is tiny (a 1e-10 sphere seen from 1 has pdf 3e19).
inline float powerHeuristic(float pdfA, float pdfB) {
    if (!(pdfA > 0.0f)) return 0.0f;
    float r = pdfB / pdfA;
    return 1.0f / (1.0f + r * r);
}

constexpr int kRouletteDepth = 3; // scattering events before Russian roulette starts
// Roulette spares a path while its throughput is above this, and below it keeps the path with
// probability throughput / kRouletteBelow. Continuing with the whole throughput (this at 1, as
// pbrt does) killed paths whose rare light through mirrors, glass or from the sun then came back
// in the few survivors, divided by their small throughput, many times as heavy as the pixel: at
// equal time, 256x256, 20 s, 2 seeds, this at 1/4 gave 0.43 to 0.66 times the relative MSE on
// cornellbottle2, cornell_textured, glass, outdoor (with and without env_sun.exr) and
// lamp_shaft; 1/2 gave 0.48 to 0.72 times, 1/8 0.42 to 0.66 times at more cost per sample.
constexpr float kRouletteBelow = 0.25f;
constexpr size_t kPrefetchAhead = 4; // paths between a shading record's prefetch and its use

} // namespace

template <typename Sampler>
bool PathTracer::neeCovers(const PathState<Sampler>& path, uint32_t emitter) const {
    return !path.deltaBefore && settings_.lightSampling != LightSampling::Bsdf && !lights_.empty() && emitter != ~0u;
}

template <typename Sampler>
float PathTracer::hitWeight(const PathState<Sampler>& path, uint32_t emitter, float distance) const {
    if (!neeCovers(path, emitter)) return 1.0f;
    if (settings_.lightSampling != LightSampling::Mis) return 0.0f; // next-event estimation already counted it
    float lightPdf = lights_.pmf(emitter, path.prevP, path.prevN) * lights_.pdf(emitter, path.prevP, path.ray.dir, distance);
    return powerHeuristic(path.prevPdf, lightPdf);
}

// Shade stage, step 1: the ray left the scene. What the environment and the sun's disk send
// along it, weighed against next-event estimation's chance of having sampled them.
template <typename Sampler>
void PathTracer::escape(PathState<Sampler>& path, bool firstHits) const {
    const Ray& ray = path.ray;
    const Environment& env = scene_.environment;
    const Spectrum sky = env.radiance(ray.dir);
    // No surface. A camera ray that misses gives the denoiser the sky's colour (within [0, 1]) as
    // its albedo, as Cycles does, so that the filter sees the background's edges and shading as
    // it sees a texture's. Seen through a mirror or glass the sky gives 0, as before: there the
    // lobe is chosen at random, and a white sky in a few of a dark wall's samples is noise in the
    // feature (a checker behind glass denoised with 20 % more error and 2.5 % darker).
    if (firstHits && path.first.open) {
        path.first.albedo = path.depth == 0 ? glm::min(sky, Spectrum(1.0f)) : Spectrum(0.0f);
        path.first.normal = Vec3(0.0f);
    }
    path.addEmitted(path.beta * sky * hitWeight(path, lights_.environmentEmitter(), kInf),
                     neeCovers(path, lights_.environmentEmitter()));
    if (env.sun && env.sun->covers(ray.dir))
        path.addEmitted(path.beta * env.sun->radiance * hitWeight(path, lights_.sunEmitter(), kInf),
                         neeCovers(path, lights_.sunEmitter()));
}

// Shade stage, step 2 for a sphere light: it emits and reflects nothing, so the path ends here.
template <typename Sampler>
void PathTracer::hitSphereLight(PathState<Sampler>& path, const Hit& hit, bool firstHits) const {
    const Ray& ray = path.ray;
    if (firstHits && path.first.open) {
        const LocalLight& l = scene_.lights[hit.prim];
        if (path.depth == 0) path.first.depth = hit.t;
        path.first.albedo = Spectrum(0.0f);
        path.first.normal = glm::normalize(ray.origin + hit.t * ray.dir - l.center);
        path.first.open = false;
    }
    const uint32_t e = lights_.emitterOfLight(hit.prim);
    path.addEmitted(path.beta * std::get<SphereEmitter>(lights_.emitter(e)).radiance * hitWeight(path, e, hit.t),
                     neeCovers(path, e));
}

// Shade stage, step 3: next-event estimation at a surface point. One emitter, one point on it;
// the shadow ray goes to the shadow stage with what it adds if nothing blocks it.
template <typename Sampler>
void PathTracer::sampleLight(const PathState<Sampler>& path, const SurfacePoint& sp, const Material& m,
                             const ShadingPoint& shading, const ScatterGuide& guide, const Vec3& ng,
                             const VertexDraws& u, uint32_t slot, std::vector<ShadowQuery>& shadows,
                             RayCounts& counts) const {
    const Frame& frame = shading.frame;
    const Bsdf& bsdf = shading.bsdf;
    const float uLight = lights_.size() > 1 ? u.lightChoice : 0.0f;
    float pmf;
    uint32_t e = lights_.choose(uLight, sp.p, frame.n, pmf);
    LightSample ls = pmf > 0.0f ? lights_.sample(e, sp.p, u.lightPoint) : LightSample{};
    Vec3 wiLocal = frame.toLocal(ls.wi);
    // The shading and the geometric normal must agree on the side wi leaves from, or the
    // shadow ray would start on the wrong side of the surface.
    if (!(ls.pdf > 0.0f && glm::dot(ls.wi, ng) * wiLocal.z > 0.0f)) return;
    float bsdfPdf; // for MIS; evaluated with f in one pass
    Spectrum f = bsdf.evalPdf(shading.wo, wiLocal, bsdfPdf);
    if (isBlack(f) || isBlack(ls.radiance)) return;
    ++counts.shadow;
    float w = (ls.isDelta() || settings_.lightSampling != LightSampling::Mis)
                  ? 1.0f
                  : powerHeuristic(pmf * ls.pdf, scatterPdf(bsdfPdf, ls.wi, guide));
    ShadowQuery q{Ray{}, 0.0f, -1, slot, path.beta * f * ls.radiance * (w / (pmf * ls.pdf)), path.guide ? path.guide->count : 0};
    bool aimed = true;
    if (ls.flags & kEmitterSurface) {
        // Between the two surfaces' offset points, so that neither self-intersects.
        Vec3 from = offsetRayOrigin(sp.p, sp.pError, sp.ng, ls.wi);
        Vec3 to = offsetRayOrigin(ls.point, ls.pointError, ls.normal, -ls.wi);
        Vec3 d = to - from;
        float len = glm::length(d);
        aimed = len > 0.0f;
        q.ray = Ray{from, d / len};
        q.distance = len;
    } else {
        q.ray = spawnRay(sp, ls.wi);
        q.distance = ls.distance;
        q.skipLight = ls.skipLight;
    }
    if (path.medium != kAir || m.volume) { // a shadow ray through the surface travels in the medium beyond it
        const bool crosses = glm::dot(ls.wi, sp.ng) * glm::dot(path.ray.dir, sp.ng) > 0.0f;
        const uint32_t medium = crosses ? mediumAfterCrossing(path.medium, sp.material, m, ls.wi, sp.ng) : path.medium;
        if (medium != kAir) q.contribution *= transmittance(scene_.materials[medium].attenuation, q.distance);
    }
    if (aimed) shadows.push_back(q);
}

// Shade stage, step 4: sample the BSDF for the path's next direction, then Russian roulette.
// Returns whether the path goes on (its ray set to the next).
template <typename Sampler>
bool PathTracer::continuePath(PathState<Sampler>& path, const SurfacePoint& sp, const Material& m,
                              const ShadingPoint& shading, const ScatterGuide& guide, const Vec3& ng,
                              const VertexDraws& u, bool firstHits, RayCounts& counts) const {
    const Frame& frame = shading.frame;
    const Ray& ray = path.ray;
    BsdfSample bs;
    Vec3 wi;
    ScatterParts parts;
    if (!sampleScatter(shading, u, guide, bs, wi, parts)) return false;
    if ((glm::dot(wi, ng) > 0.0f) != (bs.wi.z > 0.0f)) return false; // see sampleLight's side note
    if (m.volume && glm::dot(wi, sp.ng) * glm::dot(ray.dir, sp.ng) > 0.0f) // crossed a volume's surface
        path.medium = mediumAfterCrossing(path.medium, sp.material, m, wi, sp.ng);
    path.beta *= bs.weight;
    path.etaScale *= bs.radianceScale;
    if (guide.share > 0.0f && !bs.isDelta()) path.guideGain *= parts.bsdf / bs.pdf;
    // Through a mirror or smooth glass: what it passes tints the features of what lies beyond
    // (without refraction's radiance scaling, which is no colour).
    if (firstHits && path.first.open) path.first.tint *= bs.weight / bs.radianceScale;
    path.deltaBefore = bs.isDelta();
    path.prevPdf = bs.pdf;
    path.prevP = sp.p;
    path.prevN = frame.n;
    // Training: the light that comes back along wi is what this vertex learns from.
    if (path.guide) {
        const bool record = guide.guide && !bs.isDelta() && path.guide->count < GuidePath::kMaxVertices;
        if (record)
            path.guide->vertices[path.guide->count++] =
                GuideVertex{guide.region, wi, bs.pdf, path.beta, bs.weight * bs.pdf, parts.bsdf, parts.guide, guide.share};
        path.guide->lastIsPrevious = record;
    }

    // Russian roulette on the throughput without the refraction scaling, so paths inside glass
    // are not cut for carrying radiance that is only compressed.
    if (path.depth + 1 >= kRouletteDepth) {
        float q = std::min(1.0f, maxComponent(path.beta / path.etaScale) / kRouletteBelow);
        if (u.roulette >= q) return false;
        path.beta /= q;
    }
    if (isBlack(path.beta)) return false;
    path.ray = spawnRay(sp, wi);
    path.depth = path.depth + 1;
    ++counts.continuation;
    return true;
}

// The shade stage for one path at its hit: the steps above, in order.
template <typename Sampler>
bool PathTracer::shade(PathState<Sampler>& path, const Hit& hit, const VertexDraws& u, uint32_t slot, bool firstHits,
                       std::vector<ShadowQuery>& shadows, RayCounts& counts) const {
    const int depth = path.depth;
    const Ray& ray = path.ray;
    if (path.medium != kAir) // Beer-Lambert along the ray just traced
        path.beta *= transmittance(scene_.materials[path.medium].attenuation, hit.found() ? hit.t : kInf);
    if (!hit.found()) {
        escape(path, firstHits);
        return false;
    }
    if (hit.onSphere) {
        hitSphereLight(path, hit, firstHits);
        return false;
    }

    // The surface point, and what its material is there.
    const ShadingTriangle& tri = triangles_[hit.prim];
    SurfacePoint sp = makeSurfacePoint(tri, hit);
    const Material& m = scene_.materials[sp.material];
    path.coneWidth += pixelSpread_ * hit.t;
    if (m.isTextured()) addTextureCoordinates(sp, tri, scene_, tangents_, hit, ray.dir, path.coneWidth);
    if (m.unlit) [[unlikely]] { // only camera rays reach it (accel.cpp): its base colour, as seen
        const Spectrum color = m.kd * fetchSurfaceInputs(m, *scene_.textures, sp, -ray.dir).kd;
        path.L += path.beta * color;
        if (firstHits && path.first.open) {
            if (depth == 0) path.first.depth = hit.t;
            path.first.albedo = path.first.tint * color;
            path.first.normal = glm::dot(ray.dir, sp.ns) < 0.0f ? sp.ns : -sp.ns;
            path.first.open = false;
        }
        return false;
    }
    if (m.isEmissive()) { // emission found by the path, weighed against next-event estimation
        const uint32_t e = lights_.emitterOfTriangle(hit.prim);
        path.addEmitted(path.beta * emittedRadiance(m, *scene_.textures, sp.uv, sp.footprint) * hitWeight(path, e, hit.t),
                         neeCovers(path, e));
    }
    if (depth == settings_.maxDepth) return false;
    const ShadingPoint shading = evaluateMaterial(m, *scene_.textures, sp, -ray.dir, settings_.hemisphere);
    const Bsdf& bsdf = shading.bsdf;
    // The geometric normal on the frame's side, for the tests that wi leaves from the side the
    // frame says (a frame turned to a back face turns it too, or the back would stay black).
    const Vec3 ng = shading.turned ? -sp.ng : sp.ng;
    if (firstHits && path.first.open) { // final unless the surface is a mirror or smooth glass
        if (depth == 0) path.first.depth = hit.t;
        path.first.albedo = path.first.tint * bsdf.albedo(shading.wo);
        path.first.normal = shading.wo.z >= 0.0f ? shading.frame.n : -shading.frame.n;
        path.first.open = !bsdf.hasNonDelta() && !bsdf.isBlack();
    }
    if (bsdf.isBlack()) return false;
    const ScatterGuide guide =
        guide_ ? scatterGuideAt(guide_, sp.p, shading.wo.z >= 0.0f ? shading.frame.n : -shading.frame.n, bsdf,
                                path.guide != nullptr, path.guideGain)
               : ScatterGuide{};
    if (settings_.lightSampling != LightSampling::Bsdf && !lights_.empty() && bsdf.hasNonDelta())
        sampleLight(path, sp, m, shading, guide, ng, u, slot, shadows, counts);
    return continuePath(path, sp, m, shading, guide, ng, u, firstHits, counts);
}

// The draw stage: the sample values of every active path's vertex at `depth` (all paths of a
// round are at one depth), into batch.draws by position in batch.active. The light choice
// (with one light) and roulette (before kRouletteDepth) are left undrawn where no path reads them.
template <typename Sampler>
void drawVertexSamples(PathBatch<Sampler>& batch, int depth, bool lightChoice, bool guiding) {
    const bool roulette = depth + 1 >= kRouletteDepth;
    const size_t n = batch.active.size();
    batch.draws.resize(n);
    batch.chooseForDraws(batch.active.data(), n);
    auto draw = [&](SampleUse use, bool pair, auto&& put) {
        batch.drawDimension(sampleDimension(depth, use), pair);
        for (size_t k = 0; k < n; ++k) put(batch.draws[k], batch.drawX[k], batch.drawY[k]);
    };
    if (lightChoice) draw(SampleUse::LightChoice, false, [](VertexDraws& d, float x, float) { d.lightChoice = x; });
    draw(SampleUse::LightPoint, true, [](VertexDraws& d, float x, float y) { d.lightPoint = Vec2(x, y); });
    draw(SampleUse::Lobe, false, [](VertexDraws& d, float x, float) { d.lobe = x; });
    draw(SampleUse::Direction, true, [](VertexDraws& d, float x, float y) { d.direction = Vec2(x, y); });
    // A guided render reads the guide's choice beside roulette's, from the same dimension.
    if (guiding)
        draw(SampleUse::Roulette, true, [](VertexDraws& d, float x, float y) { d.roulette = x, d.guide = y; });
    else if (roulette)
        draw(SampleUse::Roulette, false, [](VertexDraws& d, float x, float) { d.roulette = x; });
}

template <typename Sampler>
void PathTracer::trace(PathBatch<Sampler>& batch, bool firstHits, RayCounts& counts, GuideRecorder* recorder) const {
    auto& paths = batch.paths;
    auto& hits = batch.hits;
    auto& active = batch.active;
    auto& shadows = batch.shadows;
    const uint32_t n = uint32_t(paths.size());
    if (recorder) {
        batch.guidePaths.assign(n, GuidePath{});
        for (uint32_t i = 0; i < n; ++i) paths[i].guide = &batch.guidePaths[i];
    }
    counts.camera += n;
    active.resize(n);
    for (uint32_t i = 0; i < n; ++i) active[i] = i;
    for (int depth = 0; !active.empty(); ++depth) {
        // Draw, then shade: each path's hit, keeping those that go on.
        drawVertexSamples(batch, depth, lights_.size() > 1, guide_ != nullptr);
        shadows.clear();
        size_t going = 0;
        for (size_t k = 0; k < active.size(); ++k) {
            // The hit's shading record is the first load after Embree returns, and a cache miss:
            // ask for the one a few paths ahead while this one is shaded.
            if (k + kPrefetchAhead < active.size()) {
                const Hit& ahead = hits[active[k + kPrefetchAhead]];
                if (ahead.found() && !ahead.onSphere) __builtin_prefetch(&triangles_[ahead.prim]);
            }
            const uint32_t i = active[k];
            if (shade(paths[i], hits[i], batch.draws[k], i, firstHits, shadows, counts)) active[going++] = i;
        }
        active.resize(going);
        // Shadow: a light sample's contribution counts where nothing blocks its ray. Added before
        // the path's next hit is shaded, as one path alone would.
        for (const ShadowQuery& q : shadows)
            if (!accel_.occluded(q.ray, q.distance, q.skipLight)) paths[q.path].addRadiance(q.contribution, q.guideVertices);
        // Intersect: the continuing paths' next rays.
        for (uint32_t i : active) hits[i] = accel_.intersect(paths[i].ray);
    }
    // What each guidable vertex learns: the light back along its direction times the BSDF and the
    // cosine, over its density. The product, not the light alone, is what the vertex's estimate
    // integrates: learnt, the guide leaves out grazing directions and the BSDF's dark ones.
    if (recorder)
        for (const PathState<Sampler>& p : paths) {
            if (!isFinite(p.L)) continue;
            for (int i = 0; i < p.guide->count; ++i) {
                const GuideVertex& v = p.guide->vertices[i];
                const float energy = average(v.fCos * v.radiance) / v.pdf;
                if (!(std::isfinite(energy) && energy >= 0.0f)) continue;
                recorder->record(guide_->recordKey(v.region, v.dir), energy);
                // And, where it was guided, how well each share would have sampled that light.
                if (v.share > 0.0f) recorder->recordShare(v.region, energy, v.pdf, v.bsdfPdf, v.guidePdf);
            }
        }
    for (PathState<Sampler>& p : paths) {
        if (!isFinite(p.L) || p.L.x < 0.0f || p.L.y < 0.0f || p.L.z < 0.0f) {
            ++counts.discarded;
            p.L = Spectrum(0.0f);
        } else if (settings_.clamp > 0.0f) {
            float peak = maxComponent(p.L);
            if (peak > settings_.clamp) {
                p.L *= settings_.clamp / peak;
                ++counts.clamped;
            }
        }
    }
}

template void PathTracer::trace(PathBatch<IndependentSampler>&, bool, RayCounts&, GuideRecorder*) const;
template void PathTracer::trace(PathBatch<SobolSampler>&, bool, RayCounts&, GuideRecorder*) const;

} // namespace pt
