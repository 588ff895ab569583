// GetDP's list-based views on the volumes of a volume mesh, put on that mesh (mesh/pos/pos_on_mesh.hpp):
// the skin faces show their tetrahedra's values at their corners, jumps between elements kept, and
// a view that gives the interface's own triangles values shows those there. tests/data/pos/layers
// (scripts/make_pos_fixtures.py): two dielectric layers in a unit cube solved exactly by GetDP,
// v = 1.5 z below z = 0.5 and 0.75 + 0.5 (z - 0.5) above, e = (0, 0, -1.5) below and (0, 0, -0.5)
// above; e.pos also lists the interface's triangles (VT), where GetDP's field within them is 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

std::string layersFile(const std::string& name) { return test::dataFile("pos/layers/" + name); }

const MeshField& fieldNamed(const Mesh& mesh, const std::string& name) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name) return field;
  ADD_FAILURE() << "no field " << name;
  return mesh.fields.front();
}

float cornerValue(const Mesh& mesh, const MeshField& field, std::size_t f, int c, int k = 0) {
  const auto slot = static_cast<std::size_t>(cornerSlot(mesh.faces[f], c));
  return field.values[(f * kCornerSlots + slot) * static_cast<std::size_t>(field.components) +
                      static_cast<std::size_t>(k)];
}

double centroidZ(const Mesh& mesh, std::size_t f) {
  double z = 0;
  for (int c = 0; c < 3; ++c) z += mesh.worldPosition(mesh.faces[f].vertex[c]).z / 3;
  return z;
}

// The exact solution's potential at height z, and the field's z component in the layer a face
// (by its centroid) is in.
double potential(double z) { return z <= 0.5 ? 1.5 * z : 0.75 + 0.5 * (z - 0.5); }
double fieldZ(double centroidHeight) { return centroidHeight < 0.5 ? -1.5 : -0.5; }

// e.pos with its element lines rewritten: `keep` says which stay, those starting with `last` (such
// as "VT(") are moved after the others, and `reversed` lists them in the opposite order.
std::string rewrittenView(bool (*keep)(const std::string&), const std::string& last, bool reversed = false) {
  std::ifstream in(layersFile("e.pos"));
  std::string line, head, tail;
  std::vector<std::string> first, second;
  while (std::getline(in, line)) {
    if (line.size() > 3 && line[2] == '(') {
      if (keep(line)) (!last.empty() && line.starts_with(last) ? second : first).push_back(line + "\n");
    } else {
      (first.empty() && second.empty() ? head : tail) += line + "\n";
    }
  }
  first.insert(first.end(), second.begin(), second.end());
  if (reversed) std::reverse(first.begin(), first.end());
  for (const std::string& element : first) head += element;
  return head + tail;
}

Mesh layersWith(const std::vector<std::string>& views) {
  Mesh mesh = readMsh(layersFile("layers.msh"));
  addViewFiles(mesh, views);
  return mesh;
}

TEST(PosVolumeSkin, EverySkinFaceShowsItsTetrahedronsCornerValues) {
  const Mesh mesh = layersWith({layersFile("v.pos"), layersFile("e.pos")});
  ASSERT_EQ(mesh.faceCount(),
            44u);  // 40 on the skin (8 the top's and bottom's triangles), 4 on the interface
  const MeshField& v = fieldNamed(mesh, "v");
  const MeshField& e = fieldNamed(mesh, "e");
  ASSERT_EQ(e.components, 3);
  std::size_t jumps = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const bool interface = mesh.volumeSides.isInterface(f);
    for (int c = 0; c < 3; ++c) {
      const Vec3d p = mesh.worldPosition(mesh.faces[f].vertex[c]);
      EXPECT_NEAR(cornerValue(mesh, v, f, c), potential(p.z), 1e-6) << "face " << f << " corner " << c;
      // The interface's own triangles carry GetDP's field within them (0), every other face its
      // tetrahedron's field, whichever layer the corner also touches.
      const double expected = interface ? 0.0 : fieldZ(centroidZ(mesh, f));
      EXPECT_NEAR(cornerValue(mesh, e, f, c, 2), expected, 1e-6) << "face " << f << " corner " << c;
      EXPECT_NEAR(cornerValue(mesh, e, f, c, 0), 0.0, 1e-6);
      jumps += !interface && std::abs(p.z - 0.5) < 1e-9;
    }
  }
  EXPECT_GT(jumps, 8u);  // side-face corners on the interface's edges: -1.5 below, -0.5 above
}

TEST(PosVolumeSkin, TheInterfacesTrianglesWinWhereverTheViewListsThem) {
  test::ScratchFolder scratch;
  scratch.write("last.pos", rewrittenView([](const std::string&) { return true; }, "VT("));
  const Mesh mesh = layersWith({scratch.file("last.pos")});
  const MeshField& e = fieldNamed(mesh, "e");
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const double expected = mesh.volumeSides.isInterface(f) ? 0.0 : fieldZ(centroidZ(mesh, f));
    interfaces += mesh.volumeSides.isInterface(f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(cornerValue(mesh, e, f, c, 2), expected, 1e-6) << "face " << f;
  }
  EXPECT_EQ(interfaces, 4u);
}

TEST(PosVolumeSkin, AnInterfaceNoTriangleCoversShowsItsInnerVolume) {
  // The view on the tetrahedra only, in GetDP's order and reversed: an interface face shows the
  // tetrahedron behind it, of the volume its facePhysicalTag names (lower: 1, upper: 2), as element
  // data in a .msh does, whichever the view lists first.
  for (const bool reversed : {false, true}) {
    test::ScratchFolder scratch;
    scratch.write(
        "volumes.pos",
        rewrittenView([](const std::string& line) { return !line.starts_with("VT("); }, "", reversed));
    const Mesh mesh = layersWith({scratch.file("volumes.pos")});
    const MeshField& e = fieldNamed(mesh, "e");
    std::size_t interfaces = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      if (!mesh.volumeSides.isInterface(f)) continue;
      ++interfaces;
      ASSERT_TRUE(mesh.facePhysicalTag[f] == 1 || mesh.facePhysicalTag[f] == 2);
      const double expected = mesh.facePhysicalTag[f] == 1 ? -1.5 : -0.5;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(cornerValue(mesh, e, f, c, 2), expected, 1e-6)
            << "face " << f << " reversed " << reversed;
    }
    EXPECT_EQ(interfaces, 4u);
  }
}

TEST(PosVolumeSkin, AViewFileAloneColoursTheSkinUnderAnotherViewsTriangle) {
  // A .pos drawn on its own elements: v on the tetrahedra, and a view "mark" on one triangle of the
  // top (z = 1), which becomes that skin face; v shows there the values of the tetrahedron under it.
  std::ifstream in(layersFile("v.pos"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += "View \"mark\" {\nST(0,0,1,1,0,1,0.5,0.5,1){7,7,7};\n};\n";
  test::ScratchFolder scratch;
  scratch.write("both.pos", text);
  const Mesh mesh = readMsh(scratch.file("both.pos"));
  const MeshField& v = fieldNamed(mesh, "v");
  const MeshField& mark = fieldNamed(mesh, "mark");
  std::size_t marked = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    marked += !std::isnan(cornerValue(mesh, mark, f, 0));
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(cornerValue(mesh, v, f, c), potential(mesh.worldPosition(mesh.faces[f].vertex[c]).z), 1e-6)
          << "face " << f << " corner " << c;
  }
  EXPECT_EQ(marked, 1u);
}

}  // namespace
}  // namespace lancer
