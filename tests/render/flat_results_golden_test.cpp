// Golden image of a 2D field plot with its legend beside it: GetDP's magnet (az, written by
// `getdp -v2`) as `lancer render magnet_v2_az.pos --color-by az --isolines 10 --legend right`
// draws it: straight on, the map's own colours, isolines, the legend clear of the model.
// Regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include "lancer/image/legend.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"

namespace lancer {
namespace {

TEST(FlatResultsGolden, MagnetWithIsolinesAndALegendBeside) {
  const std::string path = test::dataFile("getdp/magnet_v2_az.pos");
  const Mesh mesh = readMsh(path);
  RenderRequest request;
  request.description = quickLookScene(path, mesh);
  ColorBy colorBy;
  colorBy.field = "az";
  request.description.meshes[0].colorBy = colorBy;
  request.quickLookMesh = mesh;
  request.overrides.width = 256;
  request.overrides.height = 144;
  request.overrides.isolines = 10;
  request.overrides.legend = LegendPlacement::Right;
  const PreparedRender prepared = prepareRender(std::move(request));
  Image image = prepared.renderer().renderFinal(RenderOptions{});
  const FieldColors& fields = *prepared.scene.fieldColors;
  drawLegends(image, fields.legends, fields.legendPlacement, prepared.settings().srgb);
  test::expectImageNear(image, test::dataFile("render/golden/flat_magnet_az.png"),
                        test::kRenderGoldenMinPsnrDb, TransferCurve::Srgb);
}

}  // namespace
}  // namespace lancer
