// The volume of a list-based .pos view (meshFromPos with its volume, addViewFiles on a mesh's
// volume), checked against closed forms on the views gmsh wrote on a tetrahedral cube
// (scripts/make_pos_fixtures.py: f = x + 2y + 3z, then f + 10, and u = (1, 2, 3) at the nodes).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/pos/pos_on_volume.hpp"
#include "lancer/mesh/volume/volume_cut.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_probe.hpp"
#include "lancer/util/input_error.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

double linearF(const Vec3d& p) { return p.x + 2 * p.y + 3 * p.z; }

std::string cubePos() { return test::dataFile("pos/volume/cube.pos"); }
std::string cubeMsh() { return test::dataFile("pos/volume/cube.msh"); }

const MeshWithVolume& posCube() {
  static const MeshWithVolume read = readMshWithVolume(cubePos());
  return read;
}

// The mesh the views were computed on, with the views put on it.
const MeshWithVolume& mshCubeWithViews() {
  static const MeshWithVolume read = [] {
    MeshWithVolume result = readMshWithVolume(cubeMsh());
    addViewFiles(result, {cubePos()});
    return result;
  }();
  return read;
}

// Every field at random points inside the cube: f and f + 10 exact (linear on each tetrahedron),
// u the constant.
void expectLinearFields(const VolumeMesh& volume) {
  const VolumeLocator locator(volume);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> inside(0.001, 0.999);
  for (int i = 0; i < 100; ++i) {
    const Vec3d p{inside(random), inside(random), inside(random)};
    const ProbeResult f0 = probeVolume(volume, locator, p, "f", 0, "cube.pos");
    const ProbeResult f1 = probeVolume(volume, locator, p, "f", 1, "cube.pos");
    const ProbeResult u = probeVolume(volume, locator, p, "u", 0, "cube.pos");
    EXPECT_NEAR(f0.values.front().values[0], linearF(p), 4e-6) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(f1.values.front().values[0], linearF(p) + 10, 4e-6);
    EXPECT_NEAR(u.values.front().values[0], 1, 1e-6);
    EXPECT_NEAR(u.values.front().values[1], 2, 1e-6);
    EXPECT_NEAR(u.values.front().values[2], 3, 1e-6);
  }
}

// Each cell's corner values are f at its corners: the values follow the corners they belong to.
void expectCornerValues(const VolumeMesh& volume) {
  const VolumeField* f = volume.findField("f", 0);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->at, FieldAt::kCorner);
  for (std::size_t c = 0; c < volume.cellCount(); ++c)
    for (int k = 0; k < cellCornerCount(volume.shapes[c]); ++k) {
      const Vec3d p = volume.origin + toDouble(volume.nodes[volume.cells[c][static_cast<std::size_t>(k)]]);
      ASSERT_NEAR(f->values[c * kMaxCellCorners + static_cast<std::size_t>(k)], linearF(p), 4e-6);
    }
}

TEST(PosVolume, AViewsTetrahedraAreTheVolumeOfItsMergedPoints) {
  const VolumeMesh& volume = *posCube().volume;
  const std::shared_ptr<const VolumeMesh> msh = readMshWithVolume(cubeMsh()).volume;
  const VolumeMesh& fromMsh = *msh;
  EXPECT_EQ(volume.cellCount(), fromMsh.cellCount());
  EXPECT_EQ(volume.nodes.size(), fromMsh.nodes.size());  // coincident corners are one node
  ASSERT_EQ(volume.fieldSteps("f").size(), 2U);
  EXPECT_EQ(volume.fieldSteps("f")[1]->time, 1.0);
  ASSERT_NE(volume.findField("u", 0), nullptr);
  EXPECT_EQ(volume.findField("u", 0)->components, 3);
  EXPECT_EQ(volume.fieldNameList(), "f, u");
  // The skin is what readMsh makes of the view.
  EXPECT_EQ(posCube().mesh.faceCount(), readMsh(cubePos()).faceCount());
}

TEST(PosVolume, ProbesOfALinearViewAreExact) {
  expectLinearFields(*posCube().volume);
  expectCornerValues(*posCube().volume);
}

TEST(PosVolume, ViewsPutOnTheirMeshAreFieldsOfItsVolume) {
  const VolumeMesh& volume = *mshCubeWithViews().volume;
  EXPECT_EQ(volume.fieldNameList(), "f, u");
  EXPECT_EQ(volume.fieldSteps("f").size(), 2U);
  expectLinearFields(volume);
  expectCornerValues(volume);
  // The mesh's own faces have them too.
  EXPECT_EQ(mshCubeWithViews().mesh.fields.size(), 3U);
}

TEST(PosVolume, TheIsosurfaceOfALinearViewIsTheExactPlane) {
  const VolumeMesh& volume = *posCube().volume;
  const VolumeField& f = *volume.findField("f", 0);
  const CellLevels levels = [&](std::uint32_t cell, float* out) { cellPointValues(volume, f, cell, out); };
  const VolumeCut cut = cutVolume(volume, levels, 3.0F, true);
  double area = 0;
  for (const MeshFace& face : cut.surface.faces) {
    const Vec3d a = toDouble(cut.surface.positions[face.vertex[0]]);
    area += 0.5 * length(cross(toDouble(cut.surface.positions[face.vertex[1]]) - a,
                               toDouble(cut.surface.positions[face.vertex[2]]) - a));
  }
  EXPECT_NEAR(area, std::sqrt(14.0) / 3.0, 1e-5);
  for (const Vec3& position : cut.surface.positions)
    EXPECT_NEAR(linearF(volume.origin + toDouble(position)), 3.0, 4e-6);
}

// GetDP's default output for the capacitor (tests/data/pos/capacitor: v and e on the air's
// tetrahedra): the same fields from the views alone and from the views put on the mesh GetDP read.
TEST(PosVolume, GetDPsViewsAreTheSameAloneAndOnTheirMesh) {
  MeshWithVolume alone = readMshWithVolume(test::dataFile("pos/capacitor/v.pos"));
  addViewFiles(alone, {test::dataFile("pos/capacitor/e.pos")});
  MeshWithVolume onMesh = readMshWithVolume(test::dataFile("pos/capacitor/capacitor.msh"));
  addViewFiles(onMesh, {test::dataFile("pos/capacitor/v.pos"), test::dataFile("pos/capacitor/e.pos")});
  ASSERT_EQ(alone.volume->cellCount(), onMesh.volume->cellCount());
  EXPECT_EQ(alone.volume->fieldNameList(), "v, e");
  EXPECT_EQ(onMesh.volume->fieldNameList(), "v, e");
  const VolumeLocator aloneLocator(*alone.volume), meshLocator(*onMesh.volume);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> box(-1.45, 1.45);
  int compared = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3d p{box(random), box(random), box(random)};
    if (!aloneLocator.locate(p - alone.volume->origin).inside()) continue;  // inside a plate: a hole
    const ProbeResult a = probeVolume(*alone.volume, aloneLocator, p, "", 0, "v.pos");
    const ProbeResult b = probeVolume(*onMesh.volume, meshLocator, p, "", 0, "capacitor.msh");
    ASSERT_EQ(a.values.size(), 2U);
    ASSERT_EQ(b.values.size(), 2U);
    for (std::size_t f = 0; f < 2; ++f)
      for (std::size_t c = 0; c < a.values[f].values.size(); ++c)
        EXPECT_NEAR(a.values[f].values[c], b.values[f].values[c], 1e-5) << a.values[f].name;
    EXPECT_LE(std::abs(a.values[0].values[0]), 1.0F + 1e-5F);  // between the plates' potentials
    ++compared;
  }
  EXPECT_GT(compared, 150);
  // Between the plates (+1 V above, -1 V below) the field points down.
  const ProbeResult centre = probeVolume(*alone.volume, aloneLocator, {0, 0, 0}, "e", 0, "e.pos");
  EXPECT_LT(centre.values.front().values[2], 0.0F);
}

// Second-order tetrahedra, hexahedra, prisms and pyramids (tests/data/pos/second_order.pos, values
// x + 2y + 4z + 16 step + component / 8 at every node) are cut through their corners: a linear
// field is exact inside each.
TEST(PosVolume, SecondOrderElementsAreTheirCorners) {
  const std::shared_ptr<const VolumeMesh> read =
      readMshWithVolume(test::dataFile("pos/second_order.pos")).volume;
  const VolumeMesh& volume = *read;
  ASSERT_EQ(volume.cellCount(), 4U);
  EXPECT_EQ(volume.fieldNameList(), "scalar2, vector2, tensor2");
  const VolumeLocator locator(volume);
  for (const Vec3d& p :
       {Vec3d{16.2, 0.2, 1.2}, Vec3d{20.3, 0.1, 1.4}, Vec3d{24.2, 0.3, 1.1}, Vec3d{28, 0.1, 1.3}}) {
    const ProbeResult scalar = probeVolume(volume, locator, p, "scalar2", 1, "second_order.pos");
    EXPECT_NEAR(scalar.values.front().values[0], p.x + 2 * p.y + 4 * p.z + 16, 1e-4) << p.x;
    const ProbeResult vector = probeVolume(volume, locator, p, "vector2", 0, "second_order.pos");
    EXPECT_NEAR(vector.values.front().values[2], p.x + 2 * p.y + 4 * p.z + 0.25, 1e-4) << p.x;
  }
}

TEST(PosVolume, AViewOfSurfacesAloneHasNoVolume) {
  const MeshWithVolume read = readMshWithVolume(test::dataFile("pos/heat/t.pos"));
  EXPECT_TRUE(read.volume->empty());
  EXPECT_GT(read.mesh.faceCount(), 0U);
}

TEST(PosVolume, AViewOfAnotherMeshMatchesNoCell) {
  // Another gmsh mesh of the same unit cube: its tetrahedra are not the view's.
  VolumeMesh other = *readMshWithVolume(test::dataFile("element_node/tet_v41_bin.msh")).volume;
  try {
    addPosViews(other, readPosFile(cubePos()));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("view \"f\" has 184 volume elements, and none has the corners"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace lancer
