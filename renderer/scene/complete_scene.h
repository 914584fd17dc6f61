// What every loader's scene goes through, whatever its format: a camera where the file has
// none, the checks against io/scene_limits.h, glTF's default lighting, and the scene's bounds.
#pragma once

#include "io/load_error.h"
#include "scene/scene.h"

#include <string>

namespace pt {

// What loadScene does after parsing, for any format: adds the framing camera if there is none
// and warns about degenerate triangles or an empty scene.
void completeScene(Scene& scene, Warnings& warnings);

// For a glTF scene without lights (KHR_lights_punctual) or an environment (--env, --sky): a
// uniform white environment of radiance 1, with a warning. It shows base colours as they are, as
// a grey-card studio would, with soft contact shadows and no light direction to prefer; emissive
// surfaces still glow, and inside a closed room the environment never reaches. OBJ scenes keep
// the lab's two-tone sky; a glTF scene with lights gets a black environment (its lights alone).
// Call after the command line has set the environment.
void addDefaultLighting(Scene& scene, Warnings& warnings);

// "" where an orthographic camera at `position` may have half-height `halfHeight`, else why not
// ("its orthographic half-height ... is outside ..."). In double, so that a file's value that
// float would round to 0 (which means "not orthographic") meets the same rule as any other.
std::string orthoHalfHeightProblem(double halfHeight, const Vec3& position);

// Axis-aligned bounds of all triangle vertices and lights.
void sceneBounds(const Scene& scene, Vec3& lo, Vec3& hi);

} // namespace pt
