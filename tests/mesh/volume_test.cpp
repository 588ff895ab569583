// The volume kept beside the skin (readMshWithVolume) and what is drawn from it: probes, slices and
// isosurfaces, checked against closed forms on a gmsh-made cube of tetrahedra whose fields are
// linear (scripts/make_element_node_fixtures.py: f = x + 2y + 3z at nodes and element nodes), and for
// watertightness on a grid of hexahedra, pyramids and prisms built here.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/volume/volume_cut.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_probe.hpp"
#include "lancer/util/input_error.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

double linearF(const Vec3d& p) { return p.x + 2 * p.y + 3 * p.z; }

const MeshWithVolume& tetCube() {
  static const MeshWithVolume read = readMshWithVolume(test::dataFile("element_node/tet_v41_bin.msh"));
  return read;
}

double surfaceArea(const Mesh& mesh) {
  double area = 0;
  for (const MeshFace& face : mesh.faces) {
    const Vec3d a = toDouble(mesh.positions[face.vertex[0]]);
    area += 0.5 * length(cross(toDouble(mesh.positions[face.vertex[1]]) - a,
                               toDouble(mesh.positions[face.vertex[2]]) - a));
  }
  return area;
}

Vec3d faceNormal(const Mesh& mesh, const MeshFace& face) {
  const Vec3d a = toDouble(mesh.positions[face.vertex[0]]);
  return normalize(
      cross(toDouble(mesh.positions[face.vertex[1]]) - a, toDouble(mesh.positions[face.vertex[2]]) - a));
}

TEST(VolumeRead, KeepsEveryElementAndEveryFieldStep) {
  const VolumeMesh& volume = *tetCube().volume;
  EXPECT_EQ(volume.cellCount(), 101U);
  EXPECT_EQ(volume.nodes.size(), 45U);
  EXPECT_EQ(volume.fieldSteps("g").size(), 2U);
  ASSERT_NE(volume.findField("jumpe", 0), nullptr);
  EXPECT_EQ(volume.findField("jumpe", 0)->at, FieldAt::kElement);
  EXPECT_EQ(volume.findField("u", 0)->components, 3);
  // The skin is the same as readMsh's.
  const Mesh skin = readMsh(test::dataFile("element_node/tet_v41_bin.msh"));
  EXPECT_EQ(tetCube().mesh.faceCount(), skin.faceCount());
  EXPECT_EQ(tetCube().mesh.fields.size(), skin.fields.size());
}

TEST(VolumeRead, ASurfaceMeshHasAnEmptyVolume) {
  const MeshWithVolume read = readMshWithVolume(test::dataFile("element_node/quad9_v41_bin.msh"));
  EXPECT_TRUE(read.volume->empty());
  EXPECT_GT(read.mesh.faceCount(), 0U);
}

TEST(VolumeProbe, LinearFieldsAreExactInsideEveryTetrahedron) {
  const VolumeMesh& volume = *tetCube().volume;
  const VolumeLocator locator(volume);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> inside(0.001, 0.999);
  for (int i = 0; i < 200; ++i) {
    const Vec3d p{inside(random), inside(random), inside(random)};
    const ProbeResult result = probeVolume(volume, locator, p, "", std::nullopt, "cube.msh");
    std::map<std::string, std::vector<float>> value;
    for (const ProbeValue& v : result.values) value[v.name + std::to_string(v.step)] = v.values;
    EXPECT_NEAR(value["f0"][0], linearF(p), 2e-6) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(value["g0"][0], linearF(p), 2e-6);
    EXPECT_NEAR(value["g1"][0], 2 * linearF(p), 4e-6);
    EXPECT_NEAR(value["u0"][0], 0.1 * p.x, 1e-7);
    EXPECT_NEAR(value["u0"][1], 0.2 * p.y, 1e-7);
    // Element data and element-node data of one value per element agree: the element's own.
    EXPECT_EQ(value["jump0"][0], value["jumpe0"][0]);
  }
}

TEST(VolumeProbe, SaysWhatIsWrong) {
  const VolumeMesh& volume = *tetCube().volume;
  const VolumeLocator locator(volume);
  const auto message = [&](const Vec3d& p, const std::string& field, std::optional<int> step) {
    try {
      probeVolume(volume, locator, p, field, step, "cube.msh");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({2, 0.5, 0.5}, "f", 0).find("inside no volume element"), std::string::npos);
  EXPECT_NE(
      message({0.5, 0.5, 0.5}, "F", 0).find("no field 'F' in the file; its fields: f, g, jump, jumpe, u"),
      std::string::npos)
      << message({0.5, 0.5, 0.5}, "F", 0);
  EXPECT_NE(message({0.5, 0.5, 0.5}, "g", 7).find("no step 7 of 'g'; its steps: 0, 1"), std::string::npos);
  EXPECT_NE(message({NAN, 0.5, 0.5}, "f", 0).find("inside no volume element"), std::string::npos);
  const VolumeMesh empty;
  const VolumeLocator none(empty);
  EXPECT_THROW(probeVolume(empty, none, {0, 0, 0}, "", std::nullopt, "flat.msh"), InputError);
}

TEST(VolumeSlice, APlaneThroughTheCubeIsItsSquareColouredByTheField) {
  const VolumeMesh& volume = *tetCube().volume;
  const Vec3d origin = volume.origin;
  const VolumeCut cut = sliceVolume(volume, Vec3d{0, 0, 0.3} - origin, {0, 0, 2});
  ASSERT_GT(cut.surface.faceCount(), 0U);
  EXPECT_NEAR(surfaceArea(cut.surface), 1.0, 1e-5);
  for (const MeshFace& face : cut.surface.faces) EXPECT_GT(faceNormal(cut.surface, face).z, 0.999999);
  const MeshField f = cutField(cut, volume, *volume.findField("f", 0));
  const MeshField g = cutField(cut, volume, *volume.findField("g", 0));
  const MeshField jumpe = cutField(cut, volume, *volume.findField("jumpe", 0));
  ASSERT_EQ(f.at, FieldAt::kNode);
  ASSERT_EQ(g.at, FieldAt::kCorner);
  for (std::size_t v = 0; v < cut.surface.positions.size(); ++v) {
    const Vec3d p = origin + toDouble(cut.surface.positions[v]);
    EXPECT_NEAR(p.z, 0.3, 1e-6);
    EXPECT_NEAR(f.values[v], linearF(p), 2e-6);
  }
  for (std::size_t face = 0; face < cut.surface.faceCount(); ++face) {
    for (int c = 0; c < 3; ++c) {
      const Vec3d p = origin + toDouble(cut.surface.positions[cut.surface.faces[face].vertex[c]]);
      const auto slot = static_cast<std::size_t>(cornerSlot(cut.surface.faces[face], c));
      EXPECT_NEAR(g.values[face * kCornerSlots + slot], linearF(p), 2e-6);
    }
    EXPECT_EQ(jumpe.values[face], volume.findField("jumpe", 0)->values[cut.faceCell[face]]);
  }
}

TEST(VolumeSlice, APlaneMissingTheVolumeGivesNoTriangles) {
  const VolumeMesh& volume = *tetCube().volume;
  EXPECT_EQ(sliceVolume(volume, Vec3d{0, 0, 5} - volume.origin, {0, 0, 1}).surface.faceCount(), 0U);
}

TEST(VolumeIsosurface, OfALinearFieldIsTheExactPlane) {
  const VolumeMesh& volume = *tetCube().volume;
  const VolumeField& f = *volume.findField("f", 0);
  const CellLevels levels = [&](std::uint32_t cell, float* out) { cellPointValues(volume, f, cell, out); };
  const VolumeCut cut = cutVolume(volume, levels, 3.0F, true);
  // x + 2y + 3z = 3 crosses the whole unit square's column: its area is the square's over cos(n, z).
  EXPECT_NEAR(surfaceArea(cut.surface), std::sqrt(14.0) / 3.0, 1e-5);
  const Vec3d n = normalize(Vec3d{1, 2, 3});
  for (const MeshFace& face : cut.surface.faces) EXPECT_GT(dot(faceNormal(cut.surface, face), n), 0.99999);
  for (const Vec3& position : cut.surface.positions)
    EXPECT_NEAR(linearF(volume.origin + toDouble(position)), 3.0, 2e-6);
}

// A grid of unit cubes meshed conformingly with hexahedra, six pyramids about an added centre
// node, and columns of prisms (each cube split by the same vertical diagonal plane).
VolumeMesh mixedGrid(int n) {
  VolumeMesh volume;
  const auto node = [n](int i, int j, int k) {
    return static_cast<std::uint32_t>((k * (n + 1) + j) * (n + 1) + i);
  };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) volume.nodes.push_back(Vec3{float(i), float(j), float(k)});
  const auto add = [&](CellShape shape, std::initializer_list<std::uint32_t> corners) {
    std::array<std::uint32_t, kMaxCellCorners> cell;
    cell.fill(kNoVertex);
    std::copy(corners.begin(), corners.end(), cell.begin());
    volume.cells.push_back(cell);
    volume.shapes.push_back(shape);
    volume.cellPhysicalTag.push_back(1);
    volume.cellEntityTag.push_back(1);
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::uint32_t c[8] = {
            node(i, j, k),     node(i + 1, j, k),     node(i + 1, j + 1, k),     node(i, j + 1, k),
            node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)};
        if ((i + j) % 3 == 2) {
          add(CellShape::kPrism, {c[0], c[1], c[2], c[4], c[5], c[6]});
          add(CellShape::kPrism, {c[0], c[2], c[3], c[4], c[6], c[7]});
        } else if ((i + j + k) % 2 == 0) {
          add(CellShape::kHexahedron, {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]});
        } else {
          const auto centre = static_cast<std::uint32_t>(volume.nodes.size());
          volume.nodes.push_back(Vec3{i + 0.5F, j + 0.5F, k + 0.5F});
          add(CellShape::kPyramid, {c[0], c[3], c[2], c[1], centre});
          add(CellShape::kPyramid, {c[4], c[5], c[6], c[7], centre});
          add(CellShape::kPyramid, {c[0], c[1], c[5], c[4], centre});
          add(CellShape::kPyramid, {c[1], c[2], c[6], c[5], centre});
          add(CellShape::kPyramid, {c[2], c[3], c[7], c[6], centre});
          add(CellShape::kPyramid, {c[3], c[0], c[4], c[7], centre});
        }
      }
  VolumeField field;
  field.name = "r";
  for (const Vec3& p : volume.nodes) {
    const Vec3d d = toDouble(p) - Vec3d{n / 2.0 + 0.1, n / 2.0 - 0.2, n / 2.0 + 0.05};
    field.values.push_back(static_cast<float>(length(d) + 0.3 * std::sin(3 * p.x)));
  }
  volume.fields.push_back(field);
  return volume;
}

// Every edge of the surface is shared by exactly two of its triangles.
void expectClosed(const Mesh& surface) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const MeshFace& face : surface.faces)
    for (int c = 0; c < 3; ++c) {
      std::uint32_t a = face.vertex[c], b = face.vertex[(c + 1) % 3];
      if (a > b) std::swap(a, b);
      ++uses[{a, b}];
    }
  int open = 0;
  for (const auto& [edge, count] : uses) open += count != 2;
  EXPECT_EQ(open, 0) << "of " << uses.size() << " edges";
}

TEST(VolumeIsosurface, IsWatertightOnHexahedraPyramidsAndPrisms) {
  const VolumeMesh volume = mixedGrid(6);
  const VolumeField& r = volume.fields[0];
  const CellLevels levels = [&](std::uint32_t cell, float* out) { cellPointValues(volume, r, cell, out); };
  for (const float value : {1.3F, 2.0F, 2.6F}) {
    const VolumeCut cut = cutVolume(volume, levels, value, true);
    ASSERT_GT(cut.surface.faceCount(), 50U);
    expectClosed(cut.surface);
  }
}

TEST(VolumeProbe, ALinearFieldIsExactInHexahedraPyramidsAndPrisms) {
  VolumeMesh volume = mixedGrid(3);
  VolumeField& f = volume.fields[0];
  for (std::size_t v = 0; v < volume.nodes.size(); ++v)
    f.values[v] = static_cast<float>(linearF(toDouble(volume.nodes[v])));
  const VolumeLocator locator(volume);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> inside(0.0, 3.0);
  for (int i = 0; i < 300; ++i) {
    const Vec3d p{inside(random), inside(random), inside(random)};
    const CellPoint at = locator.locate(p);
    ASSERT_TRUE(at.inside()) << p.x << " " << p.y << " " << p.z;
    float value = 0;
    locator.interpolate(f, at, &value);
    EXPECT_NEAR(value, linearF(p), 1e-4);
  }
}

}  // namespace
}  // namespace lancer
