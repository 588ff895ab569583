// The reader against gmsh itself: for every fixture, the node count, element counts, bounding box and
// surface area that gmsh 4.8 reports after reading the same file (tests/data/msh/gmsh_reference.tsv,
// written by scripts/gmsh_reference.sh: Mesh.NbNodes/NbTriangles/..., Plugin(MathEval) min/max of x,
// y, z, Plugin(Integrate) of 1 over the surface or Plugin(Skin) boundary).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::mshFixture;

// Element families in the column order of the table.
constexpr const char* kFamilies[] = {"triangle",   "quadrangle", "tetrahedron",
                                     "hexahedron", "prism",      "pyramid"};
constexpr int kFamilyCount = 6;

struct GmshReference {
  std::string file;
  std::uint64_t nodes = 0;
  std::uint64_t elements[kFamilyCount] = {};
  Vec3d lower, upper;
  double area = 0;
};

std::ostream& operator<<(std::ostream& out, const GmshReference& r) { return out << r.file; }

std::vector<GmshReference> readReferenceTable() {
  std::ifstream in(mshFixture("gmsh_reference.tsv"));
  std::vector<GmshReference> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    GmshReference row;
    fields >> row.file >> row.nodes;
    for (auto& count : row.elements) fields >> count;
    fields >> row.lower.x >> row.lower.y >> row.lower.z >> row.upper.x >> row.upper.y >> row.upper.z >>
        row.area;
    if (!fields) throw std::runtime_error("gmsh_reference.tsv: bad line: " + line);
    rows.push_back(row);
  }
  return rows;
}

const std::vector<GmshReference>& referenceTable() {
  static const std::vector<GmshReference> table = readReferenceTable();
  return table;
}

// The family of a gmsh element type, by the last word of its name ("6-node triangle"); -1 for others.
int familyOf(int type) {
  const std::string name = mshElementTypeName(type);
  for (int f = 0; f < kFamilyCount; ++f)
    if (name.ends_with(std::string(" ") + kFamilies[f])) return f;
  return -1;
}

class GmshReferenceTest : public testing::TestWithParam<GmshReference> {};

TEST_P(GmshReferenceTest, CountsBoundsAndAreaMatchGmsh) {
  const GmshReference& expected = GetParam();
  const Mesh mesh = readMsh(mshFixture(expected.file));
  const MeshStats stats = computeMeshStats(mesh);
  const MeshSourceInfo& source = mesh.source;
  EXPECT_EQ(source.nodeCount, expected.nodes);

  // MSH 2 writes an element once per physical group it belongs to; gmsh reads every copy as an
  // element (and integrates it again), lancer keeps the first copy and counts the others. In these
  // fixtures every surface and volume element has the same number of copies.
  std::uint64_t read[kFamilyCount] = {};
  std::uint64_t readTotal = 0;
  for (const auto& [type, count] : source.elementsByType) {
    if (const int family = familyOf(type); family >= 0) {
      read[family] += count;
      readTotal += count;
    }
  }
  ASSERT_GT(readTotal, 0u);
  const std::uint64_t copies = (readTotal + source.duplicateElementsSkipped) / readTotal;
  ASSERT_EQ(copies * readTotal, readTotal + source.duplicateElementsSkipped) << "uneven MSH 2 copies";
  if (source.formatVersion != "2.2") {
    EXPECT_EQ(copies, 1u);
  }
  for (int f = 0; f < kFamilyCount; ++f) {
    EXPECT_EQ(read[f] * copies, expected.elements[f]) << kFamilies[f];
  }

  if (!source.unrenderableByType.empty()) {
    // Third-order elements are counted, not rendered: no faces, so no box and no area.
    EXPECT_EQ(mesh.faceCount(), 0u);
    EXPECT_GT(expected.area, 0.0);
    return;
  }
  // Positions are float offsets from the box centre: exact to about 1e-7 of the box size.
  const double tolerance = 1e-6 * std::max(1.0, length(expected.upper - expected.lower));
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(stats.worldBounds.lower[axis], expected.lower[axis], tolerance) << "axis " << axis;
    EXPECT_NEAR(stats.worldBounds.upper[axis], expected.upper[axis], tolerance) << "axis " << axis;
  }
  EXPECT_NEAR(stats.area * static_cast<double>(copies), expected.area, 1e-6 * expected.area);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, GmshReferenceTest, testing::ValuesIn(referenceTable()),
                         [](const testing::TestParamInfo<GmshReference>& param) {
                           return test::fixtureTestName(param.param.file);
                         });

TEST(GmshReference, EveryFixtureHasGmshFigures) {
  std::set<std::string> listed;
  for (const GmshReference& row : referenceTable()) listed.insert(row.file);
  std::size_t fixtures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(mshFixture(""))) {
    if (entry.path().extension() != ".msh") continue;
    ++fixtures;
    EXPECT_TRUE(listed.count(entry.path().filename().string()))
        << entry.path() << " is missing from gmsh_reference.tsv: run scripts/gmsh_reference.sh";
  }
  EXPECT_EQ(listed.size(), fixtures);
}

}  // namespace
}  // namespace lancer
