// What the staged path loop (path_tracer.h) keeps of each path between its stages, and the shadow
// rays next-event estimation leaves for the shadow stage. Plain values in flat arrays, one slot
// per path of a batch, reused from batch to batch.
#pragma once

#include "accel/accel.h"
#include "core/color.h"
#include "render/medium.h"

namespace pt {

// The albedo, normal and depth layers: the features the denoiser is guided by. Depth is the
// camera ray's hit. Albedo and normal are those of the first surface that is not perfectly
// specular: through mirrors and smooth glass the path is followed (as OIDN's documentation and
// Cycles do), so that what is seen in them or behind them keeps its edges and texture.
struct FirstHit {
    Spectrum albedo{0.0f}; // Bsdf::albedo at wo (each lobe's colour times its share), times tint
    Vec3 normal{0.0f};     // shading normal, turned to face the ray
    float depth = kInf;    // distance along the camera ray
    Spectrum tint{1.0f};   // what the perfectly specular surfaces passed so far let through
    bool open = true;      // only perfectly specular surfaces so far: albedo and normal may change
};

// A training pass's record of one path (--guide): the vertices where it could have been guided,
// each with the light that came back along the direction it left in, credited as the path finds
// that light. A path records its first kMaxVertices such vertices.
struct GuideVertex {
    uint32_t region;
    Vec3 dir;           // world direction the path left in
    float pdf;          // its density
    Spectrum betaAfter; // throughput after this vertex's BSDF weight (before roulette)
    Spectrum fCos;      // the BSDF's value times the cosine: what the light back along dir is learnt times
    float bsdfPdf;      // where the vertex was guided (share > 0), the density's two parts
    float guidePdf;     // (scatter.h's ScatterParts)
    float share;        // the guide's share of the draw, 0 where the region had learnt nothing yet
    Spectrum radiance{0.0f};
};
struct GuidePath {
    static constexpr int kMaxVertices = 8;
    GuideVertex vertices[kMaxVertices];
    int count = 0;
    bool lastIsPrevious = false; // the last vertex recorded is the one the path just left
    // Light the path gathered (throughput included) reaches vertices [0, upTo) along their
    // directions: each receives it divided by its own throughput.
    void credit(const Spectrum& contribution, int upTo) {
        for (int i = 0; i < upTo; ++i)
            for (int c = 0; c < 3; ++c)
                if (vertices[i].betaAfter[c] > 0.0f) vertices[i].radiance[c] += contribution[c] / vertices[i].betaAfter[c];
    }
};

template <typename Sampler>
struct PathState {
    Sampler sampler;          // this path's (pixel, sample index, seed)
    Ray ray;                  // the ray whose hit the next shade stage reads
    Spectrum L{0.0f};         // radiance gathered so far
    Spectrum beta{1.0f};      // throughput
    Vec3 prevP{0.0f};         // where the ray started (MIS of emitters it hits)
    Vec3 prevN{0.0f};         // and the shading normal there (the light tree weighs emitters by it)
    float prevPdf = 0.0f;     // BSDF pdf of the ray's direction (non-delta)
    float etaScale = 1.0f;    // product of radiance scalings at refractions, undone for roulette
    // The product, over the path's guided vertices, of the BSDF's density over the mixed one at
    // the direction taken: how many times guiding has scaled the throughput above what the
    // BSDF's own sampling would have given it (scatter.h's kMaxGuideGain bounds it).
    float guideGain = 1.0f;
    // Ray cone for texture footprints: width at the ray's origin. It keeps the camera's spread
    // after a bounce rather than the lobe's: filtering a texture over a rough lobe's footprint
    // blurs it against the light that varies across it, a bias the crosscheck measured (+0.3 %).
    float coneWidth = 0.0f;
    int depth = 0;            // scattering events so far
    uint32_t medium = kAir;   // material whose volume the ray travels in (medium.h)
    bool deltaBefore = true;  // camera or delta lobe before this hit: emitters seen count fully
    bool kept = true;         // whether the image keeps the path's light (a training pass keeps only some)
    uint32_t pixel = 0;       // the caller's index of the pixel the path belongs to
    FirstHit first;
    GuidePath* guide = nullptr; // a training pass's record of the path, or none

    // Adds light the path found to its estimate and, in training, to its first `credited`
    // recorded vertices.
    void addRadiance(const Spectrum& contribution, int credited) {
        L += contribution;
        if (guide) [[unlikely]] guide->credit(contribution, credited);
    }
    // Emitted light the path found along its ray: every recorded vertex learns from it, except
    // that light next-event estimation could have sampled from the vertex the path just left is
    // not that vertex's to learn: the guide is for the light NEE cannot find, and learning the
    // lamps would send guided samples where NEE already looks.
    void addEmitted(const Spectrum& contribution, bool neeCovers) {
        addRadiance(contribution, guide ? guide->count - int(neeCovers && guide->lastIsPrevious) : 0);
    }
};

// A vertex's sample values, one per decision (sampler.h's SampleUse), drawn for all paths of a
// round together before they are shaded.
struct VertexDraws {
    float lightChoice;
    Vec2 lightPoint;
    float lobe;
    Vec2 direction;
    float roulette;
    float guide; // guided renders: the BSDF or the guide (scatter.h)
};

// A shadow ray of next-event estimation, with what it adds to its path's radiance if unblocked.
struct ShadowQuery {
    Ray ray;
    float distance;
    int skipLight;           // sphere light the ray is aimed at (Accel::occluded), or -1
    uint32_t path;           // slot of the path in its batch
    Spectrum contribution;
    int guideVertices = 0;   // training: the path's vertices before the one that sent it
};

} // namespace pt
