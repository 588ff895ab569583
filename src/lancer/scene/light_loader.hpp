// The scene file's lights and environment: `[[light]]` tables of every type and `[environment]`,
// checked at the boundary (errors at the file's line).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// `[[light]]` number `index` of the scene file `path`.
PointLight readLight(const std::string& path, const toml::table& table, std::size_t index);

// `[environment]` of the scene file `path`, whose map is relative to `folder`.
EnvironmentSettings readEnvironment(const std::string& path, const std::filesystem::path& folder,
                                    const toml::table& table);

}  // namespace lancer
