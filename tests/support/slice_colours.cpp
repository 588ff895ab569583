#include "support/slice_colours.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <utility>

#include "lancer/image/color_map.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"

namespace lancer::test {

std::string topViewSliceScene(int side, const std::string& fileKeys, const std::string& rest) {
  return fmt::format(R"([render]
width = {0}
height = {0}
shading = "unlit"

[camera]
projection = "orthographic"
position = [0.5, 0.5, 5]
look_at = [0.5, 0.5, 0.3]
up = [0, 1, 0]
view_height = 1.2

[[light]]
position = [0.5, 0.5, 10]

[[mesh]]
{1}
color_by = {{ field = "f", range = [0, 6] }}
{2}
)",
                     side, fileKeys, rest);
}

int expectSliceColours(const ScratchFolder& folder, const std::string& scene) {
  const std::string path = folder.file("scene.toml");
  std::ofstream(path) << scene;
  const std::string out = folder.file("out.png");
  const CommandResult run = runCli("render " + quoted(path) + " -q -o " + quoted(out) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  if (run.exitCode != 0) return 0;
  const Image image = readPng(out);
  RenderRequest request;
  request.description = loadScene(path);
  const PreparedRender prepared = prepareRender(std::move(request));
  int checked = 0;
  double worst = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Ray ray = prepared.camera.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const Vec3d origin = prepared.scene.geometry.origin + toDouble(ray.origin);
      const Vec3d direction = toDouble(ray.direction);
      const Vec3d p = origin + direction * ((0.3 - origin.z) / direction.z);
      // Away from the square's border, where a pixel may see the background too.
      if (p.x < 0.01 || p.x > 0.99 || p.y < 0.01 || p.y > 0.99) continue;
      const double f = p.x + 2 * p.y + 0.9;
      const Vec3 expected = colorMapLookup(ColorMapKind::Viridis, static_cast<float>(f / 6));
      worst = std::max(worst, 255.0 * maxComponent(abs(image.at(x, y).rgb() - expected)));
      ++checked;
    }
  EXPECT_LE(worst, 1.0);
  return checked;
}

}  // namespace lancer::test
