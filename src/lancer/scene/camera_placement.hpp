// Where the automatic camera stands when a scene gives no position: needed by the camera itself, by
// orbits that start from it, and by the quick look, which puts its fill light there. A flat scene
// (2D results) is seen straight on, orthographic, filling the picture; legends get their side.
#pragma once

#include "lancer/math/aabb.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {

// The automatic camera placed for an image `aspect` (width / height) wide: `settings` with its
// position and look_at set, the orthographic window's height when not given, and the window moved
// off the view axis (shiftX, shiftY) so that the scene sits in the part of the image the legends
// leave (settings.legendShare). Fits the bounding sphere of `worldBounds` from `settings.viewFrom`
// (the 3/4 view for y up), or with settings.fitBox its bounding box seen along the view (a flat
// scene straight on). A camera with a position is returned as it is.
CameraSettings placeAutomaticCamera(const CameraSettings& settings, const Aabbd& worldBounds, double aspect);

// Its position alone.
Vec3d defaultCameraPosition(const Aabbd& worldBounds, const CameraSettings& settings, double aspect);

// The side of one pixel of a `width` x `height` picture, in world units, at the camera's look-at point
// (the distance its picture is framed at): the orthographic window's height over `height`, or for a
// perspective camera 2 tan(fov / 2) times the distance to the look-at point over `height`. The
// camera is taken as the picture places it for `worldBounds` (a gmsh view resolved, the automatic
// camera placed, the zoom applied). How a size given in pixels (a field line's tube radius)
// becomes model units.
double pixelSizeAtTarget(const CameraSettings& camera, const Aabbd& worldBounds, int width, int height);

// When nobody chose the view (camera.viewChosen, a position, a gmsh view) and the scene is flat
// (planarView: 2D models), turns the automatic camera to see it straight on, orthographic, fitted to
// its bounding box (as gmsh and ParaView show 2D results), and returns true; else leaves the camera
// as it is.
bool frameFlatScene(CameraSettings& camera, const Aabbd& worldBounds);

}  // namespace lancer
