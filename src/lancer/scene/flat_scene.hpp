// A flat scene (every face in one plane, as 2D results are) shown as gmsh and ParaView show it:
// straight on, orthographic, filling the picture, its field colours as the map has them.
#pragma once

#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// What the caller chose over the scene: a look (its lights), a shading for every mesh.
struct FlatSceneChoices {
  bool look = false;
  bool shading = false;
};

// With the meshes as read (meshes[i] is description.meshes[i]), placed and warped at the step
// shown: when they are flat and nobody chose the view, the automatic camera sees them straight on
// (frameFlatScene). Then, unless lights were asked for (a [[light]] or [environment] of the scene,
// a look; the quick look's own lights are not), every field-coloured mesh that sets no shading of
// its own is drawn "unlit": the map's colours, no highlight, no fall-off. Returns whether the
// scene was flat and framed so.
bool applyFlatSceneDefaults(SceneDescription& description, const std::vector<Mesh>& meshes,
                            const FlatSceneChoices& choices);

}  // namespace lancer
