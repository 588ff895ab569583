#include "lancer/scene/results/gmsh_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>

#include "lancer/scene/scene_description.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// Rows of the 3x3 rotation gmsh applies to the model (view = R (p - cg)): row 0 is the screen's right,
// row 1 its up, row 2 points at the viewer. gmsh keeps it as a column-major OpenGL matrix `rot`.
using Rotation = std::array<Vec3d, 3>;

Rotation fromColumnMajor(const std::array<double, 16>& m) {
  return {Vec3d{m[0], m[4], m[8]}, Vec3d{m[1], m[5], m[9]}, Vec3d{m[2], m[6], m[10]}};
}

// gmsh's build_rotmatrix (trackball.cpp, after SGI's trackball.c), q = (x, y, z, w).
Rotation trackballRotation(const std::array<double, 4>& q) {
  std::array<double, 16> m{};
  m[0] = 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]);
  m[1] = 2.0 * (q[0] * q[1] - q[2] * q[3]);
  m[2] = 2.0 * (q[2] * q[0] + q[1] * q[3]);
  m[4] = 2.0 * (q[0] * q[1] + q[2] * q[3]);
  m[5] = 1.0 - 2.0 * (q[2] * q[2] + q[0] * q[0]);
  m[6] = 2.0 * (q[1] * q[2] - q[0] * q[3]);
  m[8] = 2.0 * (q[2] * q[0] - q[1] * q[3]);
  m[9] = 2.0 * (q[1] * q[2] + q[0] * q[3]);
  m[10] = 1.0 - 2.0 * (q[1] * q[1] + q[0] * q[0]);
  return fromColumnMajor(m);
}

// gmsh's drawContext::buildRotationMatrix for General.Trackball = 0 (Euler angles in degrees).
Rotation eulerRotation(const Vec3d& degrees) {
  constexpr double kRadians = std::numbers::pi / 180.0;
  const double A = std::cos(degrees.x * kRadians), B = std::sin(degrees.x * kRadians);
  const double C = std::cos(degrees.y * kRadians), D = std::sin(degrees.y * kRadians);
  const double E = std::cos(degrees.z * kRadians), F = std::sin(degrees.z * kRadians);
  const double AD = A * D, BD = B * D;
  std::array<double, 16> m{};
  m[0] = C * E, m[1] = BD * E + A * F, m[2] = -AD * E + B * F;
  m[4] = -C * F, m[5] = -BD * F + A * E, m[6] = AD * F + B * E;
  m[8] = D, m[9] = -B * C, m[10] = A * C;
  return fromColumnMajor(m);
}

Vec3d transposeTimes(const Rotation& r, const Vec3d& v) { return r[0] * v.x + r[1] * v.y + r[2] * v.z; }

}  // namespace

GmshView gmshViewFromOptions(const GmshOptionLookup& option, const std::string& source) {
  GmshView view;
  view.source = source;
  auto set = [&](const char* name, double& value) {
    if (const std::optional<double> found = option(name)) value = *found;
  };
  auto flag = [&](const char* name, bool& value) {
    if (const std::optional<double> found = option(name)) value = *found != 0;
  };
  flag("Trackball", view.trackball);
  for (int i = 0; i < 4; ++i)
    set(fmt::format("TrackballQuaternion{}", i).c_str(), view.quaternion[static_cast<std::size_t>(i)]);
  set("RotationX", view.rotationDegrees.x);
  set("RotationY", view.rotationDegrees.y);
  set("RotationZ", view.rotationDegrees.z);
  set("TranslationX", view.translation.x);
  set("TranslationY", view.translation.y);
  set("TranslationZ", view.translation.z);
  set("ScaleX", view.scale.x);
  set("ScaleY", view.scale.y);
  set("ScaleZ", view.scale.z);
  flag("Orthographic", view.orthographic);
  set("ClipFactor", view.clipFactor);
  set("DisplayBorderFactor", view.displayBorderFactor);
  Vec3d low{}, high{};
  bool bounds = false;
  const auto coordinate = [&](const char* name, double& value) {
    if (const std::optional<double> found = option(name)) value = *found, bounds = true;
  };
  coordinate("MinX", low.x), coordinate("MinY", low.y), coordinate("MinZ", low.z);
  coordinate("MaxX", high.x), coordinate("MaxY", high.y), coordinate("MaxZ", high.z);
  if (bounds && low.x <= high.x && low.y <= high.y && low.z <= high.z) {
    Aabbd box;
    box.extend(low);
    box.extend(high);
    view.modelBounds = box;
  }
  return view;
}

GmshView readGmshView(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(
        SourceLocation{path},
        "cannot open this gmsh options file; in gmsh, File > Save Model Options writes part.msh.opt");
  std::map<std::string, double> numbers;
  std::string line;
  for (std::int64_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
    constexpr std::string_view kPrefix = "General.";
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, kPrefix.size(), kPrefix) != 0) continue;
    const std::size_t equals = line.find('=', start);
    if (equals == std::string::npos) continue;
    std::string name = line.substr(start + kPrefix.size(), equals - start - kPrefix.size());
    name.erase(name.find_last_not_of(" \t") + 1);
    std::string value = line.substr(equals + 1);
    value = value.substr(0, value.find(';'));
    const std::size_t first = value.find_first_not_of(" \t");
    if (first == std::string::npos || value[first] == '"' || value[first] == '{')
      continue;  // strings, colours
    char* end = nullptr;
    const double number = std::strtod(value.c_str() + first, &end);
    if (end == value.c_str() + first || !std::isfinite(number))
      throw InputError(SourceLocation{path, lineNumber, static_cast<std::int64_t>(equals + 2)},
                       fmt::format("General.{} should be a number, not '{}'", name, value.substr(first)));
    numbers[name] = number;
  }
  return gmshViewFromOptions(
      [&](const std::string& name) -> std::optional<double> {
        const auto found = numbers.find(name);
        return found == numbers.end() ? std::nullopt : std::optional<double>(found->second);
      },
      path);
}

GmshCamera gmshViewCamera(const GmshView& view, const Aabbd& sceneBounds, double imageAspect) {
  const Aabbd& worldBounds = view.modelBounds ? *view.modelBounds : sceneBounds;
  const Vec3d low = worldBounds.empty() ? Vec3d{} : worldBounds.lower;
  const Vec3d high = worldBounds.empty() ? Vec3d{} : worldBounds.upper;
  const Vec3d cg = 0.5 * (low + high);  // gmsh's CTX::cg: the bounding box's centre
  const Rotation r =
      view.trackball ? trackballRotation(view.quaternion) : eulerRotation(view.rotationDegrees);

  // The world window at the model's depth, as initProjection frames it: the bounding box's x and y
  // extents fitted to the viewport's aspect, plus a border on every side.
  const double va = imageAspect > 0 ? 1 / imageAspect : 1;
  const double dx = std::max(high.x - low.x, 1e-300), dy = high.y - low.y;
  double windowHeight = va > dy / dx ? va * dx : dy;
  windowHeight *= 1 + 2 * view.displayBorderFactor;

  GmshCamera camera;
  camera.orthographic = view.orthographic;
  camera.up = r[1];
  // gmsh draws view = s * (t + R (p - cg)); the window is centred on view (0, 0).
  const Vec3d& s = view.scale;
  const Vec3d& t = view.translation;
  const double diagonal = std::max(length(high - low), 1e-300);
  if (view.orthographic) {
    camera.lookAt = cg - transposeTimes(r, Vec3d{t.x, t.y, 0});
    camera.viewHeight = windowHeight / s.y;
    // Far enough in front that no part of the model is behind the camera, however it is translated.
    camera.position = camera.lookAt + r[2] * (2 * diagonal + length(t));
    return camera;
  }
  // Perspective: the eye at view (cg.x, cg.y, near), the window at depth `near` centred on view
  // (-cg.x, -cg.y) relative to it (initProjection's t_init), so the view (0, 0, 0) is the image's
  // centre, as in the orthographic view.
  const double zmax = std::max({std::abs(low.z), std::abs(high.z), diagonal});
  const double near = 0.75 * view.clipFactor * zmax;
  const Vec3d eye{cg.x, cg.y, near};
  camera.position = cg + transposeTimes(r, Vec3d{eye.x / s.x - t.x, eye.y / s.y - t.y, eye.z / s.z - t.z});
  camera.lookAt = camera.position - r[2];
  camera.fovDegrees = 2 * std::atan(0.5 * windowHeight / near) * 180 / std::numbers::pi;
  camera.shiftX = -cg.x / near;
  camera.shiftY = -cg.y / near;
  return camera;
}

CameraSettings resolveGmshView(const CameraSettings& camera, const Aabbd& worldBounds, double imageAspect) {
  if (!camera.gmshView) return camera;
  const GmshCamera view = gmshViewCamera(*camera.gmshView, worldBounds, imageAspect);
  CameraSettings resolved;
  resolved.projection = view.orthographic ? Projection::Orthographic : Projection::Perspective;
  resolved.position = view.position;
  resolved.lookAt = view.lookAt;
  resolved.up = view.up;
  resolved.viewHeight = view.viewHeight;
  resolved.fovDegrees = view.fovDegrees;
  resolved.shiftX = view.shiftX;
  resolved.shiftY = view.shiftY;
  return resolved;
}

}  // namespace lancer
