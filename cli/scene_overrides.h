// What pt render's options change in a loaded scene: --env or --sky in place of its environment,
// default lighting where it has none, the camera --camera picks and the size its aspect asks for.
#pragma once

#include "cli/render_options.h"
#include "io/load_error.h"
#include "scene/scene.h"

#include <string>

namespace pt::cli {

// Applies --env (read here: a LoadError names what is wrong with it), --sky and the scene's
// default lighting, and warns where an option does not reach every material.
void applySceneOverrides(Scene& scene, const RenderArgs& args, Warnings& warnings);

// --camera: a name or a 0-based index; none given is camera 0. A spec that names two cameras,
// or names one camera and is the index of another, is refused rather than resolved silently.
// A UsageError names what is wrong with the spec.
size_t pickCamera(const Scene& scene, const std::string& spec);

// A camera that asks for an aspect ratio (glTF) gets it unless --res says otherwise: 512 pixels
// across its longer side.
void sizeForCamera(const Camera& camera, RenderArgs& args);

} // namespace pt::cli
