// Isosurfaces and field lines over the time steps of their field (tests/data/volume/moving.msh, made
// by gmsh: s = x - t / 4 and w, the unit vector along x turned 30 degrees a step about z, at times
// 0, 1, 2 on a cube of hexahedra): an animation over steps makes them again at each frame's time,
// between steps from the two steps blended.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>

#include "lancer/render/render_preparation.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// The animation over the steps of the moving cube with `view` (isosurfaces or streamlines) and the
// cube's skin hidden: the frames' scenes hold the view's mesh alone.
struct MovingCube {
  test::ScratchFolder folder;
  std::optional<PreparedRender> prepared;

  explicit MovingCube(const std::string& view) {
    const std::string path = folder.file("scene.toml");
    std::ofstream(path) << fmt::format(R"([render]
width = 32
height = 24

[[light]]
position = [3, 3, 3]

[[mesh]]
file = "{}"
skin = "hidden"
{}
)",
                                       test::dataFile("volume/moving.msh"), view);
    RenderRequest request;
    request.description = loadScene(path);
    request.keepMeshes = true;
    prepared.emplace(prepareRender(std::move(request)));
  }

  // The frames' times and the scene of frame `frame` after rendering it.
  std::vector<Vec3d> framePoints(StepScenes& steps, int frame) {
    steps.render(frame, RenderOptions{});
    const SceneGeometry& geometry = steps.frameScene()->geometry;
    std::vector<Vec3d> points;
    for (const Vec3& p : geometry.positions) points.push_back(geometry.origin + toDouble(p));
    return points;
  }
};

AnimationSettings overSteps(std::optional<int> frames = std::nullopt) {
  AnimationSettings animation;
  animation.overSteps = true;
  if (frames) animation.frames = *frames, animation.framesGiven = true;
  return animation;
}

TEST(VolumeSteps, AnIsosurfaceMovesWithItsFieldBetweenAndOnSteps) {
  MovingCube cube("isosurfaces = { field = \"s\", values = [0.25] }");
  StepScenes steps(cube.prepared->description, cube.prepared->meshes, overSteps(5), AccelKind::Bvh, 1);
  ASSERT_EQ(steps.frameCount(), 5);
  for (int frame = 0; frame < 5; ++frame) {
    const double t = steps.frames().times[static_cast<std::size_t>(frame)];
    EXPECT_DOUBLE_EQ(t, 0.5 * frame);
    const std::vector<Vec3d> points = cube.framePoints(steps, frame);
    ASSERT_FALSE(points.empty()) << "frame " << frame;
    for (const Vec3d& p : points) ASSERT_NEAR(p.x, 0.25 + t / 4, 1e-5) << "frame " << frame;
  }
}

TEST(VolumeSteps, FieldLinesFollowTheStepsField) {
  MovingCube cube("streamlines = { field = \"w\", seed_points = [[0.5, 0.5, 0.5]], radius = 0.01 }");
  StepScenes steps(cube.prepared->description, cube.prepared->meshes, overSteps(), AccelKind::Bvh, 1);
  ASSERT_EQ(steps.frameCount(), 3);
  for (int frame = 0; frame < 3; ++frame) {
    // The line through the centre along w: every vertex of its tube within a radius of it.
    const double angle = frame * std::numbers::pi / 6;
    const Vec3d along{std::cos(angle), std::sin(angle), 0}, centre{0.5, 0.5, 0.5};
    const std::vector<Vec3d> points = cube.framePoints(steps, frame);
    ASSERT_FALSE(points.empty()) << "frame " << frame;
    double farthest = 0, reach = 0;
    for (const Vec3d& p : points) {
      const Vec3d offset = p - centre;
      farthest = std::max(farthest, length(offset - along * dot(offset, along)));
      reach = std::max(reach, std::abs(dot(offset, along)));
    }
    EXPECT_LE(farthest, 0.0101) << "frame " << frame;
    EXPECT_GT(reach, 0.45) << "frame " << frame << ": the line crosses the cube";
  }
}

TEST(VolumeSteps, APinnedStepStaysPut) {
  MovingCube cube("isosurfaces = { field = \"s\", values = [0.25], step = 2 }");
  StepScenes steps(cube.prepared->description, cube.prepared->meshes, overSteps(3), AccelKind::Bvh, 1);
  for (int frame = 0; frame < steps.frameCount(); ++frame)
    for (const Vec3d& p : cube.framePoints(steps, frame)) ASSERT_NEAR(p.x, 0.75, 1e-5) << "frame " << frame;
}

}  // namespace
}  // namespace lancer
