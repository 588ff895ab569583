// The view a gmsh user set up in gmsh's GUI (the General.* options "File > Save Model Options" writes
// to part.msh.opt, or the live values of the gmsh API) and the camera that reproduces gmsh's
// projection of the model: its rotation (trackball quaternion or Euler angles), translation, scale,
// and orthographic or gmsh's perspective (drawContext::initProjection and initPosition, gmsh 4.8),
// framed for the image as gmsh's own export (Print at Print.Width x Print.Height) frames it.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>

#include "lancer/math/aabb.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// gmsh's defaults where the options file says nothing (it saves only the options that changed).
struct GmshView {
  std::string source;  // the options file, or "gmsh" for the live session, for messages
  bool trackball = true;
  std::array<double, 4> quaternion{0, 0, 0, 1};  // General.TrackballQuaternion0..3
  Vec3d rotationDegrees{0, 0, 0};                // General.RotationX/Y/Z, used when Trackball = 0
  Vec3d translation{0, 0, 0};                    // General.TranslationX/Y/Z
  Vec3d scale{1, 1, 1};                          // General.ScaleX/Y/Z
  bool orthographic = true;                      // General.Orthographic
  double clipFactor = 5;                         // General.ClipFactor: sets the perspective eye distance
  double displayBorderFactor = 0.2;              // General.DisplayBorderFactor: margin around the model
  // General.MinX .. MaxZ: the model's bounding box as gmsh saw it, what it frames (a view displaced
  // by a warp is framed on the undeformed model); unset when the file gives none of them (gmsh
  // leaves out a coordinate that is 0). Framing uses the scene's bounds then.
  std::optional<Aabbd> modelBounds;
  // The graphics area's size (General.GraphicsWidth less the module menu beside it, General.
  // GraphicsHeight) does not frame the model: gmsh frames it anew for each viewport, the window's
  // or the printed image's.
};

// Looks up one General.* option by its name without "General." (e.g. "RotationX"); nullopt: unset.
using GmshOptionLookup = std::function<std::optional<double>(const std::string& name)>;
GmshView gmshViewFromOptions(const GmshOptionLookup& option, const std::string& source);

// Reads the General.* numbers of a gmsh options file (`General.RotationX = 30; // comment`); other
// lines are skipped, as gmsh would apply them to other things. Throws InputError (file:line) for a
// file that cannot be read or a view option whose value is not a number.
GmshView readGmshView(const std::string& path);

// The camera of that view for a model with these world bounds (what gmsh frames: its bounding box,
// view.modelBounds when the options give it),
// for an image `imageAspect` (width / height) wide: where it is, where it looks, its up, and either the
// orthographic window height or the perspective field of view with the window's off-axis shift
// (gmsh's perspective eye sits at the model's centre of gravity in view space while the window stays
// centred: tan units at distance 1). gmsh fits the bounding box to its viewport's aspect
// (drawContext::initProjection), and its export at a given size draws into a viewport of that size
// (GetCompositePixelBuffer in common/CreateFile.cpp): the image's aspect frames the model.
struct GmshCamera {
  bool orthographic = true;
  Vec3d position, lookAt, up;
  double viewHeight = 1;   // orthographic: world units
  double fovDegrees = 40;  // perspective: vertical
  double shiftX = 0, shiftY = 0;
};
GmshCamera gmshViewCamera(const GmshView& view, const Aabbd& sceneBounds, double imageAspect);

}  // namespace lancer
