// `--look studio|sky|sun`: a lit scene from one option, for a bare mesh or a scene file. Each look
// is the path integrator with a scene-file snippet's lights, environment and shadow-catching floor
// (docs/lighting.md shows them), set relative to the camera so the key light falls from its
// upper left, as the quick look's does.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

enum class Look { Studio, Sky, Sun };
inline constexpr std::array<std::string_view, 3> kLookNames = {"studio", "sky", "sun"};

// Replaces the description's lights, ambient and environment by the look's, adds its floor (a
// shadow catcher under the scene, across the camera's up), and renders with the path integrator
// (64 samples per pixel, noise 0.02, unless the scene asked for more). Meshes coloured by a field
// lose their materials' highlights (ks), so that their colours keep the map's saturation.
void applyLook(SceneDescription& description, Look look);

}  // namespace lancer
