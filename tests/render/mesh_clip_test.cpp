// Per-mesh cut views ([[mesh.clip]]): a mesh's own planes remove its faces only. Where the front
// mesh is cut away the back mesh shows exactly as if the front one were absent, the back mesh is
// not cut, removed parts cast no shadow and are not seen in mirrors, and a cut closed shell is
// capped exactly as a scene plane caps it; every accelerator and thread count agrees to the bit.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 64;
const ClipSettings kRemovePlusX{Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, true};

// World x of the centre of pixel column i in the views from +z below (4 units wide).
float columnX(int i) { return (static_cast<float>(i) + 0.5f) * 4.0f / kSize - 2.0f; }

Material flatMaterial(const char* name, Vec3 color) { return test::matteMaterial(name, color, color); }

// Seen orthographically from +z: a red square (mesh 0, z = 2, [-0.5, 0.5]^2) above a green one
// (mesh 1, z = 0, [-2, 2]^2), lit from (0, 0, 4), so the red one's shadow on the green is twice its size.
SceneDescription twoSquares() {
  SceneDescription d = test::topDownView(kSize, kSize, 4);
  d.render.shading = ShadingMode::Flat;
  d.render.background = {0, 0, 1};
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.lights = {{Vec3d{0, 0, 4}, {1, 1, 1}, {1, 0, 0}}};
  d.materials = {flatMaterial("front", {0.8f, 0.1f, 0.1f}), flatMaterial("back", {0.1f, 0.8f, 0.1f})};
  d.meshes.resize(2);
  d.meshes[0].material = 0;
  d.meshes[1].material = 1;
  return d;
}

std::vector<Mesh> twoSquareMeshes() {
  std::vector<Mesh> meshes;
  meshes.push_back(test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 2));
  meshes.push_back(test::squareMesh(-2, -2, 2, 2, 0));
  return meshes;
}

Image renderSquares(const SceneDescription& d, AccelKind accel = AccelKind::KdTreeSah, int threads = 0) {
  return test::renderMeshes(d, twoSquareMeshes(), accel, threads);
}

// The green square alone: what the cut-away half of the red one must reveal.
Image renderBackOnly(SceneDescription d) {
  d.meshes.erase(d.meshes.begin());
  std::vector<Mesh> meshes = twoSquareMeshes();
  meshes.erase(meshes.begin());
  return test::renderMeshes(d, std::move(meshes));
}

TEST(MeshClip, CutAwayPartRevealsTheMeshBehindUncutAndUnshadowed) {
  SceneDescription d = twoSquares();
  const Image whole = renderSquares(d);
  const Image backOnly = renderBackOnly(d);
  d.meshes[0].clips = {kRemovePlusX};
  const Image cut = renderSquares(d);
  int revealed = 0, unshadowed = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (columnX(x) > 0.0f) {
        // The red half and its shadow are gone: exactly the green square alone.
        EXPECT_EQ(cut.at(x, y), backOnly.at(x, y)) << x << "," << y;
        revealed += whole.at(x, y).r > 0.5f;
        unshadowed += whole.at(x, y).r <= 0.5f && whole.at(x, y) != backOnly.at(x, y);
      } else {
        // The kept half and its shadow (cast towards -x only: the light is at x = 0) are untouched.
        EXPECT_EQ(cut.at(x, y), whole.at(x, y)) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(revealed, (kSize / 8) * (kSize / 4)) << "the removed half of the red square, 8 x 16 pixels";
  EXPECT_GT(unshadowed, 100) << "the removed half's shadow, which must vanish";
  // Spot checks: red square kept at x < 0, green (lit) behind its removed half at x > 0.
  EXPECT_GT(cut.at(kSize / 2 - 4, kSize / 2).r, 0.5f);
  EXPECT_GT(cut.at(kSize / 2 + 4, kSize / 2).g, 0.5f);
}

TEST(MeshClip, TheMeshBehindIsNotCutByTheFrontMeshsPlanes) {
  // The same plane at scene level removes the green square's x > 0 half too (background shows).
  SceneDescription d = twoSquares();
  d.meshes[0].clips = {kRemovePlusX};
  const Image own = renderSquares(d);
  d.meshes[0].clips.clear();
  d.clips = {kRemovePlusX};
  const Image scene = renderSquares(d);
  const int x = kSize - 4, y = kSize / 2;
  EXPECT_EQ(scene.at(x, y).b, 1.0f);
  EXPECT_EQ(scene.at(x, y).g, 0.0f);
  EXPECT_GT(own.at(x, y).g, 0.5f);
}

TEST(MeshClip, AcceleratorsAndThreadCountsAgreeToTheBit) {
  SceneDescription d = twoSquares();
  d.meshes[0].clips = {kRemovePlusX, ClipSettings{Vec3d{0, 0.25, 0}, normalize(Vec3d{0, 1, 0.3}), true}};
  d.meshes[1].clips = {ClipSettings{Vec3d{1.5, 0, 0}, Vec3d{1, 0, 0}, false}};
  const Image reference = renderSquares(d, AccelKind::Naive, 1);
  EXPECT_EQ(renderSquares(d, AccelKind::Naive, 3), reference);
  EXPECT_EQ(renderSquares(d, AccelKind::KdTreeSah, 1), reference);
  EXPECT_EQ(renderSquares(d, AccelKind::KdTreeSah, 3), reference);
  EXPECT_EQ(renderSquares(d, AccelKind::KdTreeMedian, 3), reference);
}

TEST(MeshClip, AMirrorDoesNotSeeTheCutAwayPart) {
  // A half-mirror at z = 0 seen from +z reflects a red square at z = 10 (behind the orthographic
  // camera's rays, so only the mirror sees it), lit from below by a light at z = 8.
  SceneDescription d = twoSquares();
  d.render.maxDepth = 1;
  d.lights = {{Vec3d{0, 0, 8}, {1, 1, 1}, {1, 0, 0}}};
  Material mirror = flatMaterial("mirror", {0.2f, 0.2f, 0.2f});
  mirror.reflectivity = {0.5f, 0.5f, 0.5f};
  d.materials[1] = mirror;
  auto meshes = [] {
    std::vector<Mesh> list;
    list.push_back(test::squareMesh(-1, -1, 1, 1, 10));
    list.push_back(test::squareMesh(-2, -2, 2, 2, 0));
    return list;
  };
  SceneDescription mirrorOnly = d;
  mirrorOnly.meshes.erase(mirrorOnly.meshes.begin());
  std::vector<Mesh> mirrorMesh = meshes();
  mirrorMesh.erase(mirrorMesh.begin());
  const Image empty = test::renderMeshes(mirrorOnly, std::move(mirrorMesh));
  const Image whole = test::renderMeshes(d, meshes());
  d.meshes[0].clips = {kRemovePlusX};
  const Image cut = test::renderMeshes(d, meshes());
  int reflectedKept = 0, reflectedRemoved = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (columnX(x) > 0.0f) {
        EXPECT_EQ(cut.at(x, y), empty.at(x, y)) << x << "," << y;
        reflectedRemoved += whole.at(x, y) != empty.at(x, y);
      } else {
        reflectedKept += cut.at(x, y) != empty.at(x, y);
      }
    }
  }
  EXPECT_EQ(reflectedKept, (kSize / 4) * (kSize / 2)) << "the kept half in the mirror, 16 x 32 pixels";
  EXPECT_EQ(reflectedRemoved, reflectedKept) << "uncut, the mirror shows the other half too";
}

// ---- caps: a gmsh cube (the skin of a tetrahedral mesh) ------------------------------------------

Image renderCubes(const SceneDescription& d) {
  std::vector<Mesh> meshes;
  for (std::size_t i = 0; i < d.meshes.size(); ++i)
    meshes.push_back(readMsh(test::mshFixture("cube_tet4_v41_ascii.msh")));
  return test::renderMeshes(d, std::move(meshes));
}

// The unit cube from an oblique perspective view that sees into a cut at x = 0.5 and z = 0.8.
SceneDescription obliqueCube() {
  SceneDescription d;
  d.render.width = d.render.height = 48;
  d.render.maxDepth = 0;
  d.render.shading = ShadingMode::Flat;
  d.render.background = {0, 0, 1};
  d.camera.position = Vec3d{3, 1.6, 1.4};
  d.camera.lookAt = Vec3d{0.3, 0.5, 0.5};
  d.camera.fovDegrees = 40;
  d.lights = {{Vec3d{3, 3, 4}, {0.7f, 0.7f, 0.7f}, {1, 0, 0}}};
  d.materials = {flatMaterial("solid", {0.6f, 0.5f, 0.4f})};
  d.meshes.resize(1);
  return d;
}

TEST(MeshClip, AMeshsOwnPlanesCapItsShellExactlyAsScenePlanes) {
  // With one mesh, moving planes between the scene and the mesh changes nothing: the kept region
  // and the plane each cap lies on are the same. Mixed: one capped plane, one open.
  const std::vector<ClipSettings> planes = {{Vec3d{0.5, 0, 0}, Vec3d{1, 0, 0}, true},
                                            {Vec3d{0, 0, 0.8}, Vec3d{0, 0, 1}, false}};
  SceneDescription d = obliqueCube();
  d.clips = planes;
  const Image scene = renderCubes(d);
  d.clips = {};
  d.meshes[0].clips = planes;
  EXPECT_EQ(renderCubes(d), scene);
  d.clips = {planes[1]};
  d.meshes[0].clips = {planes[0]};
  EXPECT_EQ(renderCubes(d), scene);
  d.clips = {planes[0]};
  d.meshes[0].clips = {planes[1]};
  EXPECT_EQ(renderCubes(d), scene);
  // Without the cap the cut is open and the inside shows: the flag is honoured.
  d.clips = {};
  d.meshes[0].clips = planes;
  d.meshes[0].clips[0].cap = false;
  const Image open = renderCubes(d);
  int differing = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) differing += std::abs(open.at(x, y).r - scene.at(x, y).r) > 0.02f;
  EXPECT_GT(differing, 100);
}

TEST(MeshClip, CapShowsTheShellsColourInFrontOfAnUncutMesh) {
  // From +x: the cube's near half is cut away by its own plane x = 0.5, and a second, uncut cube of
  // another colour fills the view behind it. The light at 45 degrees over the cap tells it from
  // what an uncapped or uncut cube would show there (the inner wall x = 0, lit at 40 degrees; the
  // face x = 1, at 51).
  SceneDescription d =
      test::orthographicView(48, 48, Vec3d{5, 0.5, 0.5}, Vec3d{0, 0.5, 0.5}, 1.5, Vec3d{0, 0, 1});
  d.render.shading = ShadingMode::Flat;
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.lights = {{Vec3d{3, 0.5, 3}, {0.7f, 0.7f, 0.7f}, {1, 0, 0}}};
  d.materials = {flatMaterial("solid", {0.6f, 0.5f, 0.4f}), flatMaterial("behind", {0.1f, 0.3f, 0.9f})};
  d.meshes.resize(2);
  d.meshes[0].clips = {{Vec3d{0.5, 0, 0}, Vec3d{1, 0, 0}, true}};
  d.meshes[1].material = 1;
  d.meshes[1].translate = Vec3d{-4, -1, -1};
  d.meshes[1].scale = Vec3d{3, 3, 3};
  const Image image = renderCubes(d);
  // The cap's centre is a third of a pixel from (0.5, 0.5, 0.5), where the light is at 45 degrees.
  const float cosine = std::sqrt(0.5f);
  const Rgba centre = image.at(24, 24);
  EXPECT_NEAR(centre.r, 0.2f * 0.6f + 0.7f * 0.6f * cosine, 2e-3f);
  EXPECT_NEAR(centre.g, 0.2f * 0.5f + 0.7f * 0.5f * cosine, 2e-3f);
  EXPECT_NEAR(centre.b, 0.2f * 0.4f + 0.7f * 0.4f * cosine, 2e-3f);
  const Rgba corner = image.at(1, 1);  // outside the cut cube: the uncut one behind, lit
  EXPECT_GT(corner.b, 0.6f);
  EXPECT_LT(corner.r, 0.2f);
}

TEST(MeshClip, KeysAreRead) {
  const SceneDescription d = parseScene(
      "[[mesh]]\nfile = \"a.msh\"\n[[mesh.clip]]\npoint = [0, 1, 0]\nnormal = [0, 2, 0]\ncap = false\n"
      "[[mesh.clip]]\npoint = [1, 0, 0]\nnormal = [1, 0, 0]\n[[mesh]]\nfile = \"b.msh\"\n[[clip]]\n"
      "point = [0, 0, 0]\nnormal = [0, 0, 1]\n",
      "cut.toml");
  ASSERT_EQ(d.meshes.size(), 2u);
  ASSERT_EQ(d.meshes[0].clips.size(), 2u);
  EXPECT_EQ(d.meshes[0].clips[0].point, (Vec3d{0, 1, 0}));
  EXPECT_EQ(d.meshes[0].clips[0].normal, (Vec3d{0, 1, 0}));
  EXPECT_FALSE(d.meshes[0].clips[0].cap);
  EXPECT_TRUE(d.meshes[0].clips[1].cap);
  EXPECT_TRUE(d.meshes[1].clips.empty());
  ASSERT_EQ(d.clips.size(), 1u);
  EXPECT_EQ(d.clips[0].normal, (Vec3d{0, 0, 1}));
}

TEST(MeshClip, TheExampleCutsTwoMeshesAndLeavesTheFloorWhole) {
  const SceneDescription d = loadScene(LANCER_SOURCE_DIR "/examples/cut_per_mesh.toml");
  ASSERT_EQ(d.meshes.size(), 3u);
  EXPECT_EQ(d.meshes[0].clips.size(), 1u);
  EXPECT_EQ(d.meshes[1].clips.size(), 1u);
  EXPECT_TRUE(d.meshes[2].clips.empty());
  EXPECT_TRUE(d.clips.empty());
}

}  // namespace
}  // namespace lancer
