// Golden images of what lancer draws inside a volume, on a capacitor solved by GetDP
// (tests/data/volume/capacitor.msh, scripts/make_volume_fixtures.sh: two plates at +1 and -1 V in an
// air box, v and e as element-node data): a slice coloured by v with its legend and the box's edges,
// isosurfaces of v through a ghost of the box, and field lines of e from a disk between the plates.
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

// The quick look of the capacitor, coloured by `field`, with `configure` setting the overrides.
template <typename Configure>
void expectCapacitorGolden(const std::string& field, Configure configure, const std::string& golden) {
  const std::string path = test::dataFile("volume/capacitor.msh");
  MeshWithVolume read = readMshWithVolume(path);
  RenderRequest request;
  request.description = quickLookScene(path, read.mesh);
  if (!field.empty()) {
    ColorBy colorBy;
    colorBy.field = field;
    request.description.meshes[0].colorBy = colorBy;
  }
  request.quickLookMesh = std::move(read.mesh);
  request.quickLookVolume = read.volume;
  request.overrides.width = 240;
  request.overrides.height = 180;
  request.overrides.legend = LegendPlacement::Right;
  configure(request.overrides);
  const PreparedRender prepared = prepareRender(std::move(request));
  Image image = prepared.renderer().renderFinal(RenderOptions{});
  const FieldColors& fields = *prepared.scene.fieldColors;
  drawLegends(image, fields.legends, fields.legendPlacement, prepared.settings().srgb);
  test::expectImageNear(image, test::dataFile("render/golden/" + golden), test::kRenderGoldenMinPsnrDb,
                        TransferCurve::Srgb);
}

TEST(VolumeGolden, CapacitorSliceColouredByThePotential) {
  expectCapacitorGolden(
      "v",
      [](RenderOverrides& overrides) {
        SliceSpec slice;
        slice.normal = {0, 1, 0};
        overrides.slices.push_back(slice);
        overrides.skin = SkinStyle::Edges;
        overrides.isolines = 8;
      },
      "volume_capacitor_slice.png");
}

TEST(VolumeGolden, CapacitorIsosurfacesThroughAGhost) {
  expectCapacitorGolden(
      "",
      [](RenderOverrides& overrides) {
        IsosurfaceSpec iso;
        iso.field = "v";
        iso.values = {-0.4, 0.4};
        overrides.isosurfaces = iso;
      },
      "volume_capacitor_isosurfaces.png");
}

TEST(VolumeGolden, CapacitorFieldLinesFromADisk) {
  expectCapacitorGolden(
      "",
      [](RenderOverrides& overrides) {
        StreamlineSpec lines;
        lines.field = "e";
        lines.seeds = StreamlineSpec::Seeds::Disk;
        lines.diskCenter = {0, 0, 0};
        lines.diskNormal = {0, 0, 1};
        lines.diskRadius = 1.0;
        lines.count = 60;
        lines.radius = 0.012;
        overrides.streamlines = lines;
        overrides.skin = SkinStyle::Edges;
      },
      "volume_capacitor_field_lines.png");
}

}  // namespace
}  // namespace lancer
