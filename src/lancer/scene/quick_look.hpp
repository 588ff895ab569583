// The scene `lancer render part.msh` uses when no scene file is given: the mesh framed from a 3/4
// view with its up axis guessed (up_axis.hpp) or given, a key and a fill light that follow the camera,
// each physical group in its own colour from a colour-blind-safe palette.
#pragma once

#include <optional>
#include <string>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {

// `up`: the up axis (`--up`); without it the quick look guesses (guessUpAxis). Its passes over the
// faces run on `threads` threads (0: every core).
SceneDescription quickLookScene(const std::string& meshPath, const Mesh& mesh, std::optional<UpAxis> up = {},
                                int threads = 0);

// Places the quick look's two lights for its automatic camera at the description's image size (the
// camera's distance depends on the aspect): a key above, left and in front of the camera, and a
// fill at the camera itself, so every face the camera sees is lit from the camera's side. Called
// again when the image size changes after quickLookScene (command-line --width, --height) and when
// the camera is placed (a gmsh view, a Python Camera with a position): the lights then follow it.
// Its pass over the faces runs on `threads` threads (0: every core).
void placeQuickLookLights(SceneDescription& scene, const Mesh& mesh, int threads = 0);

}  // namespace lancer
