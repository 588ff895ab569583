// List-based .pos views as meshes and on meshes (mesh/pos/pos_mesh.hpp, pos_on_mesh.hpp), read
// through the one door (readMsh, addViewFiles) from what gmsh and GetDP wrote (tests/data/pos/,
// scripts/make_pos_fixtures.py). gmsh's fixtures hold a closed form of their node's coordinates,
// so every face corner's value is checked against where the corner is; GetDP's magnet views are
// checked against the .pos values of the element whose coordinates the face has.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string posFixture(const std::string& name) { return test::dataFile("pos/" + name); }

Mesh meshFromText(const std::string& text, const std::string& name = "f.pos") {
  return readMshFromMemory(std::span<const char>(text.data(), text.size()), name);
}

// scripts/make_pos_fixtures.py's value(x, y, z, step, component).
double closedForm(const Vec3d& p, int step, int component) {
  return p.x + 2 * p.y + 4 * p.z + 16 * step + component / 8.0;
}

std::vector<const MeshField*> fieldsNamed(const Mesh& mesh, const std::string& name) {
  std::vector<const MeshField*> fields;
  for (const MeshField& field : mesh.fields)
    if (field.name == name) fields.push_back(&field);
  return fields;
}

// The value of corner c of face f (its slot, mesh.hpp's cornerSlot), component k.
float cornerValue(const Mesh& mesh, const MeshField& field, std::size_t f, int c, int k = 0) {
  const std::size_t slot = static_cast<std::size_t>(cornerSlot(mesh.faces[f], c));
  return field.values[(f * kCornerSlots + slot) * static_cast<std::size_t>(field.components) +
                      static_cast<std::size_t>(k)];
}

// Every corner of every face carries closedForm of where it is, for every step and component.
void expectClosedFormAtCorners(const Mesh& mesh, const std::string& name, int components, int steps,
                               const std::vector<double>& times) {
  const std::vector<const MeshField*> fields = fieldsNamed(mesh, name);
  ASSERT_EQ(fields.size(), static_cast<std::size_t>(steps)) << name;
  for (int step = 0; step < steps; ++step) {
    const MeshField& field = *fields[static_cast<std::size_t>(step)];
    EXPECT_EQ(field.at, FieldAt::kCorner);
    EXPECT_EQ(field.components, components);
    EXPECT_EQ(field.step, step);
    EXPECT_EQ(field.time, times[static_cast<std::size_t>(step)]);
    ASSERT_EQ(field.values.size(), mesh.faces.size() * kCornerSlots * static_cast<std::size_t>(components));
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      for (int c = 0; c < mesh.faces[f].cornerCount(); ++c) {
        const Vec3d p = mesh.worldPosition(mesh.faces[f].vertex[c]);
        for (int k = 0; k < components; ++k)
          ASSERT_NEAR(cornerValue(mesh, field, f, c, k), closedForm(p, step, k), 1e-4)
              << name << " step " << step << " face " << f << " corner " << c << " component " << k;
      }
  }
}

TEST(PosMesh, GmshListsOfEveryShapeBecomeOneMeshWithTheirValuesAtEveryCorner) {
  const Mesh mesh = readMsh(posFixture("gmsh_lists.pos"));
  EXPECT_EQ(mesh.source.format, "pos");
  // Three views on the same elements: one geometry. Two of each shape: points and lines counted,
  // triangles and quads as faces, volumes by their skin (tetrahedra 4 faces, hexahedra 6, prisms 5,
  // pyramids 5).
  const std::map<int, std::uint64_t> expected = {{15, 2}, {1, 2}, {2, 2}, {3, 2},
                                                 {4, 2},  {5, 2}, {6, 2}, {7, 2}};
  EXPECT_EQ(mesh.source.elementsByType, expected);
  EXPECT_EQ(mesh.source.volumeElements, 8u);
  EXPECT_EQ(mesh.faces.size(), 2u + 2u + 2u * (4 + 6 + 5 + 5));
  EXPECT_TRUE(mesh.physicalGroups.empty());
  expectClosedFormAtCorners(mesh, "scalar", 1, 2, {0, 1});
  expectClosedFormAtCorners(mesh, "vector", 3, 2, {0, 1});
  expectClosedFormAtCorners(mesh, "tensor", 9, 2, {0, 1});
}

TEST(PosMesh, SecondOrderElementsAreSplitAndKeepTheValuesOfTheirNodes) {
  const Mesh mesh = readMsh(posFixture("second_order.pos"));
  // 6-node triangles and 9-node quads split in four; the skin of 10-node tetrahedra and 27-node
  // hexahedra through their edge nodes, that of prisms and pyramids through their corners.
  EXPECT_EQ(mesh.source.elementsByType.at(9), 1u);
  EXPECT_EQ(mesh.source.elementsByType.at(12), 1u);
  EXPECT_GT(mesh.faces.size(), 4u + 4u + 4u * 4u + 6u * 4u);
  expectClosedFormAtCorners(mesh, "scalar2", 1, 2, {0.5, 1.5});
  expectClosedFormAtCorners(mesh, "vector2", 3, 2, {0.5, 1.5});
  expectClosedFormAtCorners(mesh, "tensor2", 9, 2, {0.5, 1.5});
}

TEST(PosMesh, AnElementTwoViewsListInAnotherOrderIsOneFaceWithEachViewsValuesAtItsNodes) {
  const Mesh mesh = meshFromText(
      "View \"a\" {\nST(0,0,0,1,0,0,0,1,0){1,2,3};\n};\n"
      "View \"b\" {\nST(1,0,0,0,1,0,0,0,0){20,30,10};\n};\n");
  ASSERT_EQ(mesh.faces.size(), 1u);
  const std::vector<const MeshField*> a = fieldsNamed(mesh, "a"), b = fieldsNamed(mesh, "b");
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  for (int c = 0; c < 3; ++c) {
    const Vec3d p = mesh.worldPosition(mesh.faces[0].vertex[c]);
    const float expectedA = p.x == 1 ? 2.0f : p.y == 1 ? 3.0f : 1.0f;
    EXPECT_EQ(cornerValue(mesh, *a[0], 0, c), expectedA) << c;
    EXPECT_EQ(cornerValue(mesh, *b[0], 0, c), 10 * expectedA) << c;
  }
}

TEST(PosMesh, GetdpTransientStepsKeepTheirTimes) {
  const Mesh mesh = readMsh(posFixture("heat/t.pos"));
  for (const char* name : {"T", "gradT"}) {
    const std::vector<const MeshField*> steps = viewSteps(mesh, name);
    ASSERT_EQ(steps.size(), 4u) << name;
    const double times[] = {0, 0.01, 0.02, 0.03};
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(steps[k]->step, static_cast<int>(k));
      EXPECT_EQ(steps[k]->time, times[k]);
    }
  }
  // A time loop that appends a view per step (no TIME list): views of one name are its steps.
  const Mesh appended = readMsh(posFixture("heat/steps.pos"));
  const std::vector<const MeshField*> steps = viewSteps(appended, "T");
  ASSERT_EQ(steps.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(steps[k]->step, static_cast<int>(k));
    EXPECT_EQ(steps[k]->time, static_cast<double>(k));
  }
  // Its last step is t.pos's last: the same elements, the same values.
  const MeshField& last = *viewSteps(mesh, "T").back();
  EXPECT_EQ(steps.back()->values.size(), last.values.size());
}

// The nodes of an MSH 2.2 ASCII file as written: tag -> (x, y, z).
std::map<long, std::array<double, 3>> mshNodes(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && line != "$Nodes") {
  }
  std::size_t count = 0;
  in >> count;
  std::map<long, std::array<double, 3>> nodes;
  for (std::size_t i = 0; i < count; ++i) {
    long tag = 0;
    std::array<double, 3> p{};
    in >> tag >> p[0] >> p[1] >> p[2];
    nodes[tag] = p;
  }
  return nodes;
}

TEST(PosOnMesh, GetdpPrintsTheNodesOfItsMeshWithTheSameNumbers) {
  // What matching by exact coordinates rests on: every node of GetDP's views is a node of the .msh
  // it solved on, to the last bit.
  std::set<std::array<double, 3>> meshNodes;
  for (const auto& [tag, p] : mshNodes(posFixture("magnet/magnet.msh"))) meshNodes.insert(p);
  ASSERT_EQ(meshNodes.size(), 159u);
  for (const char* file : {"magnet/az.pos", "magnet/b_a.pos"}) {
    const PosFile pos = readPosFile(posFixture(file));
    std::size_t checked = 0;
    for (const PosView& view : pos.views)
      for (const PosElementBlock& block : view.blocks)
        for (std::size_t i = 0; i < block.coords.size(); i += 3, ++checked)
          ASSERT_TRUE(meshNodes.count({block.coords[i], block.coords[i + 1], block.coords[i + 2]}))
              << file << ": " << block.coords[i] << " " << block.coords[i + 1] << " " << block.coords[i + 2];
    EXPECT_EQ(checked, 279u * 3u) << file;
  }
}

// The element of `view` whose nodes are the face's corners, and where each corner is among them.
struct ViewElementAt {
  const PosElementBlock* block = nullptr;
  std::size_t element = 0;
  std::array<int, 4> node{};
};
ViewElementAt elementOfFace(const Mesh& mesh, const PosView& view, std::size_t f) {
  const MeshFace& face = mesh.faces[f];
  for (const PosElementBlock& block : view.blocks)
    for (std::size_t e = 0; e < block.elementCount(); ++e) {
      ViewElementAt at{&block, e, {}};
      bool all = true;
      for (int c = 0; c < face.cornerCount() && all; ++c) {
        const Vec3 corner = mesh.positions[face.vertex[c]];
        all = false;
        for (int j = 0; j < block.nodesPerElement() && !all; ++j) {
          const double* p = &block.coords[(e * block.nodesPerElement() + j) * 3];
          if (toFloat(Vec3d{p[0], p[1], p[2]} - mesh.origin) == corner) all = true, at.node[c] = j;
        }
      }
      if (all) return at;
    }
  return {};
}

TEST(PosOnMesh, EveryFaceOfTheMagnetTakesItsElementsValuesFromGetdpsViews) {
  Mesh mesh = readMsh(posFixture("magnet/magnet.msh"));
  addViewFiles(mesh, {posFixture("magnet/az.pos"), posFixture("magnet/b_a.pos")});
  // The views are printed on Vol_Mag, every region of the model: every face has its values.
  const PosFile az = readPosFile(posFixture("magnet/az.pos"));
  const PosFile b = readPosFile(posFixture("magnet/b_a.pos"));
  const std::vector<const MeshField*> azField = fieldsNamed(mesh, "az"), bField = fieldsNamed(mesh, "b");
  ASSERT_EQ(azField.size(), 1u);
  ASSERT_EQ(bField.size(), 1u);
  EXPECT_EQ(bField[0]->components, 3);
  std::set<std::int32_t> regions;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    regions.insert(mesh.facePhysicalTag[f]);
    for (const auto& [field, pos] : {std::pair{azField[0], &az}, std::pair{bField[0], &b}}) {
      const ViewElementAt at = elementOfFace(mesh, pos->views[0], f);
      ASSERT_NE(at.block, nullptr) << "face " << f;
      const float* values = pos->views[0].elementValues(*at.block, at.element, 0);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < field->components; ++k)
          ASSERT_EQ(cornerValue(mesh, *field, f, c, k), values[at.node[c] * field->components + k])
              << field->name << " face " << f << " corner " << c;
    }
  }
  // Air, Spherical shell, Airgap, Magnet, Core: the regions of Vol_Mag.
  EXPECT_EQ(regions, (std::set<std::int32_t>{100, 101, 102, 103, 104}));
}

TEST(PosOnMesh, AFaceOfTheMagnetFoundByItsCoordinatesHasTheJumpOfB) {
  Mesh mesh = readMsh(posFixture("magnet/magnet.msh"));
  addViewFiles(mesh, {posFixture("magnet/b_a.pos")});
  const MeshField& b = *fieldsNamed(mesh, "b").front();
  // The first element GetDP printed: its corners in the file, its b at each.
  const Vec3d corners[] = {{-0.09567085780739318, 0.2309698832454083, 0},
                           {-0.1246186360765172, 0.1715228382367372, 0},
                           {-0.08407702922352449, 0.1694878087822198, 0}};
  const float bx[] = {2.356140762083859e-19f, 0.0009439487001487366f, 0.001344786233588612f};
  std::size_t found = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::array<int, 3> corner{-1, -1, -1};  // which of `corners` each corner of the face is
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        if (mesh.positions[mesh.faces[f].vertex[c]] == toFloat(corners[k] - mesh.origin)) corner[c] = k;
    if (std::count(corner.begin(), corner.end(), -1) != 0) continue;
    ++found;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(cornerValue(mesh, b, f, c, 0), bx[corner[c]]) << c;
  }
  EXPECT_EQ(found, 1u);
  // b is constant on each first-order triangle of az: faces that share a node give it other values.
  std::size_t jumps = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::size_t g = f + 1; g < mesh.faces.size(); ++g)
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          if (mesh.faces[f].vertex[c] == mesh.faces[g].vertex[d] &&
              cornerValue(mesh, b, f, c, 0) != cornerValue(mesh, b, g, d, 0))
            ++jumps;
  EXPECT_GT(jumps, 100u);
}

TEST(PosOnMesh, TheSkinOfATetrahedralViewTakesItsTetrahedraValues) {
  // The tetrahedra of gmsh_lists.pos put on the mesh of their own skin (read from the .pos): each
  // skin face's corners carry its tetrahedron's values, which are closedForm of where they are.
  const std::string tets = [] {
    std::ifstream in(posFixture("gmsh_lists.pos"));
    std::string line, out = "View \"tets\" {\n";
    bool scalar = false;
    while (std::getline(in, line)) {
      if (line.starts_with("View \"")) scalar = line.starts_with("View \"scalar\"");
      if (scalar && line.starts_with("SS(")) out += line + "\n";
      if (scalar && line.starts_with("TIME")) out += line + "\n";
    }
    return out + "};\n";
  }();
  Mesh mesh = readMsh(posFixture("gmsh_lists.pos"));
  test::ScratchFolder scratch;
  scratch.write("tets.pos", tets);
  addViewFiles(mesh, {scratch.file("tets.pos")});
  const std::vector<const MeshField*> steps = fieldsNamed(mesh, "tets");
  ASSERT_EQ(steps.size(), 2u);
  std::size_t covered = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (std::isnan(cornerValue(mesh, *steps[1], f, 0))) continue;
    ++covered;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(cornerValue(mesh, *steps[1], f, c),
                  closedForm(mesh.worldPosition(mesh.faces[f].vertex[c]), 1, 0), 1e-4);
  }
  EXPECT_EQ(covered, 8u);  // two tetrahedra's skin; every other face NaN
}

TEST(PosOnMesh, FacesNoElementOfAViewCoversAreNan) {
  // GetDP prints a view on some regions only: here the first 10 elements of az.
  std::ifstream in(posFixture("magnet/az.pos"));
  std::string line, part;
  int elements = 0;
  while (std::getline(in, line)) {
    if (line.starts_with("ST(") && ++elements > 10) continue;
    part += line + "\n";
  }
  test::ScratchFolder scratch;
  scratch.write("part.pos", part);
  Mesh mesh = readMsh(posFixture("magnet/magnet.msh"));
  addViewFiles(mesh, {scratch.file("part.pos")});
  const MeshField& az = *fieldsNamed(mesh, "az").front();
  std::size_t covered = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const bool nan = std::isnan(cornerValue(mesh, az, f, 0));
    for (int c = 1; c < 3; ++c) EXPECT_EQ(std::isnan(cornerValue(mesh, az, f, c)), nan);
    covered += !nan;
  }
  EXPECT_EQ(covered, 10u);
}

TEST(PosOnMesh, AViewOnNoFaceOfTheMeshIsAnErrorThatSaysWhatToDo) {
  Mesh mesh = readMsh(posFixture("magnet/magnet.msh"));
  const std::string message = test::messageOf([&] { addViewFiles(mesh, {posFixture("heat/t.pos")}); });
  EXPECT_NE(message.find("t.pos:1: error: view \"T\" matches no face of "), std::string::npos) << message;
  EXPECT_NE(message.find("magnet.msh: none of its 33 elements has the corners of a face of that mesh among "
                         "its nodes (the view spans [0, 0, 0] .. [1, 1, 0], the mesh [-0.25, 0, 0] .. "
                         "[0.25, 0.25, 0]); give the mesh the view was computed on"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("or draw the view on its own elements: lancer render "), std::string::npos)
      << message;
}

TEST(PosOnMesh, AViewOfPointsAndLinesIsSkippedWithAWarning) {
  Mesh mesh = readMsh(posFixture("magnet/magnet.msh"));
  test::ScratchFolder scratch;
  scratch.write("lines.pos", "View \"edge\" {\nSL(0,0,0,0.1,0,0){1,2};\n};\n");
  addViewFiles(mesh, {scratch.file("lines.pos")});
  EXPECT_TRUE(fieldsNamed(mesh, "edge").empty());
  ASSERT_FALSE(mesh.source.warnings.empty());
  EXPECT_NE(
      mesh.source.warnings.back().find(
          "lines.pos:1: warning: view \"edge\" holds only points and lines, which lancer does not draw"),
      std::string::npos)
      << mesh.source.warnings.back();
}

TEST(PosMesh, AViewOfScalarAndVectorElementsIsAnError) {
  const std::string message = test::messageOf([] {
    meshFromText(
        "View \"mixed\" {\nST(0,0,0,1,0,0,0,1,0){1,2,3};\n"
        "VT(1,0,0,1,1,0,0,1,0){1,0,0,1,0,0,1,0,0};\n};\n",
        "mixed.pos");
  });
  EXPECT_EQ(
      message,
      "mixed.pos:1: error: view \"mixed\" holds scalar elements (ST at line 2) and vector elements (VT at "
      "line 3): lancer makes one field of a view, of one kind; write them as two views");
}

}  // namespace
}  // namespace lancer
