// Flat models (2D results: every face in one plane) as gmsh and ParaView show them: seen straight
// on, orthographic, filling the picture, the field in the map's own colours unless lights are asked
// for; in the quick look (GetDP's magnet, az) as in a scene file without a camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lancer/image/color_map.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

constexpr int kWidth = 200, kHeight = 150;
// The smallest box of pixels that differ from the background (the top-left pixel's colour).
struct PixelBox {
  int left = 1 << 30, top = 1 << 30, right = -1, bottom = -1;
};
PixelBox modelPixels(const Image& image) {
  const Vec3 background = image.at(0, 0).rgb();
  PixelBox box;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (maxComponent(abs(image.at(x, y).rgb() - background)) > 2.0f / 255.0f) {
        box.left = std::min(box.left, x);
        box.right = std::max(box.right, x);
        box.top = std::min(box.top, y);
        box.bottom = std::max(box.bottom, y);
      }
  return box;
}

// `lancer render MAGNET --color-by az` as a user types it; the picture as its stored 8-bit values.
Image magnetQuickLook(const test::ScratchFolder& folder, const std::string& options = "") {
  const std::string out = folder.file("az.png");
  const test::CommandResult run =
      test::runCli("render " + test::quoted(test::dataFile("getdp/magnet_v2_az.pos")) + " --color-by az " +
                   options + " --width 200 --height 150 -q -o " + test::quoted(out) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return readPng(out);
}

// GetDP's magnet (MSH 2.2 with $ElementNodeData, as `getdp -v2` writes it): at every pixel of the
// model, the colour map at the value the element under the pixel's centre takes there.
TEST(FlatResults, QuickLookShowsTheMapColoursOfGetdpsMagnet) {
  const std::string path = test::dataFile("getdp/magnet_v2_az.pos");
  const test::ScratchFolder folder;
  const Image image = magnetQuickLook(folder);
  ASSERT_EQ(image.width(), kWidth);

  // The camera the command used: the quick look's, through the same preparation.
  const Mesh mesh = readMsh(path);
  RenderRequest request;
  request.description = quickLookScene(path, mesh);
  ColorBy colorBy;
  colorBy.field = "az";
  request.description.meshes[0].colorBy = colorBy;
  request.quickLookMesh = mesh;
  request.overrides.width = kWidth;
  request.overrides.height = kHeight;
  const PreparedRender prepared = prepareRender(std::move(request));
  EXPECT_EQ(prepared.camera.projection(), Projection::Orthographic);

  const MeshField& az = mesh.fields.at(0);
  ASSERT_EQ(az.at, FieldAt::kCorner);
  const auto [low, high] = az.range();
  int checked = 0;
  double worst = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Ray ray = prepared.camera.generateRay(x + 0.5f, y + 0.5f);
      const Vec3d p = prepared.scene.geometry.origin + toDouble(ray.origin);
      // The colour of every element whose triangle holds the point (two or more on a shared edge,
      // where the field may jump): the pixel must show one of them.
      double best = 1e9;
      for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const MeshFace& face = mesh.faces[f];
        const Vec3d a = mesh.worldPosition(face.vertex[0]), b = mesh.worldPosition(face.vertex[1]),
                    c = mesh.worldPosition(face.vertex[2]);
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const double w1 = ((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x)) / area;
        const double w2 = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / area;
        const double w0 = 1 - w1 - w2;
        constexpr double kOn = -1e-6;
        if (w0 < kOn || w1 < kOn || w2 < kOn) continue;
        const float* corner = az.values.data() + f * kCornerSlots;
        const double value = w0 * corner[cornerSlot(face, 0)] + w1 * corner[cornerSlot(face, 1)] +
                             w2 * corner[cornerSlot(face, 2)];
        const Vec3 expected =
            colorMapLookup(ColorMapKind::Viridis, static_cast<float>((value - low) / (high - low)));
        const Vec3 got = image.at(x, y).rgb();
        best = std::min(best, 255.0 * maxComponent(abs(got - expected)));
      }
      if (best == 1e9) continue;  // the background
      ++checked;
      worst = std::max(worst, best);
    }
  EXPECT_GT(checked, kWidth * kHeight / 3);
  RecordProperty("worst_8bit_steps", std::to_string(worst));
  RecordProperty("pixels_checked", checked);
  // The map's own colours: the stored 8-bit values round the map's to the nearest step.
  EXPECT_LE(worst, 1.0);
}

TEST(FlatResults, QuickLookFillsThePictureStraightOn) {
  // The half disc of radius 0.25 (0.5 x 0.25) fills 94% of the width: 188 of 200 pixels, 94 rows
  // high, centred.
  const test::ScratchFolder folder;
  const PixelBox box = modelPixels(magnetQuickLook(folder));
  EXPECT_NEAR(box.left, 6, 1);
  EXPECT_NEAR(box.right, 193, 1);
  EXPECT_NEAR(box.top, 28, 1);
  EXPECT_NEAR(box.bottom, 121, 1);
}

TEST(FlatResults, AnUpAxisKeepsTheThreeQuarterView) {
  // --up chooses the view: the camera looks from the side (the half disc is seen foreshortened).
  const test::ScratchFolder folder;
  const PixelBox box = modelPixels(magnetQuickLook(folder, "--up z"));
  EXPECT_LT(box.right - box.left, 170);
}

// A scene file without a camera or lights: the gmsh-made unit square with the field x + 2 y fills
// 94 of a 100 x 100 picture's pixels straight on, each pixel in viridis at (x + 2 y) / 3.
double worstSquareError(const std::string& extraKeys, int& checked) {
  const test::ScratchFolder folder;
  folder.write("square.toml",
               "[render]\nwidth = 100\nheight = 100\nbackground = [0, 0, 0]\n"
               "encoding = \"linear\"\n" +
                   extraKeys + "\n[[mesh]]\nfile = \"" + test::dataFile("fields/node_xy_v41_bin.msh") +
                   "\"\ncolor_by = { field = \"temperature\" }\n");
  const std::string out = folder.file("square.png");
  const test::CommandResult run = test::runCli("render " + test::quoted(folder.file("square.toml")) +
                                               " -q -o " + test::quoted(out) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  const Image image = readPng(out);
  double worst = 0;
  checked = 0;
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) {
      const double x = 0.5 + (i + 0.5 - 50) / 94.0, y = 0.5 - (j + 0.5 - 50) / 94.0;
      if (x < 0.01 || y < 0.01 || x > 0.99 || y > 0.99) continue;
      ++checked;
      const Vec3 expected = colorMapLookup(ColorMapKind::Viridis, static_cast<float>((x + 2 * y) / 3));
      worst = std::max(worst, 255.0 * maxComponent(abs(image.at(i, j).rgb() - expected)));
    }
  return worst;
}

TEST(FlatResults, SceneWithoutACameraSeesAFlatModelStraightOn) {
  int checked = 0;
  EXPECT_LE(worstSquareError("", checked), 1.0);
  EXPECT_GT(checked, 8000);
}

TEST(FlatResults, LightsAskedForLightTheField) {
  int checked = 0;
  EXPECT_GT(worstSquareError("[[light]]\nposition = [0.5, 0.5, 2]\n", checked), 10.0);
}

TEST(FlatResults, ALookLightsTheFieldAndUnlitShadingShowsItsColours) {
  // --look studio asks for light: the colours are lit. --shading unlit shows the map's colours under
  // any look (the path tracer's samples spread over each pixel: a few steps from its centre's).
  const test::ScratchFolder folder;
  const Image plain = magnetQuickLook(folder);
  const Image unlit = magnetQuickLook(folder, "--shading unlit --look studio --samples 16");
  const Image lit = magnetQuickLook(folder, "--look studio --samples 16");
  const Vec3 map = plain.at(kWidth / 2, 60).rgb();  // inside the half disc, above the magnet
  EXPECT_LT(maxComponent(abs(unlit.at(kWidth / 2, 60).rgb() - map)), 3.0f / 255.0f);
  EXPECT_GT(maxComponent(abs(lit.at(kWidth / 2, 60).rgb() - map)), 10.0f / 255.0f);
}

}  // namespace
}  // namespace lancer
