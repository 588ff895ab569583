// Views given on volume elements only (GetDP's -v2 output, gmsh's saved views) on a skin that
// surface elements cover: each skin face is its surface element, and takes the values of the volume
// element under it where the surface element has no record of its own. capacitor.msh (MSH 2.2,
// GetDP's $ElementNodeData on the tetrahedra; plates and box as Physical Surfaces), cube_hex.msh
// (MSH 4.1, $ElementData on the hexahedra, the skin as quads), and interfaces between two volumes,
// where a surface element's own record wins over the volume elements' (layers.msh).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

const MeshField& fieldNamed(const Mesh& mesh, const std::string& name) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name) return field;
  ADD_FAILURE() << "no field " << name << " in " << mesh.source.path;
  return mesh.fields.front();
}

float cornerValue(const MeshField& field, const Mesh& mesh, std::size_t f, int c) {
  const auto slot = static_cast<std::size_t>(cornerSlot(mesh.faces[f], c));
  return field.values[(f * kCornerSlots + slot) * static_cast<std::size_t>(field.components)];
}

Vec3d cornerPoint(const Mesh& mesh, std::size_t f, int c) {
  const Vec3& p = mesh.positions[mesh.faces[f].vertex[c]];
  return mesh.origin + Vec3d{p.x, p.y, p.z};
}

// What an MSH 2.2 text file says, parsed here on its own: nodes, elements, and one
// $ElementNodeData view's records.
struct Msh22Text {
  std::map<std::uint64_t, Vec3d> nodes;
  struct Element {
    int type = 0;
    int physical = 0;
    std::vector<std::uint64_t> nodes;
  };
  std::map<std::uint64_t, Element> elements;
};

std::istringstream sectionOf(const std::string& text, const std::string& name) {
  const std::size_t begin = text.find("$" + name + "\n");
  const std::size_t end = text.find("$End" + name, begin);
  EXPECT_NE(begin, std::string::npos) << name;
  return std::istringstream(text.substr(begin + name.size() + 2, end - begin - name.size() - 2));
}

Msh22Text parseMsh22(const std::string& text) {
  Msh22Text msh;
  std::istringstream nodes = sectionOf(text, "Nodes");
  std::size_t count = 0;
  nodes >> count;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t tag = 0;
    Vec3d p;
    nodes >> tag >> p.x >> p.y >> p.z;
    msh.nodes[tag] = p;
  }
  std::istringstream elements = sectionOf(text, "Elements");
  elements >> count;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t tag = 0;
    int type = 0, tags = 0;
    elements >> tag >> type >> tags;
    Msh22Text::Element& element = msh.elements[tag];
    element.type = type;
    for (int t = 0; t < tags; ++t) {
      int value = 0;
      elements >> value;
      if (t == 0) element.physical = value;
    }
    const int nodeCount = type == 2 ? 3 : type == 4 ? 4 : 0;
    EXPECT_NE(nodeCount, 0) << "element type " << type;
    element.nodes.resize(static_cast<std::size_t>(nodeCount));
    for (std::uint64_t& node : element.nodes) elements >> node;
  }
  return msh;
}

// The node tag at point p (brute force: these meshes have a few thousand nodes).
std::uint64_t nodeAt(const Msh22Text& msh, const Vec3d& p) {
  std::uint64_t best = 0;
  double bestDistance = std::numeric_limits<double>::max();
  for (const auto& [tag, q] : msh.nodes) {
    const double distance = length(q - p);
    if (distance < bestDistance) best = tag, bestDistance = distance;
  }
  EXPECT_LT(bestDistance, 1e-5);
  return best;
}

// An $ElementData section (MSH 2.2 text) with one value per listed element.
std::string elementDataSection(const std::string& name, const std::map<std::uint64_t, double>& values) {
  std::ostringstream out;
  out << "$ElementData\n1\n\"" << name << "\"\n1\n0\n3\n0\n1\n" << values.size() << "\n";
  for (const auto& [tag, value] : values) out << tag << " " << value << "\n";
  out << "$EndElementData\n";
  return out.str();
}

// GetDP's v at every skin face corner is v at that node as the tetrahedra's records give it (v is
// continuous: every tetrahedron around a node agrees); the plates are at +1 and -1, the box at 0.
TEST(SkinElementData, CapacitorSkinCornersHoldTheTetrahedraValues) {
  const std::string path = test::dataFile("volume/capacitor.msh");
  const std::string text = test::readText(path);
  const Msh22Text msh = parseMsh22(text);
  std::istringstream records = sectionOf(text, "ElementNodeData");
  // String tags (the name, one word here), real tags, then integer tags: step, components, count, ...
  int tagCount = 0;
  std::string name;
  double real = 0;
  records >> tagCount >> name >> tagCount >> real >> tagCount;
  ASSERT_EQ(name, "\"v\"");
  std::vector<std::size_t> integers(static_cast<std::size_t>(tagCount));
  for (std::size_t& integer : integers) records >> integer;
  const std::size_t count = integers.at(2);
  ASSERT_GT(count, 1000u);
  std::map<std::uint64_t, double> vAtNode;
  for (std::size_t r = 0; r < count; ++r) {
    std::uint64_t tag = 0;
    int nodes = 0;
    records >> tag >> nodes;
    const Msh22Text::Element& element = msh.elements.at(tag);
    ASSERT_EQ(element.type, 4);
    for (int n = 0; n < nodes; ++n) {
      double v = 0;
      records >> v;
      const auto [at, fresh] = vAtNode.emplace(element.nodes[static_cast<std::size_t>(n)], v);
      if (!fresh) {
        ASSERT_NEAR(at->second, v, 1e-9) << "node " << at->first;
      }
    }
  }

  const Mesh mesh = readMsh(path);
  EXPECT_EQ(mesh.source.skinFacesCoveredBySurfaces, mesh.faceCount());
  const MeshField& v = fieldNamed(mesh, "v");
  ASSERT_EQ(v.at, FieldAt::kCorner);
  const std::map<std::int32_t, double> potential{{11, 1.0}, {12, -1.0}, {13, 0.0}};
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    for (int c = 0; c < mesh.faces[f].cornerCount(); ++c) {
      const float value = cornerValue(v, mesh, f, c);
      EXPECT_NEAR(value, vAtNode.at(nodeAt(msh, cornerPoint(mesh, f, c))), 1e-6) << "face " << f;
      EXPECT_NEAR(value, potential.at(mesh.facePhysicalTag[f]), 1e-6) << "face " << f;
    }
  EXPECT_NEAR(v.range().first, -1.0, 1e-6);
  EXPECT_NEAR(v.range().second, 1.0, 1e-6);
}

// cube_hex's g is f = x + 2y + 3z at each hexahedron's centroid: a skin quad shows the one inside
// it, half a hexahedron (1/12) in from the face's centre.
TEST(SkinElementData, CubeHexSkinFacesHoldTheHexahedronUnderThem) {
  const Mesh mesh = readMsh(test::dataFile("volume/cube_hex.msh"));
  EXPECT_EQ(mesh.source.skinFacesCoveredBySurfaces, mesh.faceCount());
  const MeshField& g = fieldNamed(mesh, "g");
  ASSERT_EQ(g.at, FieldAt::kElement);
  constexpr double kHalf = 1.0 / 12.0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    ASSERT_TRUE(mesh.faces[f].isQuad());
    Vec3d centroid{};
    for (int c = 0; c < 4; ++c) centroid += cornerPoint(mesh, f, c) * 0.25;
    for (double* x : {&centroid.x, &centroid.y, &centroid.z}) {
      if (*x < 1e-6) *x = kHalf;
      if (*x > 1 - 1e-6) *x = 1 - kHalf;
    }
    EXPECT_NEAR(g.values[f], centroid.x + 2 * centroid.y + 3 * centroid.z, 1e-5) << "face " << f;
  }
}

// A view with records for the surface elements of one group and for the volume elements: that
// group's faces show the surface elements' own values, the rest the volume elements'.
TEST(SkinElementData, TheSurfaceElementsOwnRecordWins) {
  const std::string path = test::dataFile("volume/capacitor.msh");
  std::string text = test::readText(path);
  const Msh22Text msh = parseMsh22(text);
  std::map<std::uint64_t, double> w;
  for (const auto& [tag, element] : msh.elements)
    if (element.type == 4 || element.physical == 11) w[tag] = element.type == 4 ? 3.0 : 7.0;
  text += elementDataSection("w", w);
  const Mesh mesh = readMshFromMemory(text, path);
  const MeshField& field = fieldNamed(mesh, "w");
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    EXPECT_EQ(field.values[f], mesh.facePhysicalTag[f] == 11 ? 7.0f : 3.0f) << "face " << f;
}

// Element data on two volumes meshed together (a ball in a cube), each element's value its volume's
// physical tag: an interface face shows its inner volume's value (the volume its facePhysicalTag
// names, the one it is wound out of), not the outer one's; a skin face the cube's.
TEST(SkinElementData, InterfacesTakeTheirInnerVolumesValues) {
  const std::string path = test::dataFile("multimaterial/cube_sphere_v22.msh");
  std::string text = test::readText(path);
  const Msh22Text msh = parseMsh22(text);
  std::map<std::uint64_t, double> volume;
  for (const auto& [tag, element] : msh.elements) volume[tag] = element.physical;
  text += elementDataSection("volume", volume);
  const Mesh mesh = readMshFromMemory(text, path);
  ASSERT_FALSE(mesh.volumeSides.empty());
  const MeshField& field = fieldNamed(mesh, "volume");
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    EXPECT_EQ(field.values[f], static_cast<float>(mesh.facePhysicalTag[f])) << "face " << f;
    if (!mesh.volumeSides.isInterface(f)) continue;
    ++interfaces;
    EXPECT_NE(mesh.volumeSides.outerPhysicalTag[f], mesh.facePhysicalTag[f]) << "face " << f;
  }
  EXPECT_EQ(interfaces, 1002u);
}

// An $ElementNodeData section (MSH 2.2 text) of one scalar: per listed element, its value at each node.
std::string elementNodeDataSection(const std::string& name,
                                   const std::map<std::uint64_t, std::vector<double>>& values) {
  std::ostringstream out;
  out << "$ElementNodeData\n1\n\"" << name << "\"\n1\n0\n3\n0\n1\n" << values.size() << "\n";
  for (const auto& [tag, nodes] : values) {
    out << tag << " " << nodes.size();
    for (const double value : nodes) out << " " << value;
    out << "\n";
  }
  out << "$EndElementNodeData\n";
  return out.str();
}

// layers.msh (GetDP's two dielectric layers, tests/data/pos/layers): two physical volumes (1 and 2)
// meeting at the interface's triangles (physical surface 13), top and bottom as physical surfaces.
// Element data on every tetrahedron (its volume's tag) and on the interface's triangles (13): the
// interface faces show the triangles' own values, every other face its tetrahedron's.
TEST(SkinElementData, AnInterfacesSurfaceElementKeepsItsOwnRecord) {
  const std::string path = test::dataFile("pos/layers/layers.msh");
  std::string text = test::readText(path);
  const Msh22Text msh = parseMsh22(text);
  std::map<std::uint64_t, double> perElement;
  std::map<std::uint64_t, std::vector<double>> perNode;
  for (const auto& [tag, element] : msh.elements) {
    if (element.type == 4) {
      perElement[tag] = element.physical;
      perNode[tag].assign(4, element.physical);
    } else if (element.physical == 13) {
      perElement[tag] = 13;
      // The triangle's value at its node j is 13 + j: a corner shows where it is in the record.
      perNode[tag] = {13, 14, 15};
    }
  }
  text += elementDataSection("w", perElement) + elementNodeDataSection("n", perNode);
  const Mesh mesh = readMshFromMemory(text, path);
  EXPECT_EQ(mesh.source.interfaceSurfaceElementsMerged, 4u);
  const MeshField& w = fieldNamed(mesh, "w");
  const MeshField& n = fieldNamed(mesh, "n");
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    // Which volume a face is on: the interface at z = 0.5, the lower volume below, the upper above.
    double z = 0;
    for (int c = 0; c < 3; ++c) z += cornerPoint(mesh, f, c).z / 3;
    if (mesh.volumeSides.isInterface(f)) {
      ++interfaces;
      EXPECT_EQ(w.values[f], 13.0f) << "face " << f;
      std::vector<std::uint64_t> corners;
      for (int c = 0; c < 3; ++c) corners.push_back(nodeAt(msh, cornerPoint(mesh, f, c)));
      const auto triangle = std::find_if(msh.elements.begin(), msh.elements.end(), [&](const auto& entry) {
        return entry.second.type == 2 &&
               std::is_permutation(corners.begin(), corners.end(), entry.second.nodes.begin());
      });
      ASSERT_NE(triangle, msh.elements.end()) << "face " << f;
      EXPECT_EQ(triangle->second.physical, 13);
      for (int c = 0; c < 3; ++c) {
        const std::vector<std::uint64_t>& nodes = triangle->second.nodes;
        const auto j =
            std::find(nodes.begin(), nodes.end(), corners[static_cast<std::size_t>(c)]) - nodes.begin();
        EXPECT_EQ(cornerValue(n, mesh, f, c), static_cast<float>(13 + j)) << "face " << f << " corner " << c;
      }
    } else {
      const float volume = z < 0.5 ? 1.0f : 2.0f;
      EXPECT_EQ(w.values[f], volume) << "face " << f;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(cornerValue(n, mesh, f, c), volume) << "face " << f;
    }
  }
  EXPECT_EQ(interfaces, 4u);
}

// The same records less the triangles': the interface faces fall back on their inner volume's
// tetrahedra (the volume facePhysicalTag names), as faces with no surface element do.
TEST(SkinElementData, AnInterfaceWithoutRecordsOfItsOwnShowsItsInnerVolume) {
  const std::string path = test::dataFile("pos/layers/layers.msh");
  std::string text = test::readText(path);
  const Msh22Text msh = parseMsh22(text);
  std::map<std::uint64_t, double> perElement;
  std::map<std::uint64_t, std::vector<double>> perNode;
  for (const auto& [tag, element] : msh.elements)
    if (element.type == 4) perElement[tag] = element.physical, perNode[tag].assign(4, element.physical);
  text += elementDataSection("w", perElement) + elementNodeDataSection("n", perNode);
  const Mesh mesh = readMshFromMemory(text, path);
  const MeshField& w = fieldNamed(mesh, "w");
  const MeshField& n = fieldNamed(mesh, "n");
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!mesh.volumeSides.isInterface(f)) continue;
    ++interfaces;
    EXPECT_EQ(w.values[f], static_cast<float>(mesh.facePhysicalTag[f])) << "face " << f;
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(cornerValue(n, mesh, f, c), static_cast<float>(mesh.facePhysicalTag[f])) << "face " << f;
  }
  EXPECT_EQ(interfaces, 4u);
}

}  // namespace
}  // namespace lancer
