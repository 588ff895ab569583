// What `lancer render` writes: sRGB-encoded by default (the PNG says so), --linear keeps the
// raw values, 16-bit PNG, OpenEXR with its layers (the radiance the library renders, to the bit),
// tone curves and the denoiser from the command line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/image/exr_io.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/tone_map.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::quoted;

const std::string kScene = test::dataFile("render/bracket_ortho.toml");

// `lancer render bracket_ortho.toml -q OPTIONS -o folder/NAME`, which must succeed.
std::string render(const test::ScratchFolder& folder, const std::string& name,
                   const std::string& options = "") {
  const test::CommandResult result =
      test::runCli("render " + quoted(kScene) + " -q " + options + " -o " + quoted(folder.file(name)));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return folder.file(name);
}

TEST(OutputCli, PngIsSrgbByDefaultAndLinearOnRequest) {
  const test::ScratchFolder folder;
  PngDescription srgb, linear;
  const Image byDefault = readPng(render(folder, "default.png"), TransferCurve::Linear, &srgb);
  const Image raw = readPng(render(folder, "linear.png", "--linear"), TransferCurve::Linear, &linear);
  EXPECT_TRUE(srgb.srgb);
  EXPECT_FALSE(linear.srgb);
  // The same radiance under both curves: each sRGB byte is the curve of the linear one, to a step
  // of the 8-bit rounding either side.
  double worst = 0;
  for (int y = 0; y < raw.height(); ++y)
    for (int x = 0; x < raw.width(); ++x)
      worst = std::max(worst,
                       std::abs(static_cast<double>(srgbFromLinear(raw.at(x, y).g)) - byDefault.at(x, y).g));
  EXPECT_LT(worst * 255, 8.5);  // the sRGB slope near black is 12.92: one linear step is up to 13 sRGB steps
  EXPECT_EQ(test::readPictureBytes(render(folder, "srgb.png", "--srgb")),
            test::readPictureBytes(folder.file("default.png")));
  // The scene key does what the flag does.
  const std::vector<char> bytes = test::readFileBytes(kScene);
  std::string scene(bytes.begin(), bytes.end());
  scene.replace(scene.find("[render]\n"), 9, "[render]\nencoding = \"linear\"\n");
  folder.copy(test::dataFile("render/bracket_coarse.msh"), "bracket_coarse.msh");
  folder.copy(test::dataFile("render/floor.msh"), "floor.msh");
  folder.write("linear_scene.toml", scene);
  const test::CommandResult keyed = test::runCli("render " + quoted(folder.file("linear_scene.toml")) +
                                                 " -q -o " + quoted(folder.file("keyed.png")));
  ASSERT_EQ(keyed.exitCode, 0) << keyed.output;
  EXPECT_EQ(test::readPictureBytes(folder.file("keyed.png")),
            test::readPictureBytes(folder.file("linear.png")));
}

TEST(OutputCli, SixteenBitPngHoldsTheSamePicture) {
  const test::ScratchFolder folder;
  const Image eight = readPng(render(folder, "8.png", "--linear"));
  const Image sixteen = readPng16(render(folder, "16.png", "--linear --bit-depth 16"));
  double worst = 0;
  for (int y = 0; y < eight.height(); ++y)
    for (int x = 0; x < eight.width(); ++x)
      worst = std::max(worst, std::abs(double{eight.at(x, y).r} - sixteen.at(x, y).r));
  EXPECT_LE(worst * 255, 0.5 + 1e-3);
}

TEST(OutputCli, ExrHoldsTheRadianceAndTheLayers) {
  if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  const test::ScratchFolder folder;
  ExrLayers layers;
  const Image exr = readExr(render(folder, "a.exr", "--aovs albedo,normal,depth"), &layers);
  // The library's own render of the scene, to the bit: linear float, no curve, no clamp.
  const SceneDescription description = loadScene(kScene);
  const Scene scene = buildScene(description);
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  const Camera camera = makeCamera(description.camera, scene, description.render);
  const Renderer renderer(scene, accelerator, camera, description.render);
  EXPECT_EQ(exr, renderer.renderImage({}));
  const FeatureBuffers features = renderer.renderFeatures(0);
  EXPECT_EQ(layers.albedo, features.albedo);
  EXPECT_EQ(layers.normal, features.normal);
  EXPECT_EQ(layers.depth, features.depth);
  // Without --aovs: the radiance alone.
  readExr(render(folder, "b.exr"), &layers);
  EXPECT_TRUE(layers.albedo.empty() && layers.depth.empty());
}

TEST(OutputCli, ToneCurveAndExposureApplyToThePicture) {
  const test::ScratchFolder folder;
  const Image plain = readPng(render(folder, "plain.png", "--linear"));
  const Image brighter = readPng(render(folder, "brighter.png", "--linear --exposure 1"));
  const Image aces = readPng(render(folder, "aces.png", "--linear --tonemap aces"));
  // The floor's lit value: one stop doubles it (clamped at 1); ACES maps it through Narkowicz's fit.
  const float floor = plain.at(10, 90).g;
  EXPECT_NEAR(brighter.at(10, 90).g, std::min(1.0f, 2 * floor), 1.5f / 255);
  EXPECT_NEAR(aces.at(10, 90).g, acesCurve(floor), 1.5f / 255);
  EXPECT_EQ(render(folder, "d.png", "--denoise --tonemap filmic --exposure -0.5").empty(), false);
}

}  // namespace
}  // namespace lancer
