// The gmsh view: reading gmsh's options file, and the camera against analytic expectations and
// against gmsh's own bookkeeping (gmsh saves the trackball quaternion of the Euler angles it shows,
// so both modes must give the same camera). The pictures are compared with gmsh's own exports in
// tests/python/test_gmsh_view.py.
#include "lancer/scene/results/gmsh_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lancer/scene/scene_description.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string viewFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/gmsh_view/" + name;
}

void expectNear(const Vec3d& actual, const Vec3d& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(GmshView, ReadsTheOptionsGmshSaved) {
  const GmshView view = readGmshView(viewFixture("euler_xyz.opt"));
  EXPECT_FALSE(view.trackball);
  expectNear(view.rotationDegrees, {30, 20, 10}, 0);
  EXPECT_TRUE(view.orthographic);  // gmsh's default: not in the file
  EXPECT_EQ(view.scale.x, 1);
}

TEST(GmshView, DefaultViewLooksDownMinusZWithTheBorderedWindow) {
  const GmshView view;
  const Aabbd box{{0, 0, 0}, {2, 1, 1}};
  const GmshCamera camera = gmshViewCamera(view, box, 1);  // a square image
  EXPECT_TRUE(camera.orthographic);
  expectNear(camera.up, {0, 1, 0}, 1e-15);
  expectNear(camera.lookAt, {1, 0.5, 0.5}, 1e-15);
  EXPECT_GT(camera.position.z, 1.5);
  expectNear({camera.position.x, camera.position.y, 0}, {1, 0.5, 0}, 1e-15);
  // The box's 2 x 1 fitted to a square area is 2 x 2, plus 20% of it on every side.
  EXPECT_NEAR(camera.viewHeight, 2 * 1.4, 1e-12);
}

// gmsh's Print at Print.Width x Print.Height frames the box anew for the printed image's aspect: the
// box's wider side fills the image less the borders, whatever the window it was set up in.
TEST(GmshView, TheImagesAspectFramesTheBoxAsGmshsPrintDoes) {
  const GmshView view;
  const Aabbd box{{0, 0, 0}, {2, 1, 1}};
  EXPECT_NEAR(gmshViewCamera(view, box, 4).viewHeight, 1 * 1.4, 1e-12);    // wide: the box's height
  EXPECT_NEAR(gmshViewCamera(view, box, 2).viewHeight, 1 * 1.4, 1e-12);    // the box's own aspect
  EXPECT_NEAR(gmshViewCamera(view, box, 0.5).viewHeight, 4 * 1.4, 1e-12);  // tall: its width fits
  EXPECT_NEAR(gmshViewCamera(view, box, 4.0 / 3).viewHeight, 1.5 * 1.4, 1e-12);
}

TEST(GmshView, TranslationAndScaleMoveAndShrinkTheWindow) {
  GmshView view;
  view.translation = {0.5, -0.25, 0};
  view.scale = {2, 2, 2};
  const GmshCamera camera = gmshViewCamera(view, Aabbd{{0, 0, 0}, {2, 1, 1}}, 1);
  // The model moves right and down on screen: the camera looks at a point left of and above its centre.
  expectNear(camera.lookAt, {0.5, 0.75, 0.5}, 1e-15);
  EXPECT_NEAR(camera.viewHeight, 1.4, 1e-12);
}

TEST(GmshView, EulerAnglesAndTheQuaternionGmshSavedForThemGiveOneCamera) {
  GmshView euler = readGmshView(viewFixture("euler_xyz.opt"));
  GmshView trackball = euler;
  trackball.trackball = true;  // the file's TrackballQuaternion0..3, which gmsh derived from the angles
  const Aabbd box{{-1.5, 0, -0.75}, {1.5, 1.8, 0.75}};
  for (const bool orthographic : {true, false}) {
    euler.orthographic = trackball.orthographic = orthographic;
    const GmshCamera a = gmshViewCamera(euler, box, 1.5), b = gmshViewCamera(trackball, box, 1.5);
    expectNear(a.position, b.position, 1e-9);
    expectNear(a.lookAt, b.lookAt, 1e-9);
    expectNear(a.up, b.up, 1e-12);
  }
}

TEST(GmshView, PerspectiveSitsAtClipFactorTimesTheModelSizeWithGmshsWindowShift) {
  GmshView view;
  view.orthographic = false;
  const Aabbd box{{0, 0, 0}, {2, 1, 1}};
  const GmshCamera camera = gmshViewCamera(view, box, 1);
  const double diagonal = std::sqrt(6.0), near = 0.75 * 5 * diagonal;
  // The eye sits at view-space (cg.x, cg.y, near): over the world point (2 cg.x, 2 cg.y).
  expectNear(camera.position, {2, 1, 0.5 + near}, 1e-12);
  EXPECT_NEAR(camera.shiftX, -1 / near, 1e-15);
  EXPECT_NEAR(camera.shiftY, -0.5 / near, 1e-15);
  EXPECT_NEAR(std::tan(camera.fovDegrees * std::numbers::pi / 360), 0.5 * 2.8 / near, 1e-12);
}

TEST(GmshView, ResolvedSettingsReplaceTheCameraKeys) {
  CameraSettings settings;
  settings.fovDegrees = 12;
  settings.gmshView = GmshView{};
  const CameraSettings resolved = resolveGmshView(settings, Aabbd{{0, 0, 0}, {1, 1, 1}}, 4.0 / 3);
  EXPECT_FALSE(resolved.gmshView);
  EXPECT_EQ(resolved.projection, Projection::Orthographic);
  ASSERT_TRUE(resolved.position && resolved.lookAt && resolved.viewHeight);
}

TEST(GmshViewBadInput, ANonNumberNamesTheLineAndTheOption) {
  const test::ScratchFolder folder;
  folder.write("bad.opt", "General.RotationX = 30;\nGeneral.RotationY = twenty; // comment\n");
  EXPECT_EQ(test::messageOf([&] { readGmshView(folder.file("bad.opt")); }),
            folder.file("bad.opt") + ":2:20: error: General.RotationY should be a number, not 'twenty'");
}

TEST(GmshViewBadInput, AMissingFileSaysHowGmshWritesOne) {
  EXPECT_EQ(test::messageOf([] { readGmshView("no_such.opt"); }),
            "no_such.opt: error: cannot open this gmsh options file; in gmsh, File > Save Model Options "
            "writes part.msh.opt");
}

// gmsh frames the model's bounding box as its options file records it (General.MinX .. MaxZ, a 0
// left out): a view displaced by a warp is framed on the undeformed model, whatever the warp adds.
TEST(GmshView, AViewFramesTheModelBoxItsOptionsRecord) {
  const GmshView view = readGmshView(test::dataFile("results/cantilever.msh.opt"));
  ASSERT_TRUE(view.modelBounds);
  EXPECT_EQ(view.modelBounds->lower, (Vec3d{0, 0, 0}));
  EXPECT_EQ(view.modelBounds->upper, (Vec3d{10, 1, 1}));
  Aabbd warped = *view.modelBounds;
  warped.extend(Vec3d{10, -4, 1});  // the tip bent down by the displacement
  const GmshCamera onModel = gmshViewCamera(view, *view.modelBounds, 4.0 / 3.0);
  const GmshCamera onWarped = gmshViewCamera(view, warped, 4.0 / 3.0);
  EXPECT_EQ(onWarped.lookAt, onModel.lookAt);
  EXPECT_EQ(onWarped.viewHeight, onModel.viewHeight);
  GmshView unsaved = view;
  unsaved.modelBounds.reset();  // no General.Min/Max: the scene's bounds
  EXPECT_NE(gmshViewCamera(unsaved, warped, 4.0 / 3.0).lookAt, onModel.lookAt);
}

}  // namespace
}  // namespace lancer
