#include "scene/scene_loader.h"

#include "scene/obj_loader.h"
#include "scene/text_parser.h"

#include <filesystem>

namespace pt {

void sceneBounds(const Scene& scene, Vec3& lo, Vec3& hi) {
    lo = Vec3(kInf);
    hi = Vec3(-kInf);
    for (const glm::uvec3& tri : scene.triPositions)
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, scene.positions[tri[k]]);
            hi = glm::max(hi, scene.positions[tri[k]]);
        }
    for (const SphereLight& l : scene.lights) {
        lo = glm::min(lo, l.center - Vec3(l.radius));
        hi = glm::max(hi, l.center + Vec3(l.radius));
    }
}

// Looks at the bounding box from +z, far enough back that the box fits a 45 degree view.
static Camera frameScene(const Scene& scene) {
    Vec3 lo, hi;
    sceneBounds(scene, lo, hi);
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

Scene loadScene(const std::string& path, Warnings& warnings) {
    std::string ext = toLower(std::filesystem::path(path).extension().string());
    Scene scene;
    if (ext == ".obj") {
        scene = loadObj(path, warnings);
    } else {
        throw LoadError(path + ": unsupported scene format \"" + ext + "\"; expected .obj");
    }
    completeScene(scene, warnings);
    return scene;
}

void completeScene(Scene& scene, Warnings& warnings) {
    const std::string& path = scene.path;
    if (scene.cameras.empty()) {
        scene.cameras.push_back(frameScene(scene));
        warnings.add(path + ": no camera defined; framing the whole scene from +z (add a newcamera "
                            "block to the MTL to choose the view)");
    }
    size_t degenerate = 0;
    for (const glm::uvec3& tri : scene.triPositions) {
        const Vec3 &a = scene.positions[tri[0]], &b = scene.positions[tri[1]], &c = scene.positions[tri[2]];
        degenerate += !(glm::length(glm::cross(b - a, c - a)) > 0.0f);
    }
    if (degenerate > 0)
        warnings.add(path + ": " + std::to_string(degenerate) + " of " + std::to_string(scene.triangleCount()) +
                     " triangles have zero area; rays never hit them");
    if (scene.triangleCount() == 0 && scene.lights.empty())
        warnings.add(path + ": the scene has no geometry and no lights; only the environment will show");
}

} // namespace pt
