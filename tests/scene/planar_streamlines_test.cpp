// Field lines across flat 2D meshes, seed rectangles and tube radii in pixels as a user asks for
// them (scene files, the CLI): the tubes lie on the plane on the side the camera sees, a radius in
// pixels is the pixel's size at the camera's target for both projections, and requests that cannot
// be met exit 2 with a message naming the key and no picture.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/flat_scene.hpp"
#include "lancer/scene/results/streamline_seeds.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// The unit square of triangles (z = 0) with the node field "temperature" = (x, 2y, 2).
std::string square() { return test::dataFile("fields/node_vector_v41_bin.msh"); }

// A scene of `file` seen by `camera` (the [camera] table's keys) in a 100 x 100 picture, with
// `mesh` the rest of its [[mesh]] table.
std::string sceneOf(const std::string& file, const std::string& camera, const std::string& mesh) {
  return fmt::format(R"([render]
width = 100
height = 100

[camera]
{}

[[mesh]]
file = "{}"
{}
)",
                     camera, file, mesh);
}

// The scene's meshes with their volume views added, as a render makes them.
std::vector<Mesh> viewsOf(const std::string& path, SceneDescription& description) {
  description = loadScene(path);
  std::vector<std::shared_ptr<const VolumeMesh>> volumes;
  std::vector<Mesh> meshes = readSceneMeshes(description, 1, nullptr, &volumes);
  addVolumeViews(description, meshes, volumes);
  return meshes;
}

// The least and greatest z of a mesh's vertices (world).
std::pair<double, double> heightRange(const Mesh& mesh) {
  double low = INFINITY, high = -INFINITY;
  for (const Vec3& p : mesh.positions) {
    low = std::min(low, mesh.origin.z + p.z);
    high = std::max(high, mesh.origin.z + p.z);
  }
  return {low, high};
}

TEST(PlanarStreamlines, TubesOfTheRadiusAskedLieOnThePlaneOnTheCamerasSide) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("scene.toml");
  const struct {
    std::string camera;
    double radius;  // model units
    double side;    // +1 above z = 0, -1 below
  } cases[] = {
      // Orthographic: 2 / 100 a pixel.
      {"projection = \"orthographic\"\nposition = [0.5, 0.5, 5]\nlook_at = [0.5, 0.5, 0]\nview_height = 2",
       2 * 0.02, 1},
      // Perspective, 10 away with a 40 degree field of view: 2 tan 20 * 10 / 100 a pixel.
      {"position = [0.5, 0.5, -10]\nlook_at = [0.5, 0.5, 0]\nfov = 40",
       2 * 2 * std::tan(20 * std::numbers::pi / 180) * 10 / 100, -1},
  };
  for (const auto& c : cases) {
    std::ofstream(path) << sceneOf(square(), c.camera,
                                   "streamlines = { field = \"temperature\", seed_line = [[0.2, 0.1, 0], "
                                   "[0.2, 0.9, 0]], count = 3, radius = \"2px\" }");
    SceneDescription description;
    const std::vector<Mesh> meshes = viewsOf(path, description);
    ASSERT_EQ(meshes.size(), 2U) << c.camera;
    EXPECT_TRUE(description.meshes[1].liesOnPlane);
    EXPECT_FALSE(description.meshes[0].liesOnPlane);
    const auto [low, high] = heightRange(meshes[1]);
    // The tube's centre 1.01 radii off the plane: it spans 0.01 to 2.01 radii on its side.
    const double near = c.side > 0 ? low : -high, far = c.side > 0 ? high : -low;
    EXPECT_NEAR(near, 0.01 * c.radius, 1e-3 * c.radius) << c.camera;
    EXPECT_NEAR(far, 2.01 * c.radius, 1e-3 * c.radius) << c.camera;
  }
}

TEST(PlanarStreamlines, AFlatSceneStaysFlatAndItsOwnFieldsLinesAreWhite) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("scene.toml");
  // No camera: the automatic one, which sees a flat scene straight on, tubes and all.
  std::ofstream(path) << sceneOf(square(), "",
                                 "color_by = { field = \"temperature\" }\nstreamlines = { field = "
                                 "\"temperature\", count = 4 }");
  SceneDescription description;
  const std::vector<Mesh> meshes = viewsOf(path, description);
  ASSERT_EQ(meshes.size(), 2U);
  EXPECT_TRUE(applyFlatSceneDefaults(description, meshes, FlatSceneChoices{}));
  EXPECT_EQ(description.camera.projection, Projection::Orthographic);
  EXPECT_NEAR(description.camera.viewFrom.z, 1.0, 1e-12);
  // Over the surface painted by their own field, the tubes are one colour, white.
  const MeshInstance& tubes = description.meshes[1];
  EXPECT_FALSE(tubes.colorBy.has_value());
  const Material& material = description.materials[static_cast<std::size_t>(tubes.material)];
  EXPECT_EQ(material.kd.x, 1.0F);
  EXPECT_EQ(material.kd.z, 1.0F);
  // The tubes lie above z = 0, where the camera is.
  EXPECT_GT(heightRange(meshes[1]).first, 0.0);
}

TEST(PlanarStreamlines, APixelIsTheWindowOverTheHeightAtTheTarget) {
  CameraSettings camera;
  camera.projection = Projection::Orthographic;
  camera.position = Vec3d{0, 0, 5};
  camera.lookAt = Vec3d{0, 0, 0};
  camera.viewHeight = 3;
  Aabbd box;
  box.extend(Vec3d{-1, -1, -1});
  box.extend(Vec3d{1, 1, 1});
  EXPECT_DOUBLE_EQ(pixelSizeAtTarget(camera, box, 200, 150), 3.0 / 150);
  camera.zoom = 2;  // a window half as high
  EXPECT_DOUBLE_EQ(pixelSizeAtTarget(camera, box, 200, 150), 1.5 / 150);
  CameraSettings perspective;
  perspective.position = Vec3d{0, 3, 4};
  perspective.lookAt = Vec3d{0, 0, 0};
  perspective.fovDegrees = 90;
  EXPECT_NEAR(pixelSizeAtTarget(perspective, box, 200, 100), 2 * 1.0 * 5 / 100, 1e-12);
  // The automatic camera: where placeAutomaticCamera puts it.
  CameraSettings automatic;
  const CameraSettings placed = placeAutomaticCamera(automatic, box, 2.0);
  const double distance = length(*placed.position - *placed.lookAt);
  EXPECT_NEAR(pixelSizeAtTarget(automatic, box, 200, 100),
              2 * std::tan(20 * std::numbers::pi / 180) * distance / 100, 1e-12);
}

TEST(PlanarStreamlines, RectangleSeedsAreAGridOfNearSquareCells) {
  // 6 on a 2 x 1 rectangle: 3 columns, 2 rows, each seed at its cell's centre.
  const std::vector<Vec3d> six = rectangleSeeds({1, 1, 1}, {2, 0, 0}, {0, 1, 0}, 6);
  ASSERT_EQ(six.size(), 6U);
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 3; ++column) {
      const Vec3d expected{1 + 2 * (column + 0.5) / 3, 1 + (row + 0.5) / 2, 1};
      EXPECT_LT(length(six[static_cast<std::size_t>(row * 3 + column)] - expected), 1e-12) << row << column;
    }
  // 7 on a square: 3 columns, 3 rows, the last row's one seed in its middle.
  const std::vector<Vec3d> seven = rectangleSeeds({0, 0, 0}, {0, 0, 3}, {3, 0, 0}, 7);
  ASSERT_EQ(seven.size(), 7U);
  EXPECT_LT(length(seven[0] - Vec3d{0.5, 0, 0.5}), 1e-12);
  EXPECT_LT(length(seven[6] - Vec3d{2.5, 0, 1.5}), 1e-12);
  // A parallelogram: the grid follows its edges.
  const std::vector<Vec3d> sheared = rectangleSeeds({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, 1);
  EXPECT_LT(length(sheared[0] - Vec3d{1, 0.5, 0}), 1e-12);
}

TEST(PlanarStreamlines, TheCliDrawsLinesAcrossA2dResultAndFromARectangle) {
  const test::ScratchFolder folder;
  const std::string magnet = test::dataFile("getdp/magnet_v2_b.pos");
  for (const std::string& options :
       {std::string("--streamlines b:12 --streamline-radius 1.5px"),
        std::string("--streamlines b:6 --seed-line -0.2,0.05,0,0.2,0.05,0 --color-by b"),
        std::string("--streamlines b:6 --seed-rectangle -0.1,0.02,0,0.2,0,0,0,0.05,0")}) {
    const std::string out = folder.file("out.png");
    const test::CommandResult run =
        test::runCli("render " + test::quoted(magnet) + " " + options + " --width 48 --height 32 -q -o " +
                     test::quoted(out) + " 2>&1");
    EXPECT_EQ(run.exitCode, 0) << options << "\n" << run.output;
    EXPECT_TRUE(std::filesystem::exists(out)) << options;
    std::filesystem::remove(out);
  }
}

TEST(PlanarStreamlines, RequestsThatCannotBeMetExitTwoWithoutAPicture) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  const std::string sphere = test::dataFile("msh/sphere_v41_bin.msh");
  const std::string surfaceScalar = test::dataFile("element_node/quad9_v41_bin.msh");
  const std::string cube = test::dataFile("element_node/tet_v41_bin.msh");
  const struct {
    std::string input, options, message;
  } cases[] = {
      {sphere, "--streamlines n", "has no volume elements and its faces are not in one plane"},
      {surfaceScalar, "--streamlines f", "field lines follow a vector (3 components)"},
      {square(), "--streamlines temperature --seed-rectangle 0,0,0,0,0,0,0,1,0",
       "the edge UX,UY,UZ is 0,0,0"},
      {square(), "--streamlines temperature --seed-rectangle 0,0,0,1,0,0,2,0,0",
       "the two edges are parallel"},
      {square(), "--streamlines temperature --seed-rectangle 0,0,0,1,0", "is not a rectangle"},
      {square(), "--streamlines temperature --streamline-radius -2px",
       "a radius in pixels must be greater than 0"},
      {square(), "--streamlines temperature --streamline-radius wide", "is not a radius"},
      {square(), "--seed-rectangle 0,0,0,1,0,0,0,1,0", "add --streamlines"},
      {square(), "--streamlines temperature --seed-line 0,0,0,1,1,0 --seed-rectangle 0,0,0,1,0,0,0,1,0",
       "keep one"},
      {square(), "--streamlines temperature --isosurfaces temperature", "slices and isosurfaces are drawn"},
      {cube, "--streamlines u --seed-rectangle 5,5,5,1,0,0,0,1,0",
       "none of the 50 seeds is inside the volume"},
  };
  for (const auto& c : cases) {
    const test::CommandResult run =
        test::runCli("render " + test::quoted(c.input) + " " + c.options + " --width 32 --height 32 -q -o " +
                     test::quoted(out) + " 2>&1");
    EXPECT_EQ(run.exitCode, 2) << c.options << "\n" << run.output;
    EXPECT_TRUE(test::contains(run.output, c.message)) << c.options << "\n" << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.options;
  }
}

TEST(PlanarStreamlines, SceneFileKeysAreChecked) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("scene.toml");
  const std::string camera = "position = [0.5, 0.5, 5]";
  const struct {
    std::string mesh, message;
  } cases[] = {
      {"streamlines = { field = \"temperature\", seed_rectangle = [[0, 0, 0], [0, 0, 0], [0, 1, 0]] }",
       "mesh[0].streamlines.seed_rectangle is a corner and the two edges from it"},
      {"streamlines = { field = \"temperature\", seed_rectangle = [[0, 0, 0], [1, 0, 0]] }",
       "must be an array of 3 points"},
      {"streamlines = { field = \"temperature\", seed_rectangle = [[0, 0, 0], [1, 1, 0], [2, 2, 0]] }",
       "its two edges are parallel"},
      {"streamlines = { field = \"temperature\", radius = \"-2px\" }",
       "mesh[0].streamlines.radius must be a length in model units (0.01) or in pixels greater than 0"},
      {"streamlines = { field = \"temperature\", radius = \"2 pt\" }", "found \"2 pt\""},
      {"streamlines = { field = \"temperature\", radius = -2 }", "mesh[0].streamlines.radius must be > 0"},
      {"streamlines = { field = \"temperature\", seed_line = [[0, 0, 0], [1, 1, 0]], seed_rectangle = [[0, "
       "0, "
       "0], [1, 0, 0], [0, 1, 0]] }",
       "gives seeds more than one way"},
      {"streamlines = { field = \"temperature\", seed_points = [[5, 5, 0]] }",
       "none of the 1 seeds is inside the 2D domain"},
  };
  for (const auto& c : cases) {
    std::ofstream(path) << sceneOf(square(), camera, c.mesh);
    const test::CommandResult run = test::runCli("render " + test::quoted(path) + " -q -o " +
                                                 test::quoted(folder.file("out.png")) + " 2>&1");
    EXPECT_EQ(run.exitCode, 2) << c.mesh << "\n" << run.output;
    EXPECT_TRUE(test::contains(run.output, c.message)) << c.mesh << "\n" << run.output;
    // The message names the scene file and the key's line.
    EXPECT_TRUE(test::contains(run.output, "scene.toml:")) << run.output;
  }
}

}  // namespace
}  // namespace lancer
