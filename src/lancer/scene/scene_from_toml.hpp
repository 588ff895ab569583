// The scene loader's reading of a TOML document already in memory: a scene file's, parsed, or one
// built in code (Python's lancer.Scene), with the checks and messages of a file's keys.
#pragma once

#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// The scene the document describes, as parseScene (scene_loader.hpp) reads it: messages name `path`,
// relative paths are resolved against `folder`. Throws InputError.
SceneDescription sceneFromToml(const toml::table& root, const std::string& path,
                               const std::filesystem::path& folder);

}  // namespace lancer
