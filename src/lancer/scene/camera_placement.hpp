// Where the automatic camera stands when a scene gives no position: needed by the camera itself, by
// orbits that start from it, and by the quick look, which puts its fill light there.
#pragma once

#include "lancer/math/aabb.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// From `settings.viewFrom` (the 3/4 view from the front-right-above for y up), far enough that the
// bounding sphere of `worldBounds` fits the field of view at this aspect (width / height).
Vec3d defaultCameraPosition(const Aabbd& worldBounds, const CameraSettings& settings, double aspect);

}  // namespace lancer
