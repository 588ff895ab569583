// The scene `lancer render part.msh` uses when no scene file is given: the mesh framed from a 3/4
// view, a key and a fill light, each physical group in its own colour from a colour-blind-safe palette.
#pragma once

#include <string>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

SceneDescription quickLookScene(const std::string& meshPath, const Mesh& mesh);

}  // namespace lancer
