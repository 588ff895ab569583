// The scene's lights, environment and shadow catcher in scene space (relative to the scene's origin,
// with what the path tracer samples), made from the description's and checked to stay in floats.
// sceneLights and shadowCatcherOf, which the scene's updates call too, are declared in scene.hpp.
#pragma once

#include <vector>

#include "lancer/scene/scene.hpp"

namespace lancer {

// The environment of the description's settings around `up` (a map read and checked here); an
// InputError at the settings' key for a map that is not equirectangular or a radiance no float holds.
SceneEnvironment sceneEnvironment(const EnvironmentSettings& settings, const Vec3& up);

}  // namespace lancer
