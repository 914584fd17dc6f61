// What a scene sees beyond its geometry: the lab's two tones, an HDR map or the Preetham sky with
// its sun. This is the scene's description of them; light/ samples them.
#pragma once

#include "environment/environment_map.h"
#include "environment/preetham_sky.h"
#include "environment/sun_disk.h"

#include <memory>
#include <optional>

namespace pt {

// Radiance seen by rays that leave the scene: an HDR map where one is given (it is then a light of
// the light set, sampled by next-event estimation), else the lab's two tones, `sky` for
// directions with y > 0 and `ground` below, reached by BSDF sampling only as the lab has it.
// The Preetham sky is evaluated from the model itself (the light set bakes a map of it as the
// density that samples it, environment/sky_environment.h), and the sun's disk is a light of its own.
struct Environment {
    Spectrum sky{0.5f, 0.6f, 0.7f};
    Spectrum ground{0.05f, 0.025f, 0.001f};
    std::shared_ptr<const EnvironmentMap> map;
    std::optional<SunDisk> sun;
    std::shared_ptr<const PreethamSky> preetham;

    Spectrum radiance(const Vec3& dir) const {
        if (preetham) return preetham->radiance(dir);
        if (map) return map->radiance(dir);
        return dir.y > 0.0f ? sky : ground;
    }
};

} // namespace pt
