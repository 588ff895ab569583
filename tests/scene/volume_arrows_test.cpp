// Arrows through the volume (`arrows = { field, grid = [nx, ny, nz] }`): one at each grid point inside
// a volume element, its vector interpolated there, scaled as the surface's arrows are; points outside
// the mesh draw none; one volume's arrows are drawn once however many of its slices carry them. And
// the annotation kinds' table: each row reads its own kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/volume_arrows.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_keys.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

constexpr std::size_t kArrowVertices = 3 * kArrowSides + 2;  // three rings, the base centre, the tip

// Each arrow's base centre and tip, in world coordinates.
struct DrawnArrow {
  Vec3d base, tip;
};
std::vector<DrawnArrow> drawnArrows(const Mesh& arrows) {
  std::vector<DrawnArrow> drawn;
  for (std::size_t first = 0; first + kArrowVertices <= arrows.positions.size(); first += kArrowVertices)
    drawn.push_back({arrows.worldPosition(static_cast<std::uint32_t>(first + 3 * kArrowSides)),
                     arrows.worldPosition(static_cast<std::uint32_t>(first + 3 * kArrowSides + 1))});
  return drawn;
}

ArrowSpec gridArrows(const std::string& field, std::array<int, 3> grid) {
  ArrowSpec spec;
  spec.field = field;
  spec.grid = grid;
  return spec;
}

TEST(VolumeArrows, OnTheGridOfTheCubeAlongTheUniformField) {
  // cube_hex.msh: the unit cube of 6 x 6 x 6 hexahedra, u = (1, 2, 3) at every node.
  const MeshWithVolume read = readMshWithVolume(test::dataFile("volume/cube_hex.msh"));
  ArrowSpec spec = gridArrows("u", {2, 2, 4});
  spec.fixedLength = false;  // lengths that follow the magnitude
  const Mesh arrows = volumeArrowMesh(spec, *read.volume, {}, "cube_hex.msh");
  ASSERT_EQ(arrows.positions.size(), 16 * kArrowVertices);
  EXPECT_EQ(arrows.faces.size(), 16u * 6 * kArrowSides);
  const Vec3d u{1, 2, 3};
  // The grid's cells are 0.5 x 0.5 x 0.25: the longest arrow is 0.9 of the least side.
  const double expectedLength = 0.9 * 0.25;
  int k = 0;
  for (const DrawnArrow& arrow : drawnArrows(arrows)) {
    const Vec3d expectedBase{0.25 + 0.5 * (k % 2), 0.25 + 0.5 * (k / 2 % 2), 0.125 + 0.25 * (k / 4)};
    EXPECT_NEAR(length(arrow.base - expectedBase), 0, 1e-6) << k;
    const Vec3d along = arrow.tip - arrow.base;
    EXPECT_NEAR(length(along), expectedLength, 1e-6) << k;
    EXPECT_NEAR(length(along * (1 / length(along)) - u * (1 / length(u))), 0, 1e-6) << k;
    ++k;
  }
  ASSERT_EQ(arrows.fields.size(), 1u);
  EXPECT_EQ(arrows.fields[0].name, "u magnitude");
  for (const float magnitude : arrows.fields[0].values) EXPECT_NEAR(magnitude, std::sqrt(14.0), 1e-5);
  const auto [low, high] = volumeMagnitudeRange(*read.volume, "u", std::nullopt);
  EXPECT_NEAR(low, std::sqrt(14.0), 1e-5);
  EXPECT_NEAR(high, std::sqrt(14.0), 1e-5);
}

TEST(VolumeArrows, AFieldConcentratedNearItsSourcesReadsByDefault) {
  // The capacitor's field: strongest at the plates' edges, weak through most of the air box. Arrows
  // following the magnitude leave most of them a few hundredths of a cell long (below a pixel): by
  // default a grid's arrows are all 0.8 of the cell's least side, the magnitude in their colour.
  const MeshWithVolume read = readMshWithVolume(test::dataFile("volume/capacitor.msh"));
  const VolumeMesh& volume = *read.volume;
  Aabbd box;
  for (const Vec3& node : volume.nodes) box.extend(toDouble(node));
  const std::array<int, 3> grid{6, 6, 5};
  const Vec3d extent = box.extent();
  const double cell = std::min({extent.x / grid[0], extent.y / grid[1], extent.z / grid[2]});
  const auto lengths = [&](const ArrowSpec& spec) {
    std::vector<double> drawn;
    for (const DrawnArrow& arrow : drawnArrows(volumeArrowMesh(spec, volume, {}, "capacitor.msh")))
      drawn.push_back(length(arrow.tip - arrow.base) / cell);
    std::sort(drawn.begin(), drawn.end());
    return drawn;
  };
  const std::vector<double> fixed = lengths(gridArrows("e", grid));
  ASSERT_GT(fixed.size(), 100u);
  EXPECT_NEAR(fixed.front(), 0.8, 1e-4);
  EXPECT_NEAR(fixed.back(), 0.8, 1e-4);
  ArrowSpec following = gridArrows("e", grid);
  following.fixedLength = false;
  const std::vector<double> proportional = lengths(following);
  EXPECT_NEAR(proportional.back(), 0.9, 1e-4);
  EXPECT_LT(proportional[proportional.size() / 2], 0.1);  // the median: the reason for the default
  // A scale given asks for lengths that follow the magnitude.
  following.fixedLength.reset();
  following.scale = 0.01;
  const std::vector<double> scaled = lengths(following);
  ASSERT_EQ(scaled.size(), proportional.size());
  EXPECT_NEAR(scaled.front() / scaled.back(), proportional.front() / proportional.back(), 1e-4);
  // On a surface the lengths follow the magnitude unless asked otherwise.
  ArrowSpec surface;
  surface.field = "e";
  EXPECT_FALSE(surface.drawsFixedLength());
}

// One tetrahedron, (0,0,0), (1,0,0), (0,1,0), (0,0,1), with the node field v(p) = (1 + p.x, p.y, 2 p.z)
// (linear: interpolated exactly) and the element field w = (0, 0, 5).
VolumeMesh cornerTetrahedron() {
  VolumeMesh volume;
  volume.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::array<std::uint32_t, kMaxCellCorners> corners;
  corners.fill(kNoVertex);
  for (std::uint32_t c = 0; c < 4; ++c) corners[c] = c;
  volume.cells.push_back(corners);
  volume.shapes.push_back(CellShape::kTetrahedron);
  volume.cellPhysicalTag.push_back(0);
  volume.cellEntityTag.push_back(1);
  VolumeField v;
  v.name = "v";
  v.components = 3;
  for (const Vec3& p : volume.nodes) v.values.insert(v.values.end(), {1 + p.x, p.y, 2 * p.z});
  VolumeField w;
  w.name = "w";
  w.at = FieldAt::kElement;
  w.components = 3;
  w.values = {0, 0, 5};
  volume.fields = {v, w};
  return volume;
}

TEST(VolumeArrows, PointsOutsideTheMeshDrawNone) {
  // Of the grid 2 x 2 x 2 over the tetrahedron's box, only (1/4, 1/4, 1/4) is inside (x + y + z < 1).
  const VolumeMesh volume = cornerTetrahedron();
  const Mesh node = volumeArrowMesh(gridArrows("v", {2, 2, 2}), volume, {}, "tet.msh");
  const std::vector<DrawnArrow> arrows = drawnArrows(node);
  ASSERT_EQ(arrows.size(), 1u);
  EXPECT_NEAR(length(arrows[0].base - Vec3d{0.25, 0.25, 0.25}), 0, 1e-6);
  const Vec3d v{1.25, 0.25, 0.5};
  const Vec3d along = arrows[0].tip - arrows[0].base;
  EXPECT_NEAR(length(along * (1 / length(along)) - v * (1 / length(v))), 0, 1e-6);
  EXPECT_NEAR(node.fields[0].values[0], length(v), 1e-5);
  // A fixed scale: the length is scale times the magnitude.
  ArrowSpec scaled = gridArrows("v", {2, 2, 2});
  scaled.scale = 0.1;
  const std::vector<DrawnArrow> fixed = drawnArrows(volumeArrowMesh(scaled, volume, {}, "tet.msh"));
  ASSERT_EQ(fixed.size(), 1u);
  EXPECT_NEAR(length(fixed[0].tip - fixed[0].base), 0.1 * length(v), 1e-6);
  // Element data: the cell's vector.
  ArrowSpec elementArrows = gridArrows("w", {2, 2, 2});
  elementArrows.fixedLength = false;  // the longest (the only one) 0.9 cells long
  const std::vector<DrawnArrow> element = drawnArrows(volumeArrowMesh(elementArrows, volume, {}, "tet.msh"));
  ASSERT_EQ(element.size(), 1u);
  const Vec3d up = element[0].tip - element[0].base;
  EXPECT_NEAR(up.x, 0, 1e-9);
  EXPECT_NEAR(up.y, 0, 1e-9);
  EXPECT_NEAR(up.z, 0.9 * 0.5, 1e-6);
}

TEST(VolumeArrows, DrawnOnceFromASceneWithItsSkinAndSlices) {
  const auto faces = [](const std::string& mesh) {
    const std::string text = "[[mesh]]\nfile = \"cube_hex.msh\"\n" + mesh;
    return buildScene(parseScene(text, test::dataFile("volume/scene.toml"))).geometry.faces.size();
  };
  const std::size_t arrowFaces = 8u * 6 * kArrowSides;
  const std::string arrows = "arrows = { field = \"u\", grid = [2, 2, 2] }\n";
  const std::string slices = "[[mesh.slice]]\nnormal = [0, 0, 1]\n[[mesh.slice]]\nnormal = [1, 0, 0]\n";
  // The skin (a ghost around the arrows by default) and the arrows.
  EXPECT_EQ(faces(arrows), faces("") + arrowFaces);
  // Two slices carry the mesh's arrows: still one set.
  EXPECT_EQ(faces(arrows + slices), faces(slices) + arrowFaces);
  // Solid inside the see-through skin (they took the ghost's material, washed out to grey).
  for (const std::string skin : {"ghost", "edges"}) {
    const Scene scene =
        buildScene(parseScene("[[mesh]]\nfile = \"cube_hex.msh\"\nskin = \"" + skin + "\"\n" + arrows,
                              test::dataFile("volume/scene.toml")));
    const std::vector<std::uint32_t>& material = scene.appearance.faceMaterial;
    ASSERT_GE(material.size(), arrowFaces);
    for (std::size_t f = material.size() - arrowFaces; f < material.size(); ++f)
      ASSERT_EQ(scene.appearance.materials[material[f]].transparency, 0.0f) << skin << " face " << f;
  }
}

TEST(AnnotationKinds, EachRowReadsItsOwnKindUnderAKeyOfTheMeshTable) {
  const std::span<const std::string_view> meshKeys = sceneKeys(SceneTable::Mesh);
  for (std::size_t i = 0; i < annotationKinds().size(); ++i) {
    const AnnotationKind& kind = annotationKinds()[i];
    EXPECT_NE(std::find(meshKeys.begin(), meshKeys.end(), kind.key), meshKeys.end()) << kind.key;
    toml::table mesh;
    mesh.insert(kind.key, toml::table{{"field", "f"}});
    const std::vector<AnnotationSpec> read =
        readAnnotations("scene.toml", TomlTableReader(mesh, "mesh[0]", "scene.toml", SceneTable::Mesh));
    ASSERT_EQ(read.size(), 1u) << kind.key;
    EXPECT_EQ(read[0].index(), i) << kind.key;
    EXPECT_EQ(&annotationKind(read[0]), &kind);
    EXPECT_EQ(annotationField(read[0]), "f");
  }
  // setAnnotation puts a spec in place of one of its kind.
  MeshInstance instance;
  setAnnotation(instance, arrowsOfField("a", SourceLocation{"--arrows"}));
  setAnnotation(instance, arrowsOfField("b", SourceLocation{"--arrows"}));
  ASSERT_EQ(instance.annotations.size(), 1u);
  EXPECT_EQ(annotationField(instance.annotations[0]), "b");
}

}  // namespace
}  // namespace lancer
