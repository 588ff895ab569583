// A bare-mesh turntable (`lancer animate part.msh`): the quick look's key and fill turn with the
// camera, so every frame is lit as the first is. Before, the lights stayed put and the frames half
// way round showed the part's unlit back.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// Mean of the pixels that show the part (not the background), over the three channels.
double meanPartBrightness(const Image& image, const Vec3& background) {
  double sum = 0;
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Rgba p = image.at(x, y);
      if (p.r == background.x && p.g == background.y && p.b == background.z) continue;
      sum += (p.r + p.g + p.b) / 3.0;
      ++count;
    }
  }
  return count > 0 ? sum / count : 0;
}

std::vector<double> turntableBrightness(const std::string& name, bool lightsFollow) {
  Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/render/" + name);
  SceneDescription d = quickLookScene(name, mesh);
  d.render.width = 64;
  d.render.height = 48;
  placeQuickLookLights(d, mesh);
  d.lightsFollowCamera = lightsFollow;
  std::vector<Mesh> meshes;
  meshes.push_back(std::move(mesh));
  Scene scene = buildScene(d, std::move(meshes));
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  AnimationSettings animation;
  animation.frames = 12;
  std::vector<double> brightness;
  renderAnimation(scene, accelerator, d, animation, RenderOptions{}, [&](int, const Image& image) {
    brightness.push_back(meanPartBrightness(image, d.render.background));
  });
  return brightness;
}

TEST(QuickLookTurntable, EveryFrameIsLitLikeTheFirst) {
  for (const char* name : {"bracket_zup.msh", "bracket_coarse.msh", "cut_bushing.msh"}) {
    const std::vector<double> brightness = turntableBrightness(name, true);
    ASSERT_EQ(brightness.size(), 12u);
    for (std::size_t k = 0; k < brightness.size(); ++k) {
      EXPECT_GT(brightness[k], 0.8 * brightness[0]) << name << " frame " << k;
      // Some sides show more of the part's top, the best lit face: up to 24% brighter.
      EXPECT_LT(brightness[k], 1.35 * brightness[0]) << name << " frame " << k;
    }
  }
}

// The guard: with the lights left where frame 0 put them, the far side of the turn is dark, so the
// band above means something.
TEST(QuickLookTurntable, LightsLeftBehindDarkenTheFarSide) {
  const std::vector<double> brightness = turntableBrightness("bracket_zup.msh", false);
  EXPECT_LT(*std::min_element(brightness.begin(), brightness.end()), 0.8 * brightness[0]);
}

// --up through the CLI: the guess for the z-up bracket is z (the same picture as --up z), --up y
// lays it on its side (another picture), and `lancer animate` of the bare mesh takes it too.
TEST(QuickLookTurntable, UpOptionOverridesTheGuess) {
  test::ScratchFolder folder;
  const std::string mesh = test::quoted(std::string(LANCER_TEST_DATA_DIR) + "/render/bracket_zup.msh");
  auto render = [&](const std::string& options, const std::string& name) {
    const test::CommandResult result = test::runCli("render -q --width 48 --height 36 " + options + " " +
                                                    mesh + " -o " + test::quoted(folder.file(name)));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return test::readPictureBytes(folder.file(name));
  };
  const auto guessed = render("", "guessed.png");
  EXPECT_EQ(render("--up z", "z.png"), guessed);
  EXPECT_NE(render("--up y", "y.png"), guessed);
  EXPECT_NE(render("--up -z", "minus_z.png"), guessed);
  const test::CommandResult animate = test::runCli("animate -q --width 32 --height 24 --frames 3 --up x " +
                                                   mesh + " -o " + test::quoted(folder.file("f_%04d.png")));
  EXPECT_EQ(animate.exitCode, 0) << animate.output;
}

}  // namespace
}  // namespace lancer
