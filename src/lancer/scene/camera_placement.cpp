#include "lancer/scene/camera_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {
namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;
// A flat scene's bounding box fills this share of the picture's tighter side: a thin margin, as
// gmsh's and ParaView's "fit to view" leave.
constexpr double kBoxFill = 0.94;

double fittingDistance(double radius, double halfVertical, double halfHorizontal) {
  // The tighter of the vertical and horizontal half-angles decides; 8% margin around the sphere.
  return 1.08 * radius / std::sin(std::min(halfVertical, halfHorizontal));
}

}  // namespace

CameraSettings placeAutomaticCamera(const CameraSettings& settings, const Aabbd& worldBounds, double aspect) {
  const Vec3d centre = worldBounds.empty() ? Vec3d{} : worldBounds.center();
  const double radius = std::max(0.5 * length(worldBounds.extent()), 1e-12);
  if (settings.position) {
    if (settings.zoom == 1) return settings;
    // Placed once: the result has zoom 1, so placing it again changes nothing.
    CameraSettings zoomed = settings;
    zoomed.zoom = 1;
    const Vec3d lookAt = settings.lookAt.value_or(centre);
    zoomed.position = lookAt + (*settings.position - lookAt) * (1.0 / settings.zoom);
    if (settings.projection == Projection::Orthographic)
      zoomed.viewHeight = settings.viewHeight.value_or(2.16 * radius / std::min(1.0, aspect)) / settings.zoom;
    return zoomed;
  }
  CameraSettings placed = settings;
  placed.zoom = 1;
  // The part of the image the scene is framed in: the legends take a share of the right or bottom.
  const double keepWidth = 1.0 - settings.legendShareRight, keepHeight = 1.0 - settings.legendShareBottom;
  const bool whole = keepWidth == 1.0 && keepHeight == 1.0;
  const Vec3d toViewer = normalize(settings.viewFrom);
  const double halfVertical = 0.5 * settings.fovDegrees * kDegrees;
  const double tanVertical = std::tan(halfVertical);
  const double distance = whole ? fittingDistance(radius, halfVertical, std::atan(tanVertical * aspect))
                                : fittingDistance(radius, std::atan(tanVertical * keepHeight),
                                                  std::atan(tanVertical * aspect * keepWidth));
  const Vec3d lookAt = settings.lookAt.value_or(centre);
  placed.lookAt = lookAt;
  placed.position = centre + toViewer * (distance / settings.zoom);
  if (settings.projection == Projection::Perspective) {
    // The window's centre off the axis, in tan units: the look-at point lands in the kept part's centre.
    placed.shiftX = settings.shiftX + settings.legendShareRight * tanVertical * aspect;
    placed.shiftY = settings.shiftY - settings.legendShareBottom * tanVertical;
    return placed;
  }
  if (!settings.viewHeight) {
    if (settings.fitBox && !worldBounds.empty()) {
      // The box's extent across the view: its corners on the screen's right and up.
      const Vec3d up0 = normalize(settings.up);
      const Vec3d right = normalize(cross(-toViewer, up0));
      const Vec3d up = cross(right, -toViewer);
      double width = 0, height = 0;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p{corner & 1 ? worldBounds.upper.x : worldBounds.lower.x,
                      corner & 2 ? worldBounds.upper.y : worldBounds.lower.y,
                      corner & 4 ? worldBounds.upper.z : worldBounds.lower.z};
        width = std::max(width, 2 * std::abs(dot(p - lookAt, right)));
        height = std::max(height, 2 * std::abs(dot(p - lookAt, up)));
      }
      placed.viewHeight = std::max({height / keepHeight, width / (aspect * keepWidth), 1e-12}) / kBoxFill;
    } else {
      // The bounding sphere's diameter with a margin, so the whole scene is in view.
      placed.viewHeight = whole ? 2.16 * radius / std::min(1.0, aspect)
                                : std::max(2.16 * radius / keepHeight, 2.16 * radius / (aspect * keepWidth));
    }
  }
  if (settings.zoom != 1) placed.viewHeight = *placed.viewHeight / settings.zoom;
  placed.shiftX = settings.shiftX + settings.legendShareRight * 0.5 * *placed.viewHeight * aspect;
  placed.shiftY = settings.shiftY - settings.legendShareBottom * 0.5 * *placed.viewHeight;
  return placed;
}

Vec3d defaultCameraPosition(const Aabbd& worldBounds, const CameraSettings& settings, double aspect) {
  return *placeAutomaticCamera(settings, worldBounds, aspect).position;
}

double pixelSizeAtTarget(const CameraSettings& camera, const Aabbd& worldBounds, int width, int height) {
  const double aspect = static_cast<double>(width) / height;
  const CameraSettings placed =
      placeAutomaticCamera(resolveGmshView(camera, worldBounds, aspect), worldBounds, aspect);
  const Vec3d centre = worldBounds.empty() ? Vec3d{} : worldBounds.center();
  if (placed.projection == Projection::Orthographic) {
    // The window render/camera.cpp makes when none is given.
    const double radius = std::max(0.5 * length(worldBounds.extent()), 1e-12);
    return placed.viewHeight.value_or(2.16 * radius / std::min(1.0, aspect)) / height;
  }
  const double distance = length(*placed.position - placed.lookAt.value_or(centre));
  return 2 * std::tan(0.5 * placed.fovDegrees * kDegrees) * distance / height;
}

bool frameFlatScene(CameraSettings& camera, const Aabbd& worldBounds) {
  if (camera.viewChosen || camera.position || camera.gmshView) return false;
  if (worldBounds.empty()) return false;
  const std::optional<PlanarView> view = planarView(worldBounds.extent());
  if (!view) return false;
  // An up the camera already has in the plane (a 3D model's, when only a slice of it is drawn) stays
  // up: the plane is seen from the side that puts +x, else +y, to the right.
  const Vec3d normal = view->frame.toViewer;
  if (std::abs(dot(camera.up, normal)) < 1e-9 && length(camera.up) > 0) {
    const Vec3d up = normalize(camera.up);
    const Vec3d right = cross(normal * -1.0, up);
    const double rightness = std::abs(right.x) > 1e-9 ? right.x : right.y;
    camera.up = up;
    camera.viewFrom = rightness >= 0 ? normal : normal * -1.0;
  } else {
    camera.up = view->frame.up;
    camera.viewFrom = view->frame.toViewer;
  }
  camera.projection = Projection::Orthographic;
  camera.fitBox = true;
  return true;
}

}  // namespace lancer
