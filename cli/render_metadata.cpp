#include "cli/render_metadata.h"
#include "core/system.h"
#include "render/film_part.h"
#include "render/render_job.h"

#include <algorithm>
#include <filesystem>

namespace pt::cli {

void addJobMetadata(Image& image, const RenderArgs& args, const Scene& scene, size_t cameraIndex,
                    const std::string& sceneHash) {
    JobMetadataWriter write(image);
    auto text = [&](const char* k, const std::string& v) { write.text(k, v); };
    auto integer = [&](const char* k, long long v) { write.integer(k, v); };
    auto real = [&](const char* k, double v) { write.real(k, v); };
    std::error_code ec;
    std::string resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(scene.path, ec), ec).string();
    text("Software", "pt " PT_VERSION);
    text("pt:version", PT_VERSION);
    text("pt:scene", args.scene);
    text("pt:sceneResolved", ec ? args.scene : resolved);
    text("pt:sceneHash", sceneHash);
    integer("pt:fullWidth", args.width);
    integer("pt:fullHeight", args.height);
    text("pt:camera", scene.cameras[cameraIndex].name);
    integer("pt:cameraIndex", (long long)cameraIndex); // two cameras may share a name
    if (const auto& preetham = scene.environment.preetham) { // from --sky or the MTL
        const SkyParameters* sky = &preetham->parameters();
        const Vec3& d = sky->sunDirection;
        text("pt:environment", "preetham");
        text("pt:sunDirection", shortNumber(d.x) + "," + shortNumber(d.y) + "," + shortNumber(d.z));
        real("pt:sunElevation", sunElevationDegrees(d));
        real("pt:sunAzimuth", sunAzimuthDegrees(d));
        real("pt:turbidity", sky->turbidity);
        real("pt:skyScale", sky->scale);
    } else if (const auto& map = scene.environment.map) { // from --env or the MTL
        text("pt:env", map->path);
        real("pt:envRotate", double(map->rotation()) * 180.0 / kPi);
        real("pt:envScale", map->scale);
    }
    integer("pt:sppRequested", args.spp);
    integer("pt:seed", (long long)args.settings.seed);
    integer("pt:maxDepth", args.settings.maxDepth);
    text("pt:sampler", nameOf(kSamplerNames, args.settings.sampler));
    text("pt:lightSampling", nameOf(kLightSamplingNames, args.settings.lightSampling));
    text("pt:lightChoice", nameOf(kLightChoiceNames, args.settings.lightChoice));
    text("pt:hemisphere", nameOf(kHemisphereNames, args.settings.hemisphere));
    real("pt:clamp", args.settings.clamp);
    if (args.settings.guideSpp > 0) integer("pt:guideSpp", args.settings.guideSpp);
    real("pt:exposure", args.exposure);
    if (args.budget.adaptive()) { // a part must be resumed and merged with the same rule
        real("pt:noise", args.budget.noise);
        integer("pt:minSpp", std::min<long long>(args.budget.minSpp, args.spp));
    }
}

void addRunMetadata(Image& image, const RenderArgs& args, const RenderResult& result, int threads,
                    uint32_t first, uint32_t last, const PixelWindow& window, bool part) {
    auto integer = [&](const char* k, long long v) { image.metadata.push_back(ImageAttribute::integerValue(k, v)); };
    const Film& film = result.film;
    const Film::SampleCounts counts = film.sampleCounts();
    image.metadata.push_back(ImageAttribute::integerValue("pt:spp", counts.fewest));
    if (counts.most != counts.fewest) { // adaptive, or a resumed part: per pixel in --aov spp
        integer("pt:sppMax", counts.most);
        image.metadata.push_back(ImageAttribute::floatValue("pt:sppMean", counts.mean));
    }
    if (film.hasConvergence()) integer("pt:converged", (long long)film.convergedCount());
    if (args.budget.seconds > 0.0) {
        image.metadata.push_back(ImageAttribute::floatValue("pt:time", args.budget.seconds));
        integer("pt:outOfTime", result.outOfTime ? 1 : 0);
    }
    if (args.settings.guideSpp > 0) { // what the guide learnt from (fewer under --time), its size, what it guides
        integer("pt:guideTrained", result.guideSpp);
        integer("pt:guideBytes", (long long)result.guideBytes);
        image.metadata.push_back(ImageAttribute::floatValue("pt:guidedFraction", float(result.guidedFraction)));
    }
    integer("pt:threadsRequested", args.threads);
    integer("pt:threads", threads);
    image.metadata.push_back(ImageAttribute::floatValue("pt:renderSeconds", result.seconds));
    if (!part) return;
    addPartLayers(image, result.film);
    image.x = window.x0, image.y = window.y0;
    image.fullWidth = args.width, image.fullHeight = args.height;
    integer("pt:part", 1);
    integer("pt:samplesFirst", first);
    integer("pt:samplesLast", last);
}

} // namespace pt::cli
