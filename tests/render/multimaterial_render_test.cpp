// Multi-material volume meshes rendered against closed forms (gmsh fixtures in
// tests/data/multimaterial): a capped cut through a cube holding a ball shows each volume's region
// of the cut in its material up to the ball's exact circle, an uncapped cut shows the inner volume's
// surfaces, light crossing from glass into water bends by the ratio of their indices, an
// index-matched ball is invisible, and the kd-tree and brute force give the same pictures.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/quick_look.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

std::string multimaterial(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/multimaterial/" + name;
}

// Shows only ambient light, so a pixel's value is exactly its material's ka.
Material flatColour(const char* name, Vec3 ka) { return test::ambientOnlyMaterial(name, ka); }

constexpr int kSize = 120;
constexpr double kViewHeight = 2.4;
const Vec3 kCubeColour{1, 0, 0}, kBallColour{0, 0, 1};

// The cube [-1, 1]^3 ("Cube" or "Box") with a ball or cylinder of radius 0.6 ("Ball" or "Cylinder")
// on the z axis, seen orthographically along -z after removing z > cut.
SceneDescription cutAlongZ(double cut, bool cap, const char* outerGroup, const char* innerGroup) {
  SceneDescription d = test::topDownView(kSize, kSize, kViewHeight);
  d.render.shading = ShadingMode::Flat;
  d.render.background = {0, 1, 0};
  d.ambient = {1, 1, 1};
  d.materials = {flatColour("outer", kCubeColour), flatColour("inner", kBallColour)};
  d.meshes.resize(1);
  d.meshes[0].groupMaterials = {{outerGroup, 0, {}}, {innerGroup, 1, {}}};
  d.clips = {{Vec3d{0, 0, cut}, Vec3d{0, 0, 1}, cap}};
  return d;
}

// Pixels farther than 1.5 pixels from the circle of radius 0.6 must show the inner colour inside
// it and the outer colour outside it (within the cube); returns how many do not.
int pixelsOffTheCircle(const Image& image) {
  const double pixel = kViewHeight / kSize;
  int wrong = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const double x = (i + 0.5 - kSize / 2.0) * pixel, y = (kSize / 2.0 - j - 0.5) * pixel;
      const double r = std::hypot(x, y);
      const Rgba seen = image.at(i, j);
      const Vec3 colour{seen.r, seen.g, seen.b};
      if (r < 0.6 - 1.5 * pixel) {
        wrong += !(colour == kBallColour);
      } else if (r > 0.6 + 1.5 * pixel && std::max(std::abs(x), std::abs(y)) < 1 - 1.5 * pixel) {
        wrong += !(colour == kCubeColour);
      }
    }
  }
  return wrong;
}

TEST(MultiMaterialRender, CapsFillEachVolumesRegionOfTheCutUpToTheExactCircle) {
  for (const char* file : {"cube_sphere_v41.msh", "cube_sphere_v22.msh", "cube_sphere_o2_v41.msh",
                           "cube_sphere_saveall_v41.msh"}) {
    const SceneDescription d = cutAlongZ(0.0, true, "Cube", "Ball");
    const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial(file))});
    EXPECT_EQ(pixelsOffTheCircle(test::renderScene(d, scene)), 0) << file;
  }
  for (const char* file : {"box_cylinder_hex_v41.msh", "box_cylinder_hex27_v41.msh"}) {
    const SceneDescription d = cutAlongZ(0.0, true, "Box", "Cylinder");
    const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial(file))});
    EXPECT_EQ(pixelsOffTheCircle(test::renderScene(d, scene)), 0) << file;
  }
}

// Saved without physical groups, gmsh writes the surfaces on the interface too (tutorial t18 does
// so): the ball's surface was a closed shell of the cube's group (none) inside the cube's skin, so a
// cavity wall, and the cut showed a hole with the lit far wall in it (up to 192/255 off). Now the
// whole cut square is one flat, lit cap.
TEST(MultiMaterialRender, VolumesWithoutPhysicalGroupsAreCappedEverywhere) {
  SceneDescription d = cutAlongZ(0.0, true, "", "");
  d.meshes[0].groupMaterials.clear();
  d.materials[0].kd = {1, 1, 1};
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.lights = {{Vec3d{3e4, 2e4, 1e5}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}}};  // far: one direction
  const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial("cube_sphere_nogroups_v41.msh"))});
  const Image image = test::renderScene(d, scene);
  const Rgba cap = image.at(kSize / 2, kSize / 2);
  EXPECT_GT(cap.r, 0.2f);  // lit
  int inSquare = 0, other = 0;
  for (int j = 4; j < kSize - 4; ++j) {
    for (int i = 4; i < kSize - 4; ++i) {
      const double x = (i + 0.5 - kSize / 2.0) * kViewHeight / kSize,
                   y = (kSize / 2.0 - j - 0.5) * kViewHeight / kSize;
      if (std::max(std::abs(x), std::abs(y)) > 0.97) continue;
      ++inSquare;
      other += std::abs(image.at(i, j).r - cap.r) > 1e-4f;
    }
  }
  EXPECT_GT(inSquare, kSize * kSize / 2);
  EXPECT_EQ(other, 0);
}

TEST(MultiMaterialRender, UncappedCutsShowTheInnerVolumesSurfaces) {
  // Through the ball: inside the circle the ball's far wall, outside it the cube's.
  const SceneDescription through = cutAlongZ(0.0, false, "Cube", "Ball");
  const Mesh mesh = readMsh(multimaterial("cube_sphere_v41.msh"));
  EXPECT_EQ(pixelsOffTheCircle(test::renderMeshes(through, {mesh})), 0);
  // In front of the ball: the ball's own outer surface, seen through the removed part of the cube.
  const SceneDescription before = cutAlongZ(0.8, false, "Cube", "Ball");
  EXPECT_EQ(pixelsOffTheCircle(test::renderMeshes(before, {mesh})), 0);
  // Capped in front of the ball, the cube's cap hides it.
  const SceneDescription capped = cutAlongZ(0.8, true, "Cube", "Ball");
  const Image image = test::renderMeshes(capped, {mesh});
  const Rgba centre = image.at(kSize / 2, kSize / 2);
  EXPECT_EQ((Vec3{centre.r, centre.g, centre.b}), kCubeColour);
}

// Calls visit(colour, p) for every pixel of an orthographic view from `position` towards the origin
// (up +y), with p where the pixel's ray meets the plane z = 0.
template <typename Visit>
void forEachPixelOnTheCut(const Image& image, const Vec3d& position, Visit&& visit) {
  const Vec3d forward = normalize(Vec3d{0, 0, 0} - position);
  const Vec3d right = normalize(cross(forward, Vec3d{0, 1, 0}));  // the camera's frame
  const Vec3d up = cross(right, forward);
  const double pixel = kViewHeight / kSize;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const Vec3d origin =
          position + right * ((i + 0.5 - kSize / 2.0) * pixel) + up * ((kSize / 2.0 - j - 0.5) * pixel);
      const Rgba seen = image.at(i, j);
      visit(Vec3{seen.r, seen.g, seen.b}, origin + forward * (-origin.z / forward.z));
    }
  }
}

// A cap in front of a shadow catcher that touches the part's lowest point: a ray that enters the cap
// near the bottom runs inside the cube down to the bottom face, where the catcher lies too. The cap
// is what it sees (the catcher was compared with the far face instead, and won half the time).
TEST(MultiMaterialRender, CapsStayInFrontOfACoincidentShadowCatcher) {
  SceneDescription d = cutAlongZ(0.0, true, "Cube", "Ball");
  d.floor = FloorSettings{};  // at the lowest vertex, y = -1: under the cube's bottom face
  const Vec3d position{0, 3, 5};
  d.camera.position = position;
  const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial("cube_sphere_v41.msh"))});
  int onCap = 0, wrong = 0;
  forEachPixelOnTheCut(test::renderScene(d, scene), position, [&](const Vec3& colour, const Vec3d& p) {
    if (std::max(std::abs(p.x), std::abs(p.y)) > 1 - 2 * kViewHeight / kSize) return;
    ++onCap;
    wrong += !(colour == kCubeColour || colour == kBallColour);
  });
  EXPECT_GT(onCap, kSize * kSize / 4);
  EXPECT_EQ(wrong, 0);
}

// Surfaces only (tests/data/render/nested_spheres.geo: a "Steel" sphere of radius 0.5 inside a
// "Glass" sphere of radius 1, no volume elements): the region between them is the glass's, so a ray
// that enters the cut there and meets the steel sphere from outside sees the glass cap, not the
// steel surface; inside the small sphere, the steel cap.
TEST(MultiMaterialRender, SurfacesNestedInAnotherGroupsSolidAreCappedByTheInnermostRegion) {
  SceneDescription d = cutAlongZ(0.0, true, "Glass", "Steel");
  const Vec3d position{0, 3, 5};  // tilted: rays from the ring run down onto the steel sphere
  d.camera.position = position;
  const Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/render/nested_spheres.msh")});
  const double margin = 2 * kViewHeight / kSize;
  int ring = 0, core = 0, wrong = 0;
  forEachPixelOnTheCut(test::renderScene(d, scene), position, [&](const Vec3& colour, const Vec3d& p) {
    const double r = std::hypot(p.x, p.y);
    if (r > 0.5 + margin && r < 0.97 - margin) {  // the faceted spheres: a little inside their radii
      ++ring;
      wrong += !(colour == kCubeColour);
    } else if (r < 0.48 - margin) {
      ++core;
      wrong += !(colour == kBallColour);
    }
  });
  EXPECT_GT(ring, 1000);
  EXPECT_GT(core, 500);
  EXPECT_EQ(wrong, 0);
}

// Surfaces only, meeting three on the rim of the shared wall (tests/data/multimaterial/
// slabs_surfaces.geo: glass over water, each slab's boundary a Physical Surface): cut at x = 0.3 and
// seen along -x, each slab's region of the cut is a flat cap in its group's colour, lit by a far
// light up and to the front. Before, the regions were not found and the far walls showed instead,
// in the shadow of the slabs' tops.
TEST(MultiMaterialRender, SurfacesMeetingThreeOnAnEdgeAreCappedRegionByRegion) {
  SceneDescription d = cutAlongZ(0.0, true, "Glass", "Water");
  d.clips = {{Vec3d{0.3, 0, 0}, Vec3d{1, 0, 0}, true}};
  d.camera.position = Vec3d{6, 0, 0};
  d.camera.viewHeight = 3.0;
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.lights = {{Vec3d{1e5, 1e5, 0}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}}};
  for (Material& m : d.materials) m.kd = m.ka;
  const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial("slabs_surfaces_v41.msh"))});
  for (std::size_t f = 0; f < scene.geometry.faces.size(); ++f)
    ASSERT_TRUE(scene.geometry.faceBoundsSolid[f]) << f;
  const Image image = test::renderScene(d, scene);
  const float lit = 0.2f + 0.8f * std::sqrt(0.5f);  // cap normal +x, light along (1, 1, 0)
  const double pixel = 3.0 / kSize;
  int glass = 0, water = 0, wrong = 0;
  for (int j = 0; j < kSize; ++j) {
    const double y = (kSize / 2.0 - j - 0.5) * pixel;
    for (int i = 0; i < kSize; ++i) {
      const double z = (i + 0.5 - kSize / 2.0) * pixel;  // the image's right is -z seen from +x
      if (std::abs(z) > 2 - 2 * pixel) continue;
      const Rgba seen = image.at(i, j);
      if (y > 2 * pixel && y < 1 - 2 * pixel) {
        ++glass;
        wrong += std::abs(seen.r - lit) > 1e-3f || seen.b != 0.0f;
      } else if (y < -2 * pixel && y > -1 + 2 * pixel) {
        ++water;
        wrong += std::abs(seen.b - lit) > 1e-3f || seen.r != 0.0f;
      }
    }
  }
  EXPECT_GT(glass, 1000);
  EXPECT_GT(water, 1000);
  EXPECT_EQ(wrong, 0);
}

// Three volumes, capped and lit: the kd-tree and brute force, and 1 and 3 threads, agree exactly.
TEST(MultiMaterialRender, KdTreeAndBruteForceGiveTheSameCutView) {
  SceneDescription d = cutAlongZ(0.0, true, "Housing", "Bushing");
  d.render.width = 96;
  d.render.height = 72;
  d.render.shading = ShadingMode::Phong;
  d.camera.position = Vec3d{2.5, 2.5, 3.5};
  d.camera.lookAt = Vec3d{0, 0.5, 0};
  d.camera.projection = Projection::Perspective;
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.lights = {{Vec3d{-3, 8, 6}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}}};
  for (Material& m : d.materials) m.kd = m.ka;
  d.materials.push_back(flatColour("shaft", {0.8f, 0.8f, 0.2f}));
  d.materials.back().kd = d.materials.back().ka;
  d.meshes[0].groupMaterials.push_back({"Shaft", 2, {}});
  const Scene scene = test::sceneFromMeshes(d, {readMsh(multimaterial("three_materials_v41.msh"))});
  const Image kd = test::renderScene(d, scene, AccelKind::KdTreeSah, 1);
  EXPECT_EQ(test::psnr8(kd, test::renderScene(d, scene, AccelKind::Naive, 1)), INFINITY);
  EXPECT_EQ(test::psnr8(kd, test::renderScene(d, scene, AccelKind::KdTreeSah, 3)), INFINITY);
}

// The quick look colours the groups seen from outside as it would without interfaces (here one
// group: the neutral colour, so the part looks as it did), and the volumes met only inside it next.
TEST(MultiMaterialRender, QuickLookKeepsTheOutsideColoursAndPaintsInnerVolumes) {
  const std::string path = multimaterial("cube_sphere_v41.msh");
  const SceneDescription d = quickLookScene(path, readMsh(path));
  ASSERT_EQ(d.meshes.size(), 1u);
  ASSERT_EQ(d.meshes[0].groupMaterials.size(), 1u);
  EXPECT_EQ(d.meshes[0].groupMaterials[0].group, "2");  // "Ball"
  EXPECT_EQ(d.materials.at(static_cast<std::size_t>(d.meshes[0].groupMaterials[0].material)).name, "Ball");
  EXPECT_EQ(d.meshes[0].material, 0);  // the cube: the neutral default
}

// ---- refraction across an interface ---------------------------------------------------------------

constexpr double kDegree = std::numbers::pi / 180.0;

// Glass over water (tests/data/multimaterial/glass_water_slabs.geo, turned so that the glass is
// z in [0, 1] and the water z in [-1, 0]) above a screen at z = -1.5, red for x < kEdge and green
// beyond, seen orthographically along (sin t, 0, -cos t). A ray bends at each plane by Snell's law
// with the ratio of the indices on its two sides, so the column where the screen turns green is
// predicted exactly; treating the glass-water plane as glass-air-water would move it by pixels.
constexpr double kTilt = 40 * kDegree;
constexpr double kEdge = 0.5;
constexpr int kWidth = 256;
constexpr double kPixel = 0.005;

// The first column whose ray lands at x >= kEdge, for glass of index nGlass and the ratio of
// indices used at the glass-water plane (nGlass / nWater when right).
int predictedEdgeColumn(const Vec3d& cameraPosition, double nGlass, double glassToWaterEta) {
  const double sinGlass = std::sin(kTilt) / nGlass;
  const double sinWater = glassToWaterEta * sinGlass;
  const auto tanOf = [](double s) { return s / std::sqrt(1 - s * s); };
  for (int i = 0; i < kWidth; ++i) {
    const double u = (i + 0.5 - kWidth / 2.0) * kPixel;  // along the image's right, (cos t, 0, sin t)
    const Vec3d origin = cameraPosition + Vec3d{std::cos(kTilt), 0, std::sin(kTilt)} * u;
    const double topX = origin.x + (origin.z - 1) * std::tan(kTilt);
    // Leaving the water into air the ray takes the angle it had in air again (n sin t is kept).
    const double landX = topX + tanOf(sinGlass) + tanOf(sinWater) + 0.5 * std::tan(kTilt);
    if (landX >= kEdge) return i;
  }
  return kWidth;
}

int measuredEdgeColumn(double nGlass, double nWater, Vec3d& cameraPosition) {
  Material glass = flatColour("glass", {0, 0, 0}), water = flatColour("water", {0, 0, 0});
  glass.transparency = water.transparency = 1;
  glass.ior = static_cast<float>(nGlass);
  water.ior = static_cast<float>(nWater);
  const Vec3d direction{std::sin(kTilt), 0, -std::cos(kTilt)};
  const Vec3d lookAt{kEdge - 1.45, 0, 1};
  cameraPosition = lookAt - direction * 5.0;
  SceneDescription d = test::orthographicView(kWidth, 4, cameraPosition, lookAt, 4 * kPixel);
  d.render.maxDepth = 8;
  d.render.background = {0, 0, 0};
  d.ambient = {1, 1, 1};
  d.materials = {glass, water, flatColour("red", {1, 0, 0}), flatColour("green", {0, 1, 0})};
  d.meshes.resize(3);
  d.meshes[0].groupMaterials = {{"Glass", 0, {}}, {"Water", 1, {}}};
  d.meshes[0].rotateDegrees = {90, 0, 0};  // (x, y, z) -> (x, -z, y): the slabs stack along z
  d.meshes[1].material = 2;
  d.meshes[2].material = 3;
  const Scene scene = test::sceneFromMeshes(
      d, {readMsh(multimaterial("glass_water_slabs_v41.msh")), test::squareMesh(-4, -4, kEdge, 4, -1.5f),
          test::squareMesh(kEdge, -4, 4, 4, -1.5f)});
  const Image image = test::renderScene(d, scene);
  for (int i = 0; i < kWidth; ++i)
    if (image.at(i, 2).g > 0.5f) return i;
  return kWidth;
}

TEST(MultiMaterialRender, RayCrossingFromGlassIntoWaterBendsByTheRatioOfTheirIndices) {
  Vec3d camera;
  const int measured = measuredEdgeColumn(1.5, 1.33, camera);
  const int predicted = predictedEdgeColumn(camera, 1.5, 1.5 / 1.33);
  EXPECT_NEAR(measured, predicted, 1);
  // The test can tell: glass-air-water at that plane (eta 1 / 1.33) lands many pixels away.
  EXPECT_GT(std::abs(predictedEdgeColumn(camera, 1.5, 1 / 1.33) - predicted), 10);
  // Index-matched water does not bend the ray at the plane at all.
  const int matched = measuredEdgeColumn(1.5, 1.5, camera);
  EXPECT_NEAR(matched, predictedEdgeColumn(camera, 1.5, 1.0), 1);
  EXPECT_GT(std::abs(matched - measured), 5);
}

// A water ball in a glass cube of the same index is invisible: the picture through the cube is the
// picture through a cube of glass alone; a ball of another index shows.
TEST(MultiMaterialRender, IndexMatchedBallInGlassIsInvisible) {
  auto render = [](Mesh cube, float ballIndex, bool plainCube) {
    Material glass = flatColour("glass", {0, 0, 0}), water = flatColour("water", {0, 0, 0});
    glass.transparency = water.transparency = 1;
    glass.ior = 1.5f;
    water.ior = ballIndex;
    SceneDescription d;
    d.render.width = d.render.height = 64;
    d.render.maxDepth = 8;
    d.render.background = {0, 0, 0};
    d.ambient = {1, 1, 1};
    d.camera.position = Vec3d{1.2, 1.6, 4};
    d.camera.lookAt = Vec3d{0, 0, 0};
    d.camera.fovDegrees = 45;
    d.materials = {glass, water};
    for (int k = 0; k < 8; ++k)
      d.materials.push_back(flatColour("stripe", k % 2 ? Vec3{1, 0.5f, 0} : Vec3{0, 0.3f, 1}));
    d.meshes.resize(9);
    if (plainCube) {  // cube_tet is [0, 1]^3, all of it glass
      d.meshes[0].scale = {2, 2, 2};
      d.meshes[0].translate = {-1, -1, -1};
    } else {
      d.meshes[0].groupMaterials = {{"Cube", 0, {}}, {"Ball", 1, {}}};
    }
    std::vector<Mesh> meshes{std::move(cube)};
    for (int k = 0; k < 8; ++k) {  // a striped screen behind the cube
      d.meshes[static_cast<std::size_t>(k) + 1].material = 2 + k;
      const float x0 = -4 + static_cast<float>(k);
      meshes.push_back(test::squareMesh(x0, -4, x0 + 1, 4, -2.5f));
    }
    return test::renderMeshes(d, std::move(meshes));
  };
  const Image glassOnly = render(readMsh(LANCER_TEST_DATA_DIR "/msh/cube_tet4_v41_bin.msh"), 1.5f, true);
  const Mesh cubeAndBall = readMsh(multimaterial("cube_sphere_v41.msh"));
  EXPECT_GE(test::psnr8(render(cubeAndBall, 1.5f, false), glassOnly), 45.0);
  EXPECT_LT(test::psnr8(render(cubeAndBall, 1.33f, false), glassOnly), 30.0);
}

}  // namespace
}  // namespace lancer
