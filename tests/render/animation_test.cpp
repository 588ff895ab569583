// Orbit animations in the library: frame angles, the rotation, and a 4-frame turn of a committed
// scene whose half-turn frame must match a render from the opposite side, for the camera and a light.
#include "lancer/render/animation.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"

namespace lancer {
namespace {

const std::string kTurntable = std::string(LANCER_TEST_DATA_DIR) + "/render/turntable.toml";

struct LoadedScene {
  SceneDescription description = loadScene(kTurntable);
  Scene scene = buildScene(description);
  Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
};

std::vector<Image> animate(LoadedScene& s, const AnimationSettings& animation, int threads = 2) {
  std::vector<Image> frames;
  RenderOptions options;
  options.threads = threads;
  const AnimationStats stats = renderAnimation(s.scene, s.accelerator, s.description, animation, options,
                                               [&](int frame, const Image& image) {
                                                 EXPECT_EQ(frame, static_cast<int>(frames.size()));
                                                 frames.push_back(image);
                                               });
  EXPECT_FALSE(stats.cancelled);
  EXPECT_GT(stats.rays, 0u);
  return frames;
}

Image renderWith(const LoadedScene& s, const CameraSettings& cameraSettings) {
  const RenderSettings& settings = s.description.render;
  const Camera camera = makeCamera(cameraSettings, s.scene, settings);
  RenderOptions options;
  options.threads = 2;
  return Renderer(s.scene, s.accelerator, camera, settings).renderImage(options);
}

bool bitIdentical(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y)
    if (std::memcmp(a.row(y).data(), b.row(y).data(), sizeof(Rgba) * static_cast<std::size_t>(a.width())) !=
        0)
      return false;
  return true;
}

TEST(OrbitAngle, FullTurnDoesNotRepeatTheFirstFramePartialSweepEndsAtItsAngle) {
  AnimationSettings animation;
  animation.frames = 4;
  animation.degrees = 360;
  EXPECT_EQ(orbitAngleDegrees(animation, 0), 0);
  EXPECT_EQ(orbitAngleDegrees(animation, 1), 90);
  EXPECT_EQ(orbitAngleDegrees(animation, 2), 180);
  EXPECT_EQ(orbitAngleDegrees(animation, 3), 270);
  animation.degrees = -720;  // two turns the other way: still a closed loop
  EXPECT_EQ(orbitAngleDegrees(animation, 1), -180);
  animation.degrees = 180;
  EXPECT_EQ(orbitAngleDegrees(animation, 1), 60);
  EXPECT_EQ(orbitAngleDegrees(animation, 3), 180);
  animation.frames = 1;
  EXPECT_EQ(orbitAngleDegrees(animation, 0), 0);
}

TEST(RotateAbout, RightHandedAboutAnOffsetAxisAndExactAtZero) {
  const Vec3d r = rotateAbout({2, 5, 0}, {1, 0, 0}, {0, 2, 0}, 90);  // about the line x = 1, z = 0
  EXPECT_NEAR(r.x, 1, 1e-12);
  EXPECT_NEAR(r.y, 5, 1e-12);
  EXPECT_NEAR(r.z, -1, 1e-12);  // +x turns towards -z about +y
  const Vec3d p{0.1, 0.7, 1e9};
  const Vec3d same = rotateAbout(p, {0.3, 0, 0.2}, {0, 1, 0}, 0);
  EXPECT_EQ(same.x, p.x);
  EXPECT_EQ(same.y, p.y);
  EXPECT_EQ(same.z, p.z);
}

TEST(OrbitCamera, DefaultCentreIsTheSceneBoundsCentre) {
  LoadedScene s;
  AnimationSettings animation = *s.description.animation;
  animation.center.reset();
  const Vec3d centre = orbitCenter(animation, s.scene);
  const Aabb& b = s.scene.geometry.bounds;
  EXPECT_NEAR(centre.x, s.scene.geometry.origin.x + 0.5 * (b.lower.x + b.upper.x), 1e-6);
  EXPECT_NEAR(centre.z, s.scene.geometry.origin.z + 0.5 * (b.lower.z + b.upper.z), 1e-6);
}

// The oracle: half way round a 4-frame full turn, the camera looks from the opposite side.
TEST(Animation, HalfTurnFrameEqualsTheRenderFromTheOppositeSide) {
  LoadedScene s;
  ASSERT_TRUE(s.description.animation.has_value());
  const AnimationSettings animation = *s.description.animation;
  ASSERT_EQ(animation.frames, 4);
  const std::vector<Image> frames = animate(s, animation);
  ASSERT_EQ(frames.size(), 4u);

  CameraSettings opposite = s.description.camera;
  opposite.position = Vec3d{-4, 3.5, -5};  // [4, 3.5, 5] turned 180 degrees about the y axis
  opposite.lookAt = Vec3d{0, 0.6, 0};      // on the axis: unchanged
  const Image expected = renderWith(s, opposite);
  // The orbit's position is off by ~1e-16 (sin 180 degrees), so a pixel may fall either side of an edge.
  EXPECT_GT(test::psnr8(frames[2], expected), 40.0);
  // ...and the test can fail: the other frames are other views.
  for (int k : {0, 1, 3}) EXPECT_LT(test::psnr8(frames[static_cast<std::size_t>(k)], expected), 25.0) << k;
  EXPECT_TRUE(bitIdentical(frames[0], renderWith(s, s.description.camera)));
}

TEST(Animation, PartialSweepEndsOnItsLastFrame) {
  LoadedScene s;
  AnimationSettings animation = *s.description.animation;
  animation.degrees = 180;
  const std::vector<Image> frames = animate(s, animation);
  ASSERT_EQ(frames.size(), 4u);
  CameraSettings opposite = s.description.camera;
  opposite.position = Vec3d{-4, 3.5, -5};
  EXPECT_GT(test::psnr8(frames[3], renderWith(s, opposite)), 40.0);
}

// Frame k is the render of the same scene with the camera that orbitCamera gives, bit for bit, and
// the same for any thread count.
TEST(Animation, FramesAreBitIdenticalToSingleRendersAtTheirAngle) {
  LoadedScene s;
  AnimationSettings animation = *s.description.animation;
  animation.axis = {0.2, 1, -0.1};  // a tilted axis: the up vector turns too
  const std::vector<Image> frames = animate(s, animation, 2);
  const std::vector<Image> oneThread = animate(s, animation, 1);
  const RenderSettings& settings = s.description.render;
  for (int k = 0; k < animation.frames; ++k) {
    const CameraSettings camera =
        orbitCamera(s.description.camera, animation, s.scene, settings.width, settings.height, k);
    EXPECT_TRUE(bitIdentical(frames[static_cast<std::size_t>(k)], renderWith(s, camera))) << "frame " << k;
    EXPECT_TRUE(bitIdentical(frames[static_cast<std::size_t>(k)], oneThread[static_cast<std::size_t>(k)]));
  }
}

TEST(Animation, CameraWithoutPositionOrbitsTheDefaultView) {
  LoadedScene s;
  s.description.camera.position.reset();
  s.description.camera.lookAt.reset();
  AnimationSettings animation = *s.description.animation;
  animation.center.reset();
  const std::vector<Image> frames = animate(s, animation);
  EXPECT_TRUE(bitIdentical(frames[0], renderWith(s, s.description.camera)));
  EXPECT_LT(test::psnr8(frames[0], frames[2]), 25.0);
}

TEST(Animation, LightOrbitHalfTurnEqualsTheLightOnTheOppositeSide) {
  LoadedScene s;
  AnimationSettings animation = *s.description.animation;
  animation.orbitLight = 0;
  const Vec3 before = s.scene.appearance.lights[0].position;
  const std::vector<Image> frames = animate(s, animation);
  ASSERT_EQ(frames.size(), 4u);
  EXPECT_EQ(s.scene.appearance.lights[0].position, before);  // restored after the animation

  EXPECT_TRUE(bitIdentical(frames[0], renderWith(s, s.description.camera)));  // the camera never moves
  s.scene.appearance.lights[0].position =
      s.scene.geometry.toSceneSpace({4, 8, -5});  // [-4, 8, 5] turned 180 degrees about y
  const Image expected = renderWith(s, s.description.camera);
  EXPECT_GT(test::psnr8(frames[2], expected), 40.0);
  EXPECT_LT(test::psnr8(frames[0], expected), 35.0);
}

TEST(Animation, CancellingStopsBeforeTheNextFrame) {
  LoadedScene s;
  std::atomic<bool> cancel{false};
  RenderOptions options;
  options.threads = 2;
  options.cancel = &cancel;
  int delivered = 0;
  const Vec3 lightBefore = s.scene.appearance.lights[1].position;
  AnimationSettings animation = *s.description.animation;
  animation.orbitLight = 1;
  const AnimationStats stats =
      renderAnimation(s.scene, s.accelerator, s.description, animation, options, [&](int, const Image&) {
        ++delivered;
        cancel = true;  // as Ctrl-C during frame 1 would
      });
  EXPECT_TRUE(stats.cancelled);
  EXPECT_EQ(delivered, 1);
  EXPECT_EQ(s.scene.appearance.lights[1].position, lightBefore);
}

// A frame writer that fails (a full disk) ends the animation with its exception, and the orbiting
// light is back where it was: the scene can render again (the light stayed turned before).
TEST(Animation, AFailingFrameWriterLeavesTheLightsAsTheyWere) {
  LoadedScene s;
  RenderOptions options;
  options.threads = 2;
  const Vec3 lightBefore = s.scene.appearance.lights[0].position;
  AnimationSettings animation = *s.description.animation;
  animation.orbitLight = 0;
  int delivered = 0;
  EXPECT_THROW(renderAnimation(s.scene, s.accelerator, s.description, animation, options,
                               [&](int, const Image&) {
                                 if (++delivered == 2) throw std::runtime_error("disk full");
                               }),
               std::runtime_error);
  EXPECT_EQ(delivered, 2);
  EXPECT_EQ(s.scene.appearance.lights[0].position, lightBefore);
}

}  // namespace
}  // namespace lancer
