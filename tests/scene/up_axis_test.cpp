// The quick look's up axis: the documented guess on gmsh-made meshes (planar XY, a y-up and a z-up
// bracket, a terrain, a sphere), the frames each axis gives, --up's override, and the same guess and
// bounds on any number of threads.
#include "lancer/scene/up_axis.hpp"

#include <gtest/gtest.h>

#include <random>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/quick_look.hpp"

namespace lancer {
namespace {

Mesh fixture(const std::string& name) { return readMsh(std::string(LANCER_TEST_DATA_DIR) + "/" + name); }

void expectAxis(const Vec3d& v, double x, double y, double z) {
  EXPECT_EQ(v.x, x);
  EXPECT_EQ(v.y, y);
  EXPECT_EQ(v.z, z);
}

TEST(UpAxis, TheGuessAndTheBoundsAreTheSameOnAnyNumberOfThreads) {
  // A slab wider in x and z than in y, lying on its side in y: the base area picks y. Faces of
  // random vertices and a few quads, over enough faces for several chunks.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> across(-10, 10), height(-1, 1);
  Mesh mesh;
  for (int v = 0; v < 20000; ++v) mesh.positions.push_back({across(random), height(random), across(random)});
  std::uniform_int_distribution<std::uint32_t> vertex(0, 19999);
  for (int f = 0; f < 70000; ++f) {
    MeshFace face;
    for (int c = 0; c < (f % 7 == 0 ? 4 : 3); ++c) face.vertex[c] = vertex(random);
    mesh.faces.push_back(face);
  }
  const Aabb serial = faceBounds(mesh);
  for (const int threads : {1, 2, 5}) {
    const Aabb bounds = faceBoundsOnThreads(mesh, threads);
    EXPECT_EQ(bounds.lower, serial.lower) << threads;
    EXPECT_EQ(bounds.upper, serial.upper) << threads;
  }
  const UpGuess one = guessUpAxis(mesh, 1);
  const UpGuess three = guessUpAxis(mesh, 3);
  EXPECT_EQ(one.up, three.up);
  EXPECT_EQ(one.reason, three.reason);
  expectAxis(three.frame.toViewer, one.frame.toViewer.x, one.frame.toViewer.y, one.frame.toViewer.z);
}

TEST(UpAxis, NamesParseToTheSixSignedAxes) {
  for (std::size_t i = 0; i < kUpAxisNames.size(); ++i) {
    ASSERT_TRUE(parseUpAxis(kUpAxisNames[i]));
    EXPECT_EQ(static_cast<std::size_t>(*parseUpAxis(kUpAxisNames[i])), i);
  }
  expectAxis(upVector(UpAxis::MinusZ), 0, 0, -1);
  EXPECT_FALSE(parseUpAxis("Z"));
  EXPECT_FALSE(parseUpAxis("+z"));
  EXPECT_FALSE(parseUpAxis(""));
}

TEST(UpAxis, EachAxisGivesARightHandedThreeQuarterViewFromAbove) {
  // y up is the view lancer always had, to the bit.
  expectAxis(threeQuarterFrame(UpAxis::Y).toViewer, 0.9, 0.65, 1.3);
  for (std::size_t i = 0; i < kUpAxisNames.size(); ++i) {
    const ViewFrame frame = threeQuarterFrame(static_cast<UpAxis>(i));
    const Vec3d view = normalize(frame.toViewer);
    expectAxis(frame.up, upVector(static_cast<UpAxis>(i)).x, upVector(static_cast<UpAxis>(i)).y,
               upVector(static_cast<UpAxis>(i)).z);
    EXPECT_NEAR(dot(view, frame.up), 0.65 / length(Vec3d{0.9, 0.65, 1.3}), 1e-12) << kUpAxisNames[i];
    EXPECT_NEAR(dot(view, frame.right), 0.9 / length(Vec3d{0.9, 0.65, 1.3}), 1e-12) << kUpAxisNames[i];
    // Seen from the camera, right is on the right: right = forward x up, forward = -view.
    const Vec3d screenRight = normalize(cross(-view, frame.up));
    EXPECT_GT(dot(screenRight, frame.right), 0.7) << kUpAxisNames[i];
  }
  // z up looks from the front-right-above the CAD way: +x, -y, +z.
  const Vec3d z = threeQuarterFrame(UpAxis::Z).toViewer;
  EXPECT_GT(z.x, 0);
  EXPECT_LT(z.y, 0);
  EXPECT_GT(z.z, 0);
}

TEST(UpAxis, PlanarXyModelIsSeenStraightFromPlusZWithYUp) {
  const UpGuess guess = guessUpAxis(fixture("msh/square_tri3_v41_ascii.msh"));
  EXPECT_TRUE(guess.planar);
  EXPECT_EQ(guess.up, UpAxis::Y);
  expectAxis(guess.frame.toViewer, 0, 0, 1);
  expectAxis(guess.frame.right, 1, 0, 0);
}

TEST(UpAxis, PlanarXzFloorIsSeenFromAboveWithXToTheRight) {
  const UpGuess guess = guessUpAxis(fixture("render/floor.msh"));
  EXPECT_TRUE(guess.planar);
  expectAxis(guess.frame.toViewer, 0, 1, 0);
  expectAxis(guess.frame.right, 1, 0, 0);
}

TEST(UpAxis, PartsStandOnTheirBase) {
  // The same bracket drawn y up (the examples') and z up (CAD's): each stands on its base plate.
  EXPECT_EQ(guessUpAxis(fixture("render/bracket_coarse.msh")).up, UpAxis::Y);
  const UpGuess zUp = guessUpAxis(fixture("render/bracket_zup.msh"));
  EXPECT_EQ(zUp.up, UpAxis::Z);
  EXPECT_EQ(zUp.reason, "base area");
  EXPECT_FALSE(zUp.planar);
}

TEST(UpAxis, TerrainsAndSpheresTakeTheirThinnestAxisOrZ) {
  EXPECT_EQ(guessUpAxis(fixture("render/terrain.msh")).up, UpAxis::Z);
  const UpGuess sphere = guessUpAxis(fixture("render/sphere_fine.msh"));
  EXPECT_EQ(sphere.up, UpAxis::Z);  // no base, equal extents: z, as CAD and gmsh draw height
  EXPECT_EQ(sphere.reason, "smallest extent");
}

TEST(UpAxis, QuickLookCameraFollowsTheGuessOrTheOverride) {
  const Mesh bracket = fixture("render/bracket_zup.msh");
  const SceneDescription guessed = quickLookScene("bracket_zup.msh", bracket);
  expectAxis(guessed.camera.up, 0, 0, 1);
  const Aabb bounds = faceBounds(bracket);
  const Aabbd world{bracket.origin + toDouble(bounds.lower), bracket.origin + toDouble(bounds.upper)};
  EXPECT_GT(defaultCameraPosition(world, guessed.camera, 4.0 / 3.0).z, world.center().z);  // above
  const SceneDescription forced = quickLookScene("bracket_zup.msh", bracket, UpAxis::MinusX);
  expectAxis(forced.camera.up, -1, 0, 0);
  EXPECT_LT(defaultCameraPosition(world, forced.camera, 4.0 / 3.0).x, world.center().x);  // "above" is -x
}

// The fill sits at the camera, so a face the camera sees always has a light on its front: the fill's
// direction from any point is the viewer's. Checked for random points and normals of the part's box.
TEST(UpAxis, QuickLookLightsEveryFaceTheCameraSeesFromItsFront) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const char* name :
       {"render/bracket_zup.msh", "render/bracket_coarse.msh", "msh/square_tri3_v41_ascii.msh"}) {
    const Mesh mesh = fixture(name);
    for (int size = 0; size < 2; ++size) {
      SceneDescription d = quickLookScene(name, mesh);
      d.render.width = size == 0 ? 800 : 300;
      d.render.height = size == 0 ? 600 : 500;
      placeQuickLookLights(d, mesh);
      const Aabb bounds = faceBounds(mesh);
      const Aabbd world{mesh.origin + toDouble(bounds.lower), mesh.origin + toDouble(bounds.upper)};
      const Vec3d eye = defaultCameraPosition(world, d.camera, double(d.render.width) / d.render.height);
      ASSERT_EQ(d.lights.size(), 2u);
      EXPECT_LT(length(d.lights[1].position - eye), 1e-9 * length(world.extent())) << name;
      for (int k = 0; k < 2000; ++k) {
        const Vec3d p =
            world.center() + Vec3d{unit(random), unit(random), unit(random)} * (0.5 * world.extent());
        Vec3d n = normalize(Vec3d{unit(random), unit(random), unit(random)});
        if (dot(n, eye - p) <= 0) n = -n;  // the side the camera sees
        bool lit = false;
        for (const PointLight& light : d.lights) lit = lit || dot(n, light.position - p) > 0;
        EXPECT_TRUE(lit) << name;
      }
    }
  }
}

}  // namespace
}  // namespace lancer
