// Cut views: a gmsh cube (the skin of a tetrahedral mesh) cut by a clip plane shows its cap as a
// flat face in its material, lit like one; without a cap the inside shows; clipped geometry casts
// no shadow; a plane that removes everything leaves the background.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 48;

// The unit cube seen orthographically from +x, one light straight along the view axis.
SceneDescription cubeFromPlusX() {
  SceneDescription d = test::flatLitOnBlue(
      test::orthographicView(kSize, kSize, Vec3d{5, 0.5, 0.5}, Vec3d{0, 0.5, 0.5}, 1.5, Vec3d{0, 0, 1}),
      Vec3d{20, 0.5, 0.5});
  d.materials = {test::matteMaterial("solid", {0.5f, 0.4f, 0.3f}, {0.6f, 0.5f, 0.4f})};
  d.meshes.resize(1);
  return d;
}

Image renderCube(const SceneDescription& d) {
  return test::renderMeshes(d, {readMsh(test::mshFixture("cube_tet4_v41_ascii.msh"))});
}

TEST(Clip, CapIsAFlatFaceInTheShellsMaterialLitByTheModel) {
  SceneDescription d = cubeFromPlusX();
  d.clips = {{Vec3d{0.5, 0, 0}, Vec3d{1, 0, 0}, true}};
  const Image image = renderCube(d);
  // The cap at x = 0.5 faces the light head on (light 19.5 away, along the normal: cos = 1).
  const Rgba centre = image.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(centre.r, 0.2f * 0.5f + 0.7f * 0.6f, 1e-4f);
  EXPECT_NEAR(centre.g, 0.2f * 0.4f + 0.7f * 0.5f, 1e-4f);
  // Every pixel inside the square the cube covers shows the cap (the same flat colour).
  int capPixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (image.at(x, y).b != 1.0f) {
        EXPECT_NEAR(image.at(x, y).r, centre.r, 2e-3f)
            << x << "," << y;  // the light is 20 away, not at infinity
        ++capPixels;
      }
  EXPECT_NEAR(capPixels, (kSize / 1.5) * (kSize / 1.5), 2 * kSize);
}

TEST(Clip, WithoutCapTheInsideShowsAndTheCutIsOpen) {
  // From an oblique perspective view the open cut shows the inner walls, lit and shadowed unlike
  // the flat cap; away from the cut both pictures agree.
  SceneDescription d = cubeFromPlusX();
  d.camera.projection = Projection::Perspective;
  d.camera.position = Vec3d{3, 1.6, 1.4};
  d.camera.lookAt = Vec3d{0.3, 0.5, 0.5};
  d.camera.fovDegrees = 40;
  d.lights = {{Vec3d{3, 3, 4}, {0.7f, 0.7f, 0.7f}, {1, 0, 0}}};
  d.clips = {{Vec3d{0.5, 0, 0}, Vec3d{1, 0, 0}, false}};
  const Image open = renderCube(d);
  d.clips[0].cap = true;
  const Image capped = renderCube(d);
  int differing = 0, cube = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (capped.at(x, y).b == 1.0f && capped.at(x, y).r == 0.0f) continue;  // background
      ++cube;
      if (std::abs(open.at(x, y).r - capped.at(x, y).r) > 0.02f) ++differing;
    }
  }
  EXPECT_GT(cube, 200);
  EXPECT_GT(differing, cube / 5) << "the open cut should show the inside where the cap is";
  EXPECT_LT(differing, cube) << "faces away from the cut are the same in both";
}

TEST(Clip, RemovedGeometryCastsNoShadowAndAllClippedShowsBackground) {
  // A floor-like square at z = 0 and an occluder square at z = 1 between it and the light, seen
  // from above: clipping z > 0.5 removes the occluder and its shadow.
  SceneDescription d = test::topDownView(32, 32, 2);
  d.render.shading = ShadingMode::Flat;
  d.lights = {{Vec3d{0, 0, 10}, {1, 1, 1}, {1, 0, 0}}};
  Material m;
  m.name = "m";
  m.ks = {0, 0, 0};
  d.materials = {m};
  d.meshes.resize(2);
  auto meshes = [] {
    std::vector<Mesh> list;
    list.push_back(test::squareMesh(-2, -2, 2, 2, 0));
    list.push_back(test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1));
    return list;
  };
  const Image shadowed = test::renderMeshes(d, meshes());
  d.clips = {{Vec3d{0, 0, 0.5}, Vec3d{0, 0, 1}, true}};
  const Image clipped = test::renderMeshes(d, meshes());
  // Centre: the occluder (lit) before; the floor, lit because nothing shadows it any more, after.
  const float floorLit = d.ambient.x * m.ka.x + m.kd.x * 1.0f;
  EXPECT_NEAR(clipped.at(16, 16).r, floorLit, 1e-3f);
  // Just outside the occluder's view but inside its shadow: dark before, lit after.
  EXPECT_LT(shadowed.at(16 + 8, 16).r, floorLit - 0.3f);
  EXPECT_NEAR(clipped.at(16 + 8, 16).r, floorLit, 1e-3f);
  d.clips = {{Vec3d{0, 0, -1}, Vec3d{0, 0, 1}, true}};
  d.render.background = {0.25f, 0.5f, 0.75f};
  const Image empty = test::renderMeshes(d, meshes());
  EXPECT_EQ(empty.at(16, 16).g, 0.5f);
}

TEST(Clip, SceneKeysAreRead) {
  const SceneDescription d = parseScene(
      "[[clip]]\npoint = [0, 1, 0]\nnormal = [0, 2, 0]\ncap = false\n[[clip]]\npoint = [0, 0, 0]\nnormal = "
      "[1, 0, 0]\n",
      "cut.toml");
  ASSERT_EQ(d.clips.size(), 2u);
  EXPECT_EQ(d.clips[0].normal, (Vec3d{0, 1, 0}));
  EXPECT_FALSE(d.clips[0].cap);
  EXPECT_TRUE(d.clips[1].cap);
}

TEST(ClipBadInput, MissingOrZeroNormalIsAClearError) {
  test::expectSceneErrorContains("[[clip]]\npoint = [0, 0, 0]\n", "normal", "cut.toml");
  test::expectSceneErrorContains("[[clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n",
                                 "clip[0].normal must not be [0, 0, 0]", "cut.toml");
  test::expectSceneErrorContains("[[clip]]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\ncpa = true\n",
                                 "did you mean 'cap'", "cut.toml");
}

}  // namespace
}  // namespace lancer
