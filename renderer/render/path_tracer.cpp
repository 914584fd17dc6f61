#include "render/path_tracer.h"

#include "render/surface_point.h"
#include "material/evaluate_material.h"

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

} // namespace

template <typename Sampler>
Spectrum PathTracer::trace(const Ray& cameraRay, const Hit& cameraHit, const Sampler& sampler, RayCounts& counts,
                           FirstHit* first) const {
    const bool sampleLights = settings_.lightSampling != LightSampling::Bsdf && !lights_.empty();
    const bool weighHits = settings_.lightSampling == LightSampling::Mis;

    Spectrum L(0.0f), beta(1.0f);
    Ray ray = cameraRay;
    float etaScale = 1.0f;     // product of radiance scalings at refractions, undone for roulette
    bool deltaBefore = true;   // camera or delta lobe before this hit: emitters seen count fully
    float prevPdf = 0.0f;      // BSDF pdf of the direction that led here (non-delta)
    Vec3 prevP(0.0f);          // where that direction started
    Vec3 prevN(0.0f);          // and the shading normal there (the light tree weighs emitters by it)
    // Ray cone for texture footprints: width at the ray's origin. It keeps the camera's spread
    // after a bounce rather than the lobe's: filtering a texture over a rough lobe's footprint
    // blurs it against the light that varies across it, a bias the crosscheck measured (+0.3 %).
    float coneWidth = 0.0f;
    ++counts.camera;

    // Weight of emission found by BSDF sampling (or by the camera) at this hit.
    auto hitWeight = [&](uint32_t emitter, float distance) {
        if (deltaBefore || !sampleLights || emitter == ~0u) return 1.0f;
        if (!weighHits) return 0.0f; // next-event estimation already counted it
        float lightPdf = lights_.pmf(emitter, prevP, prevN) * lights_.pdf(emitter, prevP, ray.dir, distance);
        return powerHeuristic(prevPdf, lightPdf);
    };

    for (int depth = 0;; ++depth) { // depth = scattering events so far
        Hit hit = depth == 0 ? cameraHit : accel_.intersect(ray);
        if (!hit.found()) {
            const Environment& env = scene_.environment;
            L += beta * env.radiance(ray.dir) * hitWeight(lights_.environmentEmitter(), kInf);
            if (env.sun && env.sun->covers(ray.dir)) L += beta * env.sun->radiance * hitWeight(lights_.sunEmitter(), kInf);
            break;
        }
        if (hit.onSphere) { // sphere lights emit and reflect nothing
            if (depth == 0 && first) {
                const SphereLight& l = scene_.lights[hit.prim];
                first->depth = hit.t;
                first->normal = glm::normalize(ray.origin + hit.t * ray.dir - l.center);
            }
            uint32_t e = lights_.emitterOfLight(hit.prim);
            L += beta * lights_.emitter(e).radiance * hitWeight(e, hit.t);
            break;
        }

        const ShadingTriangle& tri = triangles_[hit.prim];
        SurfacePoint sp = makeSurfacePoint(tri, hit);
        const Material& m = scene_.materials[sp.material];
        coneWidth += pixelSpread_ * hit.t;
        if (m.isTextured()) addTextureCoordinates(sp, tri, scene_, tangents_, hit, ray.dir, coneWidth);
        if (m.isEmissive())
            L += beta * emittedRadiance(m, *scene_.textures, sp.uv, sp.footprint) *
                 hitWeight(lights_.emitterOfTriangle(hit.prim), hit.t);
        if (depth == settings_.maxDepth) break;
        ShadingPoint shading = evaluateMaterial(m, *scene_.textures, sp, -ray.dir, settings_.hemisphere);
        const Frame& frame = shading.frame;
        const Vec3 woLocal = shading.wo;
        const Bsdf& bsdf = shading.bsdf;
        if (depth == 0 && first) {
            first->albedo = bsdf.albedo();
            first->normal = woLocal.z >= 0.0f ? frame.n : -frame.n;
            first->depth = hit.t;
        }
        if (bsdf.isBlack()) break;

        // Next-event estimation: one emitter, one point on it, one shadow ray.
        const float uLight = lights_.size() > 1 ? sampler.get1D(sampleDimension(depth, SampleUse::LightChoice)) : 0.0f;
        const Vec2 uLightPoint = sampler.get2D(sampleDimension(depth, SampleUse::LightPoint));
        if (sampleLights && bsdf.hasNonDelta()) {
            float pmf;
            uint32_t e = lights_.choose(uLight, sp.p, frame.n, pmf);
            LightSample ls = pmf > 0.0f ? lights_.sample(e, sp.p, uLightPoint) : LightSample{};
            Vec3 wiLocal = frame.toLocal(ls.wi);
            // The shading and the geometric normal must agree on the side wi leaves from, or the
            // shadow ray would start on the wrong side of the surface.
            if (ls.pdf > 0.0f && glm::dot(ls.wi, sp.ng) * wiLocal.z > 0.0f) {
                float bsdfPdf; // for MIS; evaluated with f in one pass rather than again below
                Spectrum f = bsdf.evalPdf(woLocal, wiLocal, bsdfPdf);
                if (!isBlack(f) && !isBlack(ls.radiance)) {
                    ++counts.shadow;
                    bool blocked;
                    const Emitter& em = lights_.emitter(e);
                    if (em.kind == Emitter::Kind::Triangle) {
                        Vec3 from = offsetRayOrigin(sp.p, sp.pError, sp.ng, ls.wi);
                        Vec3 to = offsetRayOrigin(ls.point, ls.pointError, ls.normal, -ls.wi);
                        Vec3 d = to - from;
                        float len = glm::length(d);
                        blocked = !(len > 0.0f) || accel_.occluded(Ray{from, d / len}, len);
                    } else {
                        int skip = em.kind == Emitter::Kind::Sphere ? int(em.index) : -1;
                        blocked = accel_.occluded(spawnRay(sp, ls.wi), ls.distance, skip);
                    }
                    if (!blocked) {
                        float w = (ls.delta || !weighHits) ? 1.0f
                                                           : powerHeuristic(pmf * ls.pdf, bsdfPdf);
                        L += beta * f * ls.radiance * (w / (pmf * ls.pdf));
                    }
                }
            }
        }

        // Sample the BSDF to continue the path.
        const float uLobe = sampler.get1D(sampleDimension(depth, SampleUse::Lobe));
        const Vec2 uDir = sampler.get2D(sampleDimension(depth, SampleUse::Direction));
        BsdfSample bs;
        if (!bsdf.sample(woLocal, uLobe, uDir, bs)) break;
        Vec3 wi = frame.toWorld(bs.wi);
        if ((glm::dot(wi, sp.ng) > 0.0f) != (bs.wi.z > 0.0f)) break; // see the shadow-ray note
        beta *= bs.weight;
        etaScale *= bs.radianceScale;
        deltaBefore = bs.delta;
        prevPdf = bs.pdf;
        prevP = sp.p;
        prevN = frame.n;

        // Russian roulette on the throughput without the refraction scaling, so paths inside
        // glass are not cut for carrying radiance that is only compressed.
        if (depth + 1 >= kRouletteDepth) {
            float q = std::min(1.0f, maxComponent(beta / etaScale));
            if (sampler.get1D(sampleDimension(depth, SampleUse::Roulette)) >= q) break;
            beta /= q;
        }
        if (isBlack(beta)) break;
        ray = spawnRay(sp, wi);
        ++counts.continuation;
    }

    if (!isFinite(L) || L.x < 0.0f || L.y < 0.0f || L.z < 0.0f) {
        ++counts.discarded;
        return Spectrum(0.0f);
    }
    if (settings_.clamp > 0.0f) {
        float peak = maxComponent(L);
        if (peak > settings_.clamp) {
            L *= settings_.clamp / peak;
            ++counts.clamped;
        }
    }
    return L;
}

template Spectrum PathTracer::trace(const Ray&, const Hit&, const IndependentSampler&, RayCounts&, FirstHit*) const;
template Spectrum PathTracer::trace(const Ray&, const Hit&, const SobolSampler&, RayCounts&, FirstHit*) const;

} // namespace pt
