#include "scene/complete_scene.h"

#include "core/system.h"
#include "environment/environment_map.h"
#include "io/scene_limits.h"

#include <algorithm>
#include <filesystem>

namespace pt {

// Bounds of the triangles' vertices alone; empty (lo > hi) without triangles.
static void triangleBounds(const Scene& scene, Vec3& lo, Vec3& hi) {
    lo = Vec3(kInf);
    hi = Vec3(-kInf);
    for (const glm::uvec3& tri : scene.triPositions)
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, scene.positions[tri[k]]);
            hi = glm::max(hi, scene.positions[tri[k]]);
        }
}

// The triangles' bounds grown by the lights' spheres; point lights (radius 0) only with
// `pointLights`.
static void boundsWithLights(const Scene& scene, bool pointLights, Vec3& lo, Vec3& hi) {
    triangleBounds(scene, lo, hi);
    for (const LocalLight& l : scene.lights)
        if (pointLights || !l.isPoint()) {
            lo = glm::min(lo, l.center - Vec3(l.radius));
            hi = glm::max(hi, l.center + Vec3(l.radius));
        }
}

void sceneBounds(const Scene& scene, Vec3& lo, Vec3& hi) { boundsWithLights(scene, true, lo, hi); }

// Looks at the bounding box of what can be seen from +z, far enough back that the box fits a 45
// degree view: the triangles and the lab's sphere lights. Point lights (radius 0, glTF's punctual
// lights) are no part of the picture, and a lamp's bulb or a light far off to one side would
// otherwise shrink the model in the frame (Blender frames the meshes alone). A scene of point
// lights alone is framed by their positions.
static Camera frameScene(const Scene& scene) {
    Vec3 lo, hi;
    boundsWithLights(scene, false, lo, hi);
    if (!(lo.x <= hi.x)) sceneBounds(scene, lo, hi);
    Camera c;
    c.name = "auto";
    if (!(lo.x <= hi.x)) return c; // nothing to frame: look down -z from the origin
    Vec3 center = 0.5f * (lo + hi);
    float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f * std::max(1.0f, glm::length(center)));
    c.fovY = 45.0f;
    float distance = radius / std::sin(glm::radians(0.5f * c.fovY));
    c.target = center;
    c.position = center + Vec3(0.0f, 0.0f, distance);
    return c;
}

std::string orthoHalfHeightProblem(double halfHeight, const Vec3& position) {
    float distance = std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)});
    double least = std::max(kMinSceneSize, kMinOrthoFraction * distance);
    if (halfHeight >= least && halfHeight <= kMaxCoordinate) return "";
    return "its orthographic half-height " + shortNumber(halfHeight) + " is outside [" + shortNumber(least) +
           ", 1e12]: below, neighbouring pixels' rays start at one float point (1e-4 of its distance from the origin, "
           "and at least 1e-6)";
}

static bool withinCoordinates(const Vec3& p) {
    return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.z) <= kMaxCoordinate;
}

// A camera as PinholeCamera will use it, in float: each format checks its own fields, but a
// value that passes in the file's precision can still collapse here (an up vector parallel to
// the view to 1e-45, a position at 1e19) and make rays Embree refuses.
static void checkCamera(const Scene& scene, const Camera& c) {
    std::string what = scene.path + ": camera \"" + c.name + "\": ";
    if (!withinCoordinates(c.position) || !withinCoordinates(c.target))
        throw LoadError(what + "its position or target lies beyond 1e12, the largest coordinate pt renders correctly");
    Vec3 forward = safeNormalize(c.target - c.position);
    if (forward == Vec3(0.0f)) throw LoadError(what + "it looks nowhere (its target is its position)");
    if (!(safeLength(glm::cross(forward, safeNormalize(c.up))) > 1e-6f))
        throw LoadError(what + "its up direction is zero or parallel to its view direction");
    if (c.orthoHalfHeight > 0.0f) {
        if (std::string problem = orthoHalfHeightProblem(c.orthoHalfHeight, c.position); !problem.empty())
            throw LoadError(what + problem);
    } else if (!(c.fovY >= kMinFieldOfView && c.fovY < 180.0f)) {
        throw LoadError(what + "its field of view " + shortNumber(c.fovY) + " degrees is outside [0.01, 180), where "
                        "neighbouring pixels' ray directions differ in float");
    }
    if (c.aspect != 0.0f && !(c.aspect >= 1.0f / kMaxAspect && c.aspect <= kMaxAspect))
        throw LoadError(what + "its aspect ratio " + shortNumber(c.aspect) + " is outside [1/65536, 65536]");
}

// A float texture can hold any value: a map multiplies its factor by its largest texel, and the
// product must stay within the limit the factor alone is held to.
static void checkMaps(const Scene& scene, const Material& m) {
    auto check = [&](const TextureMap& map, double factor, double limit, const char* what, const char* limitText) {
        if (!map.used()) return;
        const Texture& t = (*scene.textures)[map.texture];
        if (!(double(t.peak) * factor <= limit))
            throw LoadError(scene.path + ": material \"" + m.name + "\": its " + what + " texture \"" + t.path + "\" reaches " +
                            shortNumber(t.peak) + ", which times its factor " + shortNumber(factor) + " passes " + limitText);
    };
    check(m.kdMap, maxComponent(m.kd), kMaxReflectance, "diffuse or base colour", "the reflectance limit 10");
    check(m.ksMap, maxComponent(m.ks), kMaxReflectance, "specular colour", "the reflectance limit 10");
    check(m.emissionMap, maxComponent(m.emission), kMaxRadiance, "emission", "the radiance limit 1e18");
    check(m.normalMap, std::abs(m.normalMap.bumpScale), kMaxNormalScale, "normal", "1e6, where normals overflow float");
    check(m.bumpMap, std::abs(m.bumpMap.bumpScale), kMaxNormalScale, "bump", "1e6, where normals overflow float");
    for (const MaterialMapEntry& e : kMaterialMaps) {
        const TextureMap* map = &(m.*e.map);
        const char* what = e.what;
        float peak = std::max({std::abs(map->linear[0].x), std::abs(map->linear[0].y), std::abs(map->linear[1].x),
                               std::abs(map->linear[1].y), std::abs(map->offset.x), std::abs(map->offset.y)});
        if (map->used() && !(peak <= kMaxTextureTransform))
            throw LoadError(scene.path + ": material \"" + m.name + "\": its " + what + " texture's coordinate transform has " +
                            shortNumber(peak) + ", beyond +-1e4, where float texture coordinates no longer address single "
                            "texels (MTL -s and -o, glTF KHR_texture_transform)");
    }
}

// The limits of io/scene_limits.h that depend on the size of the whole scene.
static void checkSceneLimits(const Scene& scene) {
    Vec3 lo, hi;
    triangleBounds(scene, lo, hi);
    if (lo.x <= hi.x) {
        float size = safeLength(hi - lo);
        if (size < kMinSceneSize)
            throw LoadError(scene.path + ": the scene's triangles span only " + shortNumber(size) +
                            " across; pt renders scenes of at least 1e-6 correctly (Embree's float ray test "
                            "loses hits below it); scale the scene up");
    }
    Vec3 all_lo, all_hi;
    sceneBounds(scene, all_lo, all_hi);
    for (const Camera& c : scene.cameras) {
        all_lo = glm::min(all_lo, c.position);
        all_hi = glm::max(all_hi, c.position);
    }
    float size = all_lo.x <= all_hi.x ? safeLength(all_hi - all_lo) : 0.0f;
    for (const Camera& c : scene.cameras) checkCamera(scene, c);
    for (const Material& m : scene.materials) checkMaps(scene, m);
    for (const DirectionalLight& d : scene.directionalLights)
        if (!(maxComponent(d.irradiance) <= kMaxRadiance))
            throw LoadError(scene.path + ": directional light \"" + d.name + "\": irradiance " +
                            shortNumber(maxComponent(d.irradiance)) + " is beyond 1e18, where samples overflow float");
    for (const LocalLight& l : scene.lights) {
        if (!withinCoordinates(l.center))
            throw LoadError(l.source + "light \"" + l.name + "\": it lies beyond 1e12, the largest coordinate pt renders correctly");
        if (l.range > 0.0f && l.range < kMinLightRadiusFraction * size)
            throw LoadError(l.source + "light \"" + l.name + "\": range " + shortNumber(l.range) + " is below 1e-12 of the "
                            "scene's size (" + shortNumber(size) + "); it would light nothing");
        float peak = maxComponent(l.intensity);
        if (l.isPoint()) {
            double limit = double(kMaxRadiance) * sqr(kPointLightDistanceFraction * std::max(size, kMinSceneSize));
            if (peak > limit)
                throw LoadError(l.source + "light \"" + l.name + "\": " + l.intensityKeyword + " " + shortNumber(peak) +
                                " of a point light in a scene " + shortNumber(size) + " across is beyond " +
                                shortNumber(limit) + " (1e18 x (size/10)^2), where samples overflow float");
        } else if (l.radius < kMinLightRadiusFraction * size) {
            throw LoadError((l.radiusSource.empty() ? l.source : l.radiusSource) + "light \"" + l.name +
                            "\": lightradius " + shortNumber(l.radius) + " is below 1e-12 of the scene's size (" +
                            shortNumber(size) + "), where its solid angle underflows float; use 0 for a point light");
        }
    }
}

static bool isGltf(const std::string& path) {
    std::string ext = toLower(std::filesystem::path(path).extension().string());
    return ext == ".gltf" || ext == ".glb";
}

void addDefaultLighting(Scene& scene, Warnings& warnings) {
    if (!isGltf(scene.path) || scene.environment.map || scene.environment.preetham) return;
    if (!scene.lights.empty() || !scene.directionalLights.empty()) {
        scene.environment.sky = scene.environment.ground = Spectrum(0.0f); // the file's lights alone
        return;
    }
    auto white = std::make_shared<EnvironmentMap>();
    white->path = "(uniform white)";
    white->width = 4;
    white->height = 2;
    white->rgb.assign(4 * 2 * 3, 1.0f);
    scene.environment.map = white;
    warnings.add(scene.path + ": the file has no lights; lighting it with a uniform white environment of radiance 1 "
                              "(give --env or --sky to light it otherwise)");
}

void completeScene(Scene& scene, Warnings& warnings) {
    const std::string& path = scene.path;
    if (scene.cameras.empty()) {
        scene.cameras.push_back(frameScene(scene));
        warnings.add(path + (isGltf(path) ? ": no camera defined; framing the whole scene from +z (--camera picks "
                                            "one where the file has cameras)"
                                          : ": no camera defined; framing the whole scene from +z (add a newcamera "
                                            "block to the MTL to choose the view)"));
    }
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (scene.cameras[i].name == scene.cameras[j].name)
                warnings.once("camera name:" + scene.cameras[i].name,
                              path + ": cameras " + std::to_string(j) + " and " + std::to_string(i) + " are both named \"" +
                                  scene.cameras[i].name + "\"; --camera picks them by index");
    size_t degenerate = 0;
    for (const glm::uvec3& tri : scene.triPositions) {
        const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]], &c = scene.positions[tri[2]];
        degenerate += !(safeLength(glm::cross(b - a, c - a)) > 0.0f);
    }
    if (degenerate > 0)
        warnings.add(path + ": " + std::to_string(degenerate) + " of " + std::to_string(scene.triangleCount()) +
                     " triangles have zero area; rays never hit them");
    checkSceneLimits(scene);
    if (scene.triangleCount() == 0 && scene.lights.empty() && scene.directionalLights.empty())
        warnings.add(path + ": the scene has no geometry and no lights; only the environment will show");
}

} // namespace pt
