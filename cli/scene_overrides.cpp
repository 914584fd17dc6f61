#include "cli/scene_overrides.h"
#include "cli/args.h"
#include "scene/complete_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>

namespace pt::cli {

void applySceneOverrides(Scene& scene, const RenderArgs& args, Warnings& warnings) {
    if (!args.env.empty()) {
        try {
            std::string warning;
            scene.environment = Environment{}; // replaces the MTL's environment, a sky included
            auto map = std::make_shared<const EnvironmentMap>(
                readEnvironmentMap(args.env, float(args.envRotate), float(args.envScale), warning));
            scene.environment.map = map;
            scene.sources.push_back({args.env, map->sourceHash});
            if (!warning.empty()) warnings.add(warning);
        } catch (const std::bad_alloc&) {
            throw LoadError(args.env + ": out of memory while reading the environment map");
        }
    }
    if (args.sky) {
        scene.environment = skyEnvironment(args.skyParameters);
        if (args.skyParameters.sunDirection.y < 0.0f)
            warnings.add("the sun is below the horizon: the model has no twilight, so the sky is that of a sun on the "
                         "horizon and the sun's disk is hidden");
    }
    addDefaultLighting(scene, warnings);
    if (args.settings.hemisphere == HemisphereSampling::Uniform) {
        // Only the lab model's Lambert lobe has the choice; glTF's BRDF samples its diffuse lobe
        // by the cosine always (its transmitting materials go through the lab model and take it).
        size_t ignoring = 0;
        for (const Material& m : scene.materials) ignoring += m.model == MaterialModel::MetalRough && !(m.transparency > 0.0f);
        if (ignoring > 0)
            warnings.add("--hemisphere uniform: " + std::to_string(ignoring) + " of the scene's " +
                         std::to_string(scene.materials.size()) + " materials (glTF metallic-roughness) ignore it and "
                         "sample their diffuse lobe by the cosine");
    }
}

size_t pickCamera(const Scene& scene, const std::string& spec) {
    if (spec.empty()) return 0;
    std::vector<size_t> named;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == spec) named.push_back(i);
    bool numeric = spec.find_first_not_of("0123456789") == std::string::npos && spec.size() < 9;
    size_t index = numeric ? std::stoul(spec) : scene.cameras.size();
    bool isIndex = index < scene.cameras.size();
    if (named.size() > 1)
        throw UsageError("--camera " + spec + ": cameras " + std::to_string(named[0]) + " and " + std::to_string(named[1]) +
                         " are both named \"" + spec + "\"; give the index of the one to render");
    if (named.size() == 1 && isIndex && named[0] != index)
        throw UsageError("--camera " + spec + ": camera " + std::to_string(named[0]) + " is named \"" + spec + "\", and camera " +
                         spec + " is another; rename one of them");
    if (named.size() == 1) return named[0];
    if (isIndex) return index;
    std::string names;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " \"" + scene.cameras[i].name + "\"";
    throw UsageError("--camera " + spec + ": no such camera; the scene has " + names);
}

void sizeForCamera(const Camera& camera, RenderArgs& args) {
    if (float aspect = camera.aspect; aspect > 0.0f && !args.resGiven) {
        if (aspect >= 1.0f) args.height = std::max(1, int(std::lround(512.0f / aspect)));
        else args.width = std::max(1, int(std::lround(512.0f * aspect)));
    }
}

} // namespace pt::cli
