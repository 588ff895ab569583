// STL, OBJ and PLY read through the mesh door (mesh_file.hpp): gmsh's STL writer (one solid per
// physical surface, and binary), meshio's OBJ and PLY writers, and hand-written files for what those
// do not write (OBJ groups, corner forms, negative indices and polygons; PLY lists of other types,
// other elements, big-endian data). Oracles: a closed triangulated sphere-like surface has
// V = F / 2 + 2 points once STL's repeated corners are welded (Euler), and the PLY's temperature is
// gmsh's $NodeData it was written from.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "lancer/mesh/mesh_file.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

Mesh fromText(const std::string& text, const std::string& name) {
  return readMeshFromMemory(std::span<const char>(text.data(), text.size()), name);
}

std::string surfaceFile(const std::string& name) { return test::dataFile("surface/" + name); }

std::size_t quadCount(const Mesh& mesh) {
  std::size_t quads = 0;
  for (const MeshFace& face : mesh.faces) quads += face.isQuad();
  return quads;
}

std::size_t facesInGroup(const Mesh& mesh, const std::string& name) {
  for (const PhysicalGroup& group : mesh.physicalGroups) {
    if (group.name != name) continue;
    std::size_t count = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) count += mesh.facePhysicalTag[f] == group.tag;
    return count;
  }
  return 0;
}

const MeshField* fieldNamed(const Mesh& mesh, const std::string& name) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name) return &field;
  return nullptr;
}

TEST(StlReader, GmshAsciiStlHasAGroupPerSolidAndWeldedCorners) {
  const Mesh mesh = readMeshFile(surfaceFile("box_groups.stl"));
  EXPECT_EQ(mesh.source.format, "stl");
  EXPECT_FALSE(mesh.source.binary);
  ASSERT_EQ(mesh.physicalGroups.size(), 2u);
  EXPECT_GT(facesInGroup(mesh, "bottom"), 0u);
  EXPECT_EQ(facesInGroup(mesh, "bottom") + facesInGroup(mesh, "walls"), mesh.faceCount());
  // One closed surface: the groups share the points along their seam.
  EXPECT_EQ(mesh.positions.size(), mesh.faceCount() / 2 + 2);
}

TEST(StlReader, GmshBinaryStlIsTheSameSurfaceAsItsAscii) {
  // gmsh writes a binary block per physical surface, the surface's name in its header.
  const Mesh ascii = readMeshFile(surfaceFile("box_groups.stl"));
  const Mesh binary = readMeshFile(surfaceFile("box_binary.stl"));
  EXPECT_TRUE(binary.source.binary);
  EXPECT_EQ(binary.faceCount(), ascii.faceCount());
  EXPECT_EQ(binary.positions.size(), ascii.positions.size());
  EXPECT_EQ(facesInGroup(binary, "bottom"), facesInGroup(ascii, "bottom"));
  EXPECT_EQ(facesInGroup(binary, "walls"), facesInGroup(ascii, "walls"));
}

TEST(StlReader, OneBinaryBlockIsOneUnnamedGroup) {
  const Mesh mesh = readMeshFile(test::dataFile("reader/sphere_binary.stl"));  // gmsh's, one surface
  EXPECT_TRUE(mesh.source.binary);
  ASSERT_EQ(mesh.physicalGroups.size(), 1u);
  EXPECT_EQ(mesh.physicalGroups[0].name, "");
  EXPECT_EQ(mesh.positions.size(), mesh.faceCount() / 2 + 2);
}

// Some exporters start a binary STL's header with "solid": its size tells it apart.
std::string binaryStl(const std::string& header, const std::vector<std::array<float, 9>>& triangles) {
  std::string bytes = header;
  bytes.resize(80, '\0');
  const auto count = static_cast<std::uint32_t>(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& corners : triangles) {
    const float normal[3] = {0, 0, 1};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    bytes.append(reinterpret_cast<const char*>(corners.data()), 36);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(StlReader, ABinaryStlWhoseHeaderSaysSolidIsReadAsBinary) {
  const std::string bytes = binaryStl("solid part exported as binary", {{0, 0, 0, 1, 0, 0, 0, 1, 0}});
  const Mesh mesh = fromText(bytes, "part.stl");
  EXPECT_TRUE(mesh.source.binary);
  EXPECT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(StlReader, KeywordsInAnyCaseLoopsOfFourAndSignedZeros) {
  const Mesh mesh = fromText(
      "SOLID plate\n FACET NORMAL 0 0 1\n  OUTER LOOP\n   VERTEX 0 0 0\n   VERTEX 1 0 0\n   VERTEX 1 1 0\n"
      "   VERTEX 0 1 0\n  ENDLOOP\n ENDFACET\n facet normal 0 0 1\n  outer loop\n   vertex -0 0 0\n"
      "   vertex 0 1 0\n   vertex -1 0 0\n  endloop\n endfacet\nENDSOLID plate\n",
      "plate.txt");
  EXPECT_EQ(mesh.faceCount(), 3u);  // the loop of four as two triangles
  EXPECT_EQ(mesh.positions.size(), 5u);
  ASSERT_EQ(mesh.physicalGroups.size(), 1u);
  EXPECT_EQ(mesh.physicalGroups[0].name, "plate");
}

TEST(ObjReader, GroupsCornerFormsNegativeIndicesAndPolygons) {
  const Mesh mesh = readMeshFile(surfaceFile("groups.obj"));
  EXPECT_EQ(mesh.source.format, "obj");
  EXPECT_EQ(mesh.positions.size(), 9u);
  EXPECT_EQ(facesInGroup(mesh, "base"), 2u);  // the quad, kept, and the triangle of the second `g base`
  EXPECT_EQ(facesInGroup(mesh, "roof"), 3u);  // the pentagon as a fan
  EXPECT_EQ(quadCount(mesh), 1u);
}

TEST(ObjReader, MeshioObjIsAClosedSurface) {
  const Mesh mesh = readMeshFile(surfaceFile("box.obj"));
  EXPECT_EQ(mesh.faceCount(), readMeshFile(surfaceFile("box_binary.stl")).faceCount());
  EXPECT_EQ(mesh.positions.size(), mesh.faceCount() / 2 + 2);
}

TEST(ObjReader, IsRecognisedByContentUnderAnyName) {
  const Mesh mesh = fromText("# scan\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "scan.txt");
  EXPECT_EQ(mesh.source.format, "obj");
  EXPECT_EQ(mesh.faceCount(), 1u);
}

TEST(PlyReader, MeshioAsciiAndBinaryCarryGmshsTemperature) {
  const Mesh reference = readMeshFile(test::dataFile("fields/node_xy_v22_ascii.msh"));
  const MeshField* expected = fieldNamed(reference, "temperature");
  ASSERT_NE(expected, nullptr);
  for (const char* file : {"plate_temperature.ply", "plate_temperature_bin.ply"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMeshFile(surfaceFile(file));
    EXPECT_EQ(mesh.source.format, "ply");
    EXPECT_EQ(mesh.faceCount(), reference.faceCount());
    const MeshField* field = fieldNamed(mesh, "temperature");
    ASSERT_NE(field, nullptr);
    EXPECT_EQ(field->at, FieldAt::kNode);
    EXPECT_EQ(field->range(), expected->range());
    // The value at each point is gmsh's at the same place.
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const Vec3d p = mesh.worldPosition(static_cast<std::uint32_t>(v));
      for (std::size_t w = 0; w < reference.positions.size(); ++w) {
        const Vec3d q = reference.worldPosition(static_cast<std::uint32_t>(w));
        if (std::abs(p.x - q.x) + std::abs(p.y - q.y) + std::abs(p.z - q.z) < 1e-9) {
          EXPECT_FLOAT_EQ(field->values[v], expected->values[w]) << "at point " << v;
        }
      }
    }
  }
}

TEST(PlyReader, ListsOfAnyTypesOtherElementsAndIntegerProperties) {
  const Mesh mesh = readMeshFile(surfaceFile("polygons.ply"));
  EXPECT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.faceCount(), 2u);
  EXPECT_EQ(quadCount(mesh), 1u);
  const MeshField* quality = fieldNamed(mesh, "quality");
  ASSERT_NE(quality, nullptr);
  EXPECT_EQ(quality->range(), (std::pair<float, float>{10, 50}));
  EXPECT_EQ(fieldNamed(mesh, "texcoord"), nullptr);  // a list: not a field
}

// A big-endian file: the bytes of each value reversed.
template <typename T>
void appendBigEndian(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  for (std::size_t i = sizeof(T); i-- > 0;) bytes.push_back(raw[i]);
}

TEST(PlyReader, BigEndianDataIsTheSameAsAscii) {
  const std::string header =
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nproperty short level\n"
      "element face 1\nproperty list ushort int vertex_indices\nend_header\n";
  std::string big = "ply\nformat binary_big_endian 1.0\n" + header;
  const double xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  for (int v = 0; v < 3; ++v) {
    for (const double c : xyz[v]) appendBigEndian(big, c);
    appendBigEndian(big, static_cast<std::int16_t>(-300 + v));
  }
  appendBigEndian(big, std::uint16_t{3});
  for (const std::int32_t i : {0, 1, 2}) appendBigEndian(big, i);
  const Mesh binary = fromText(big, "big.ply");
  const Mesh ascii =
      fromText("ply\nformat ascii 1.0\n" + header + "0 0 0 -300\n1 0 0 -299\n0 2 0 -298\n3 0 1 2\n", "a.ply");
  EXPECT_TRUE(binary.source.binary);
  ASSERT_EQ(binary.faceCount(), 1u);
  EXPECT_EQ(binary.positions, ascii.positions);
  ASSERT_NE(fieldNamed(binary, "level"), nullptr);
  EXPECT_EQ(fieldNamed(binary, "level")->values, fieldNamed(ascii, "level")->values);
  EXPECT_EQ(fieldNamed(binary, "level")->range(), (std::pair<float, float>{-300, -298}));
}

TEST(PlyReader, FacesOfFewerThanThreeVerticesAreLeftOutWithAWarning) {
  const Mesh mesh = fromText(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 3\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 0\n"
      "2 0 1\n3 0 1 2\n",
      "mixed.ply");
  EXPECT_EQ(mesh.faceCount(), 1u);
  ASSERT_EQ(mesh.source.warnings.size(), 1u);
  EXPECT_EQ(mesh.source.warnings[0],
            "mixed.ply:7: warning: 2 of the 3 faces have fewer than 3 vertices (points or edges): left out");
}

TEST(MeshDoor, SurfacesAreMeshFilesForTheCommandLine) {
  for (const char* file : {"box_groups.stl", "box_binary.stl", "groups.obj", "polygons.ply"})
    EXPECT_TRUE(isMeshFile(surfaceFile(file))) << file;
  EXPECT_TRUE(isMeshFile(surfaceFile("box.geo")));  // answered with gmsh's command
  test::ScratchFolder folder;
  folder.write("scene.txt", "[render]\nwidth = 64\n\n[[mesh]]\nfile = \"part.stl\"\n");
  EXPECT_FALSE(isMeshFile(folder.file("scene.txt")));
}

}  // namespace
}  // namespace lancer
