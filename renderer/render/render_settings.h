// Options that change how a path is traced (not where the image goes).
#pragma once

#include "light/light_tree.h"
#include "material/bsdf_sample.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace pt {

// Which estimators of direct light a path uses. Mis is the default: the other two exist for the
// convergence study and for users who want to see what each strategy alone does.
enum class LightSampling { Mis, Nee, Bsdf };

// Where sample values come from: independent random numbers, or Owen-scrambled Sobol points.
enum class SamplerKind { Random, Sobol };

// Each setting's values by the name the command line and the EXR metadata give them: one table
// per enum, read both ways.
template <typename E>
struct NamedValue {
    E value;
    const char* name;
};
inline constexpr NamedValue<LightSampling> kLightSamplingNames[] = {
    {LightSampling::Mis, "mis"}, {LightSampling::Nee, "nee"}, {LightSampling::Bsdf, "bsdf"}};
inline constexpr NamedValue<LightChoice> kLightChoiceNames[] = {
    {LightChoice::Auto, "auto"}, {LightChoice::Power, "power"}, {LightChoice::Tree, "tree"}};
inline constexpr NamedValue<HemisphereSampling> kHemisphereNames[] = {
    {HemisphereSampling::Cosine, "cosine"}, {HemisphereSampling::Uniform, "uniform"}};
inline constexpr NamedValue<SamplerKind> kSamplerNames[] = {{SamplerKind::Sobol, "sobol"}, {SamplerKind::Random, "random"}};

template <typename E, size_t N>
const char* nameOf(const NamedValue<E> (&table)[N], E value) {
    for (const NamedValue<E>& v : table)
        if (v.value == value) return v.name;
    return "?";
}
// Sets `value` from its name; false for a name not in the table.
template <typename E, size_t N>
bool valueNamed(const NamedValue<E> (&table)[N], std::string_view name, E& value) {
    for (const NamedValue<E>& v : table)
        if (name == v.name) return value = v.value, true;
    return false;
}
// "a, b or c", for messages.
template <typename E, size_t N>
std::string namesOf(const NamedValue<E> (&table)[N]) {
    std::string s;
    for (size_t i = 0; i < N; ++i) s += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(table[i].name);
    return s;
}

struct RenderSettings {
    int maxDepth = 16;   // most scattering events on a path: 0 = emitters seen directly, 1 = direct light
    uint64_t seed = 0;
    LightSampling lightSampling = LightSampling::Mis;
    LightChoice lightChoice = LightChoice::Auto;
    HemisphereSampling hemisphere = HemisphereSampling::Cosine;
    SamplerKind sampler = SamplerKind::Sobol;
    // Opt-in firefly clamp: a sample whose largest channel exceeds `clamp` is scaled down to it.
    // Biased (energy is lost); 0 keeps the default, unbiased estimate.
    float clamp = 0.0f;
    // --guide: samples per pixel spent learning the path guide before the render (0: no guiding).
    uint32_t guideSpp = 0;
};

// Ray and sample counts, summed per tile and then over the image.
struct RayCounts {
    uint64_t camera = 0;
    uint64_t continuation = 0; // rays after a scattering event (BSDF-sampled)
    uint64_t shadow = 0;
    uint64_t discarded = 0; // samples that came out NaN, infinite or negative and were dropped
    uint64_t clamped = 0;   // samples scaled down by RenderSettings::clamp

    uint64_t total() const { return camera + continuation + shadow; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        continuation += o.continuation;
        shadow += o.shadow;
        discarded += o.discarded;
        clamped += o.clamped;
        return *this;
    }
};

} // namespace pt
