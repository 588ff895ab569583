// Reads a TOML scene file (render, camera, lights, materials, meshes, optics, sampling, animation and
// cut-view keys, as examples/*.toml show them) into a checked SceneDescription; every error points
// at the offending key or value as file:line:col.
#pragma once

#include <string>
#include <string_view>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// Reads and parses the file at `path`. Throws InputError (nothing is printed).
SceneDescription loadScene(const std::string& path);

// Parses scene text as if read from `path`: messages name `path`, relative paths in the scene are
// resolved against its folder. Throws InputError.
SceneDescription parseScene(std::string_view text, const std::string& path);

// Material 0 of every scene unless the file defines its own "default": a neutral light grey.
Material defaultMaterial();

}  // namespace lancer
