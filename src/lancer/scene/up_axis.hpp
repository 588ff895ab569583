// Which way is up for an automatic camera: the six signed axes `--up` and `camera.up_axis` name, the
// camera frame and 3/4 view each gives, and the guess the quick look makes from a bare mesh.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// In the order of kUpAxisNames.
enum class UpAxis { X, Y, Z, MinusX, MinusY, MinusZ };
inline constexpr std::array<std::string_view, 6> kUpAxisNames = {"x", "y", "z", "-x", "-y", "-z"};

std::optional<UpAxis> parseUpAxis(std::string_view name);
Vec3d upVector(UpAxis axis);

// A right-handed frame for an automatic camera: `toViewer` points from the scene towards the camera
// (any length: camera.viewFrom keeps it as it is, so the y-up view stays bit for bit what it was),
// `up` is the screen's up and `right` the screen's right.
struct ViewFrame {
  Vec3d right, up, toViewer;
};

// The 3/4 view with `axis` up: from the right, above and in front. For y up this is the view lancer
// has always used (right = +x, front = +z); z up looks from +x, -y, +z (CAD's front-right iso view).
ViewFrame threeQuarterFrame(UpAxis axis);

// Sets the automatic camera's up and 3/4 view direction (camera.viewFrom) for `axis`: a view chosen,
// so a flat scene keeps it (camera.viewChosen).
void applyUpAxis(CameraSettings& camera, UpAxis axis);

// Rule 1 below, for any bounds of this extent: a flat box (one extent at most 1e-6 of the largest,
// as gmsh's 2D models) is seen straight on from the + side of that axis (index 0, 1, 2); nothing for
// a box with depth (or no extent at all).
struct PlanarView {
  ViewFrame frame;
  UpAxis up = UpAxis::Y;  // the screen's up
  int axis = 2;           // the plane's normal
};
std::optional<PlanarView> planarView(const Vec3d& extent);

// What the quick look makes of a bare mesh (README "Quick look"):
//  1. planar (one extent at most 1e-6 of the largest: gmsh's 2D models in the XY plane) -> seen straight
//     on from the + side of that axis: a z plane with y up, an x plane with z up, a y plane with -z up;
//  2. else the axis with the most "base" area, faces lying flat (within 5 degrees) on or near (within
//     5% of the largest extent) the two sides of the bounding box across it (the plate a part stands
//     on, even with bolt heads below it; the ends of a cylinder), counted when
//     it is at least 2% of the surface; near ties (within 2%) go to z, then y (CAD and gmsh draw z
//     as height);
//  3. else (no flat side: terrains, spheres, organic shapes) the axis of the smallest extent (a
//     terrain's height), ties to z then y.
struct UpGuess {
  ViewFrame frame;
  UpAxis up = UpAxis::Y;  // the screen's up
  bool planar = false;    // straight-on view along frame.toViewer rather than a 3/4 view
  std::string reason;     // for messages and tests: "planar in z", "base area", "smallest extent"
};
// On `threads` threads (0: every core); the same guess on any number. `bounds`: the mesh's
// faceBounds, when the caller has them.
UpGuess guessUpAxis(const Mesh& mesh, int threads = 0);
UpGuess guessUpAxis(const Mesh& mesh, const Aabb& bounds, int threads);

// The box of the corners of the mesh's faces (faceBounds), on `threads` threads (0: every core):
// the quick look's framing and lights, a pass over every face of a mesh of millions before its
// render can start.
Aabb faceBoundsOnThreads(const Mesh& mesh, int threads);

}  // namespace lancer
