// --view's named sides for each up axis (gmsh's y-up front is +z, CAD's z-up front is -y), the orbit
// of --azimuth and --elevation, and --zoom in the camera's placement.
#include "lancer/scene/view_presets.hpp"

#include <gtest/gtest.h>

#include "lancer/scene/camera_placement.hpp"

namespace lancer {
namespace {

void expectNear(const Vec3d& v, const Vec3d& expected) {
  EXPECT_NEAR(v.x, expected.x, 1e-12) << v.x << " " << v.y << " " << v.z;
  EXPECT_NEAR(v.y, expected.y, 1e-12) << v.x << " " << v.y << " " << v.z;
  EXPECT_NEAR(v.z, expected.z, 1e-12) << v.x << " " << v.y << " " << v.z;
}

TEST(ViewPresets, NamesParseInTheirOrder) {
  for (std::size_t i = 0; i < kViewPresetNames.size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(*parseViewPreset(kViewPresetNames[i])), i);
  EXPECT_FALSE(parseViewPreset("Front"));
  EXPECT_FALSE(parseViewPreset("isometric"));
}

TEST(ViewPresets, YUpIsGmshsDefaultViewAndZUpIsCadsFront) {
  // y up: the front looks from +z (gmsh's default view), the right from +x, the top down -y with the
  // front (+z) at the bottom of the picture.
  expectNear(presetFrame(ViewPreset::Front, UpAxis::Y).toViewer, {0, 0, 1});
  expectNear(presetFrame(ViewPreset::Front, UpAxis::Y).right, {1, 0, 0});
  expectNear(presetFrame(ViewPreset::Right, UpAxis::Y).toViewer, {1, 0, 0});
  expectNear(presetFrame(ViewPreset::Top, UpAxis::Y).toViewer, {0, 1, 0});
  expectNear(presetFrame(ViewPreset::Top, UpAxis::Y).up, {0, 0, -1});
  // z up: the camera of the front view stands at -y, the right at +x, the top above with +y up.
  expectNear(presetFrame(ViewPreset::Front, UpAxis::Z).toViewer, {0, -1, 0});
  expectNear(presetFrame(ViewPreset::Front, UpAxis::Z).up, {0, 0, 1});
  expectNear(presetFrame(ViewPreset::Back, UpAxis::Z).toViewer, {0, 1, 0});
  expectNear(presetFrame(ViewPreset::Right, UpAxis::Z).toViewer, {1, 0, 0});
  expectNear(presetFrame(ViewPreset::Left, UpAxis::Z).toViewer, {-1, 0, 0});
  expectNear(presetFrame(ViewPreset::Top, UpAxis::Z).toViewer, {0, 0, 1});
  expectNear(presetFrame(ViewPreset::Top, UpAxis::Z).up, {0, 1, 0});
  expectNear(presetFrame(ViewPreset::Bottom, UpAxis::Z).toViewer, {0, 0, -1});
  expectNear(presetFrame(ViewPreset::Bottom, UpAxis::Z).up, {0, -1, 0});
  // iso is the 3/4 view, to the bit.
  const ViewFrame iso = presetFrame(ViewPreset::Iso, UpAxis::Y);
  EXPECT_EQ(iso.toViewer.x, 0.9);
  EXPECT_EQ(iso.toViewer.y, 0.65);
  EXPECT_EQ(iso.toViewer.z, 1.3);
}

TEST(ViewPresets, EverySideIsARightHandedFrameWithTheRightOnTheRight) {
  for (std::size_t a = 0; a < kUpAxisNames.size(); ++a)
    for (std::size_t p = 1; p < kViewPresetNames.size(); ++p) {
      SCOPED_TRACE(std::string(kUpAxisNames[a]) + " " + std::string(kViewPresetNames[p]));
      const ViewFrame frame = presetFrame(static_cast<ViewPreset>(p), static_cast<UpAxis>(a));
      EXPECT_NEAR(length(frame.toViewer), 1, 1e-12);
      expectNear(cross(frame.right, frame.up), frame.toViewer);
      // What the camera computes as the screen's right from the view and up.
      expectNear(cross(frame.toViewer * -1.0, frame.up), frame.right);
    }
}

TEST(ViewPresets, UpAxisOfNamesOnlyVectorsAlongAnAxis) {
  EXPECT_EQ(upAxisOf({0, 0, 3}), UpAxis::Z);
  EXPECT_EQ(upAxisOf({0, -1, 0}), UpAxis::MinusY);
  EXPECT_FALSE(upAxisOf({0, 1, 1}));
  EXPECT_FALSE(upAxisOf({0, 0, 0}));
}

TEST(ViewPresets, AzimuthMovesTheCameraToItsRightAndElevationRaisesIt) {
  // From the front (y up), 90 degrees of azimuth is the right side's view.
  ViewFrame front = presetFrame(ViewPreset::Front, UpAxis::Y);
  turnView(front.toViewer, front.up, {0, 1, 0}, {90, 0});
  expectNear(front.toViewer, presetFrame(ViewPreset::Right, UpAxis::Y).toViewer);
  expectNear(front.up, {0, 1, 0});
  // 90 degrees of elevation is the top view, its up included (the front at the bottom).
  for (std::size_t a = 0; a < kUpAxisNames.size(); ++a) {
    const auto axis = static_cast<UpAxis>(a);
    ViewFrame raised = presetFrame(ViewPreset::Front, axis);
    turnView(raised.toViewer, raised.up, upVector(axis), {0, 90});
    expectNear(raised.toViewer, presetFrame(ViewPreset::Top, axis).toViewer);
    expectNear(raised.up, presetFrame(ViewPreset::Top, axis).up);
  }
  // Azimuth turns about the model's up even from the top: the plan turns in the picture.
  ViewFrame top = presetFrame(ViewPreset::Top, UpAxis::Z);
  turnView(top.toViewer, top.up, {0, 0, 1}, {90, 0});
  expectNear(top.toViewer, {0, 0, 1});
  expectNear(top.up, {-1, 0, 0});
}

TEST(ViewPresets, ZoomBringsTheCameraCloserOnce) {
  const Aabbd bounds{{-1, -1, -1}, {1, 1, 1}};
  CameraSettings camera;
  const CameraSettings placed = placeAutomaticCamera(camera, bounds, 4.0 / 3.0);
  camera.zoom = 2;
  const CameraSettings zoomed = placeAutomaticCamera(camera, bounds, 4.0 / 3.0);
  EXPECT_NEAR(length(*zoomed.position), 0.5 * length(*placed.position), 1e-12);
  EXPECT_EQ(zoomed.zoom, 1);  // placing it again changes nothing
  expectNear(*placeAutomaticCamera(zoomed, bounds, 4.0 / 3.0).position, *zoomed.position);
  // A placed camera moves towards its look_at; an orthographic window shrinks.
  CameraSettings fixed;
  fixed.position = Vec3d{0, 0, 10};
  fixed.lookAt = Vec3d{0, 0, 2};
  fixed.zoom = 4;
  expectNear(*placeAutomaticCamera(fixed, bounds, 1).position, {0, 0, 4});
  fixed.projection = Projection::Orthographic;
  fixed.viewHeight = 8;
  EXPECT_EQ(*placeAutomaticCamera(fixed, bounds, 1).viewHeight, 2);
}

}  // namespace
}  // namespace lancer
