// The named sides an automatic camera looks from (`--view iso|front|back|left|right|top|bottom`) and
// the orbit that turns a camera about its target from there (`--azimuth`, `--elevation`, `--zoom`).
// The sides are named from the up axis (guessed for a bare mesh, or `--up`): with y up, as gmsh's
// default view, the front is +z (gmsh's "Z" view looks at the XY plane from +z) and the right +x;
// with z up, as CAD and gmsh's "Y" view, the front is -y (the camera stands at -y) and the right +x.
// In general right and front are those of the 3/4 view (threeQuarterFrame), which looks from the
// right, above and in front.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "lancer/math/vec3.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {

enum class ViewPreset { Iso, Front, Back, Left, Right, Top, Bottom };
// In the order of ViewPreset.
inline constexpr std::array<std::string_view, 7> kViewPresetNames = {"iso",   "front", "back",  "left",
                                                                     "right", "top",   "bottom"};

std::optional<ViewPreset> parseViewPreset(std::string_view name);

// The frame `preset` gives with `axis` up: iso is the 3/4 view; front, back, right and left look
// level at the model with `axis` up on the screen; top looks down `axis` with the front at the
// bottom of the picture (as a plan is drawn under an elevation), bottom looks up it with the front
// at the top. toViewer is a unit vector, except for iso (threeQuarterFrame's, bit for bit).
ViewFrame presetFrame(ViewPreset preset, UpAxis axis);

// The signed axis `up` points along, or nothing when it is not along one (exactly, after scaling).
std::optional<UpAxis> upAxisOf(const Vec3d& up);

// Turns a camera about its target: `elevationDegrees` raises it over the target (about the screen's
// right, the screen's up following), then `azimuthDegrees` moves it to its right round `axis` (the
// right-hand rule about the model's up: positive turns the model to the left on the screen).
// `toViewer` points from the target to the camera (any length, kept), `up` is the screen's up.
struct OrbitAngles {
  double azimuthDegrees = 0, elevationDegrees = 0;
};
void turnView(Vec3d& toViewer, Vec3d& up, const Vec3d& axis, const OrbitAngles& angles);

// A vector rotated by `degrees` about the unit vector `axis` (the right-hand rule).
Vec3d rotatedAbout(const Vec3d& v, const Vec3d& axis, double degrees);

}  // namespace lancer
