// A scene file's [animation] table: frames, fps, what orbits (the camera or a light) and about what,
// and the keys of an animation over time steps (result_keys.hpp).
#pragma once

#include <cstddef>
#include <string>

#include <toml++/toml.h>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// `path` is the scene file, for messages; `lightCount` the scene's [[light]] tables (orbit = "light:K").
AnimationSettings readAnimation(const toml::table& table, const std::string& path, std::size_t lightCount);

}  // namespace lancer
