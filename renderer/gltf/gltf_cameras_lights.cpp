#include "gltf/gltf_cameras_lights.h"
#include "core/math.h"
#include "core/system.h"
#include "io/load_error.h"
#include "io/scene_limits.h"
#include "scene/complete_scene.h"

#include <cmath>

namespace pt::gltf {
namespace {

// Lumens per watt: glTF lights are photometric (candela, lux), pt's radiometric. Blender's glTF
// importer divides by the same 683, so a scene is as bright in both.
constexpr double kLumensPerWatt = 683.0;

// A camera's aspect ratio, checked in double: one that float rounds to 0 (which means "none
// given") or to infinity is refused as any other outside the range.
float aspectOf(const std::string& path, const Camera& c, double aspect) {
    if (!(aspect >= 1.0 / kMaxAspect && aspect <= kMaxAspect))
        throw LoadError(path + ": camera \"" + c.name + "\": its aspect ratio " + shortNumber(aspect) +
                        " is outside [1/65536, 65536]");
    return float(aspect);
}

} // namespace

void addCamera(const tinygltf::Model& model, const std::string& path, int index, const glm::dmat4& world,
               const std::string& where, Scene& scene) {
    if (size_t(index) >= model.cameras.size())
        throw LoadError(where + ": camera " + std::to_string(index) + " does not exist");
    const tinygltf::Camera& g = model.cameras[size_t(index)];
    std::string what = path + ": camera " + std::to_string(index);
    Camera c;
    c.name = g.name.empty() ? "camera " + std::to_string(index) : g.name;
    glm::dvec3 eye(world * glm::dvec4(0, 0, 0, 1)), ahead(world * glm::dvec4(0, 0, -1, 0)), up(world * glm::dvec4(0, 1, 0, 0));
    if (!(glm::length(ahead) > 0.0) || !(glm::length(glm::cross(ahead, up)) > 0.0))
        throw LoadError(what + ": its node's transform collapses the view direction");
    c.position = Vec3(eye);
    c.target = Vec3(eye + glm::normalize(ahead));
    c.up = Vec3(glm::normalize(up));
    if (g.type == "perspective") {
        double fov = g.perspective.yfov * 180.0 / M_PI;
        if (!(fov > 0.0 && fov < 180.0)) throw LoadError(what + ": yfov " + shortNumber(g.perspective.yfov) + " must be in (0, pi)");
        c.fovY = float(fov);
        if (g.perspective.aspectRatio > 0.0) c.aspect = aspectOf(path, c, g.perspective.aspectRatio);
    } else { // orthographic: gltf_document allows no other type
        double ymag = std::abs(g.orthographic.ymag), xmag = std::abs(g.orthographic.xmag);
        if (!(ymag > 0.0 && xmag > 0.0)) throw LoadError(what + ": xmag and ymag must not be zero");
        // A value float loses (to 0, which means "not orthographic", or to a denormal) meets
        // checkCamera's rule here, named as the file gives it.
        if (float h = float(ymag); !(std::isnormal(h) && h <= kMaxCoordinate))
            throw LoadError(path + ": camera \"" + c.name + "\": " + orthoHalfHeightProblem(ymag, c.position));
        c.orthoHalfHeight = float(ymag);
        c.aspect = aspectOf(path, c, xmag / ymag);
    }
    scene.cameras.push_back(c);
}

void addLight(const tinygltf::Model& model, const std::string& path, int index, const glm::dmat4& world,
              const std::string& where, Scene& scene) {
    if (index < 0 || size_t(index) >= model.lights.size())
        throw LoadError(where + ": light " + std::to_string(index) + " does not exist");
    const tinygltf::Light& g = model.lights[size_t(index)];
    std::string what = path + ": light " + std::to_string(index) + (g.name.empty() ? "" : " \"" + g.name + "\"");
    Spectrum color = colorOf(g.color, Spectrum(1.0f)); // in [0, 1], as gltf_document checked
    if (!(g.intensity < 1e15)) throw LoadError(what + ": intensity " + shortNumber(g.intensity) + " is beyond 1e15, pt's limit");
    glm::dvec3 at(world * glm::dvec4(0, 0, 0, 1)), ahead(world * glm::dvec4(0, 0, -1, 0));
    if (g.type == "directional") {
        if (!(glm::length(ahead) > 0.0)) throw LoadError(what + ": its node's transform collapses its direction");
        DirectionalLight d;
        d.name = g.name;
        d.direction = Vec3(glm::normalize(-ahead)); // towards the light
        d.irradiance = color * float(g.intensity / kLumensPerWatt); // lux to W/m^2
        scene.directionalLights.push_back(d);
        return;
    }
    LocalLight l;
    l.name = "light " + std::to_string(index) + (g.name.empty() ? "" : " " + g.name);
    l.center = Vec3(at);
    l.radius = 0.0f;
    l.intensity = color * float(g.intensity / kLumensPerWatt); // candela to W/sr
    l.range = float(g.range);
    if (g.range > 0.0 && !(l.range > 0.0f && std::isfinite(l.range)))
        throw LoadError(what + ": range " + shortNumber(g.range) + " underflows float (0 would mean no range)");
    l.source = path + ": ";
    l.intensityKeyword = "intensity";
    if (g.type == "spot") {
        double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2))
            throw LoadError(what + ": spot cone angles must satisfy 0 <= inner < outer <= pi/2");
        if (!(glm::length(ahead) > 0.0)) throw LoadError(what + ": its node's transform collapses its direction");
        l.spotDirection = Vec3(glm::normalize(ahead));
        l.cosInner = float(std::cos(inner));
        l.cosOuter = float(std::cos(outer));
        // In float the cone must still be a cone: a narrower one is a point light in disguise.
        if (!(l.cosOuter < l.cosInner))
            throw LoadError(what + ": spot cone angles " + shortNumber(inner) + " and " + shortNumber(outer) +
                            " have the same cosine in float; make the outer cone wider");
    }
    scene.lights.push_back(l);
}

} // namespace pt::gltf
