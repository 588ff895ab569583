#include "lancer/scene/view_presets.hpp"

#include <cmath>
#include <numbers>

namespace lancer {

std::optional<ViewPreset> parseViewPreset(std::string_view name) {
  for (std::size_t i = 0; i < kViewPresetNames.size(); ++i)
    if (kViewPresetNames[i] == name) return static_cast<ViewPreset>(i);
  return std::nullopt;
}

ViewFrame presetFrame(ViewPreset preset, UpAxis axis) {
  const ViewFrame iso = threeQuarterFrame(axis);
  if (preset == ViewPreset::Iso) return iso;
  const Vec3d right = iso.right, up = iso.up;
  const Vec3d front = cross(right, up);  // right, up and front are right-handed
  switch (preset) {
    case ViewPreset::Front:
      return {right, up, front};
    case ViewPreset::Back:
      return {right * -1.0, up, front * -1.0};
    case ViewPreset::Right:
      return {front * -1.0, up, right};
    case ViewPreset::Left:
      return {front, up, right * -1.0};
    case ViewPreset::Top:  // the back at the top of the picture, the right still on the right
      return {right, front * -1.0, up};
    case ViewPreset::Bottom:
      return {right, front, up * -1.0};
    case ViewPreset::Iso:
      break;
  }
  return iso;
}

std::optional<UpAxis> upAxisOf(const Vec3d& up) {
  for (std::size_t i = 0; i < kUpAxisNames.size(); ++i) {
    const auto axis = static_cast<UpAxis>(i);
    const Vec3d direction = upVector(axis);
    if (length(up) > 0 && length(cross(up, direction)) == 0 && dot(up, direction) > 0) return axis;
  }
  return std::nullopt;
}

Vec3d rotatedAbout(const Vec3d& v, const Vec3d& axis, double degrees) {
  if (degrees == 0) return v;
  const double angle = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

void turnView(Vec3d& toViewer, Vec3d& up, const Vec3d& axis, const OrbitAngles& angles) {
  if (angles.elevationDegrees != 0) {
    // The screen's right; rotating about it by a positive angle would lower the camera.
    const Vec3d right = normalize(cross(toViewer * -1.0, up));
    toViewer = rotatedAbout(toViewer, right, -angles.elevationDegrees);
    up = rotatedAbout(up, right, -angles.elevationDegrees);
  }
  if (angles.azimuthDegrees != 0) {
    const Vec3d k = normalize(axis);
    toViewer = rotatedAbout(toViewer, k, angles.azimuthDegrees);
    up = rotatedAbout(up, k, angles.azimuthDegrees);
  }
}

}  // namespace lancer
