#include "lancer/scene/camera_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {
namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

double fittingDistance(double radius, double fovDegrees, double aspect) {
  // The tighter of the vertical and horizontal half-angles decides; 8% margin around the sphere.
  const double halfVertical = 0.5 * fovDegrees * kDegrees;
  const double halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
  return 1.08 * radius / std::sin(std::min(halfVertical, halfHorizontal));
}

}  // namespace

Vec3d defaultCameraPosition(const Aabbd& worldBounds, const CameraSettings& settings, double aspect) {
  const double radius = std::max(0.5 * length(worldBounds.extent()), 1e-12);
  return worldBounds.center() +
         normalize(settings.viewFrom) * fittingDistance(radius, settings.fovDegrees, aspect);
}

}  // namespace lancer
