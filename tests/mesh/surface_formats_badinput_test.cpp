// Broken STL, OBJ and PLY files: each refused with one line at the file's line and column (or byte
// offset in binary data) that says what is wrong, and counts checked against the file's size before
// anything is allocated.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string errorOf(const std::string& bytes, const std::string& name) {
  return test::messageOf(
      [&] { readMeshFromMemory(std::span<const char>(bytes.data(), bytes.size()), name); });
}

std::string fixture(const std::string& name) { return test::readText(test::dataFile("surface/" + name)); }

constexpr const char* kFacetStart = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";

TEST(StlBadInput, TruncatedBinaryStl) {
  const std::string bytes = fixture("box_binary.stl");
  EXPECT_EQ(
      errorOf(bytes.substr(0, bytes.size() - 10), "part.stl"),
      "part.stl:@1464: error: the binary STL header declares 130 triangles (6584 bytes with the header), "
      "but 6574 bytes remain in the file (truncated, or not an STL: an ASCII STL starts with 'solid')");
}

TEST(StlBadInput, AbsurdTriangleCountIsRefusedBeforeAllocating) {
  std::string bytes = fixture("box_binary.stl").substr(0, 134);
  bytes[80] = bytes[81] = bytes[82] = bytes[83] = '\xff';
  EXPECT_EQ(
      errorOf(bytes, "part.stl"),
      "part.stl:@80: error: the binary STL header declares 4294967295 triangles (214748364834 bytes with "
      "the header), but 134 bytes remain in the file (truncated, or not an STL: an ASCII STL starts with "
      "'solid')");
}

TEST(StlBadInput, ShorterThanTheHeader) {
  EXPECT_EQ(errorOf("\x01\x02\x03", "part.stl"),
            "part.stl: error: a binary STL starts with an 84-byte header, but the file has 3 bytes (it is "
            "truncated, or not an STL: an ASCII STL starts with 'solid')");
}

TEST(StlBadInput, AsciiStlWithABadNumber) {
  EXPECT_EQ(errorOf(std::string(kFacetStart) + "vertex 1 x 0\n", "part.stl"),
            "part.stl:5:10: error: expected the y coordinate of a vertex (a number), found 'x'");
  EXPECT_EQ(errorOf(std::string(kFacetStart) + "vertex 1 0 nan\n", "part.stl"),
            "part.stl:5:12: error: the z coordinate of a vertex is 'nan': expected a finite number");
  EXPECT_EQ(
      errorOf(std::string(kFacetStart) + "vertex 1 0\n", "part.stl"),
      "part.stl:5:11: error: expected the z coordinate of a vertex (a number), found the end of the line");
}

TEST(StlBadInput, TruncatedAsciiStl) {
  EXPECT_EQ(errorOf(std::string(kFacetStart) + "vertex 1 0 0\n", "part.stl"),
            "part.stl:5: error: the file ends inside a facet (it looks truncated)");
  EXPECT_EQ(errorOf("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                    "endloop\nendfacet\n",
                    "part.stl"),
            "part.stl:8: error: the file ends before 'endsolid' (it looks truncated)");
}

TEST(StlBadInput, FacetsOfTooFewVerticesAndStrayWords) {
  EXPECT_EQ(errorOf(std::string(kFacetStart) + "endloop\nendfacet\nendsolid\n", "part.stl"),
            "part.stl:6:1: error: a facet with 1 vertices: a facet needs at least 3");
  EXPECT_EQ(
      errorOf("solid a\nfacet normal 0 0 1\nvortex 0 0 0\n", "part.stl"),
      "part.stl:3:1: error: expected an STL keyword (solid, facet, outer loop, vertex, endloop, endfacet, "
      "endsolid), found 'vortex'");
}

constexpr const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjBadInput, IndexZero) {
  EXPECT_EQ(
      errorOf(std::string(kSquare) + "f 1 2 0\n", "part.obj"),
      "part.obj:5:7: error: vertex index 0: OBJ numbers vertices from 1 (or from -1 back from the last)");
}

TEST(ObjBadInput, IndexOutOfRange) {
  EXPECT_EQ(errorOf(std::string(kSquare) + "f 1 2 3\nf 1/1 9/2/3 3\n", "part.obj"),
            "part.obj:6:7: error: vertex index 9 is out of range: the file defines 4 vertices");
  EXPECT_EQ(errorOf(std::string(kSquare) + "f 1 2 99999999999999999999\n", "part.obj"),
            "part.obj:5:7: error: vertex index '99999999999999999999' is out of range");
}

TEST(ObjBadInput, NegativeIndexPastTheStart) {
  EXPECT_EQ(errorOf(std::string(kSquare) + "f -1 -2 -5\n", "part.obj"),
            "part.obj:5:9: error: vertex index -5 counts back past the first vertex: 4 are defined before "
            "this line");
}

TEST(ObjBadInput, MalformedCornersFacesAndStatements) {
  EXPECT_EQ(
      errorOf(std::string(kSquare) + "f 1 2 a/1\n", "part.obj"),
      "part.obj:5:7: error: expected a face corner (v, v/vt, v//vn or v/vt/vn, v an integer), found 'a/1'");
  EXPECT_EQ(errorOf(std::string(kSquare) + "f 1 2\n", "part.obj"),
            "part.obj:5: error: a face with 2 vertices: a face needs at least 3");
  EXPECT_EQ(
      errorOf(std::string(kSquare) + "f 1 2 3\nbox 1 2\n", "part.obj"),
      "part.obj:6:1: error: 'box' is not an OBJ statement (v, f, g, o, and those lancer ignores: vt, vn, "
      "usemtl, ...)");
  EXPECT_EQ(errorOf("v 0 0 0\nv 1 0 1e999\n", "part.obj"),
            "part.obj:2:7: error: the z coordinate of a vertex '1e999' is out of range");
}

std::string plyHeader(const std::string& format, const std::string& counts = "3 1") {
  const std::string vertices = counts.substr(0, counts.find(' '));
  const std::string faces = counts.substr(counts.find(' ') + 1);
  return "ply\nformat " + format + " 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(PlyBadInput, UnknownPropertyType) {
  EXPECT_EQ(
      errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty half y\nend_header\n",
              "part.ply"),
      "part.ply:5:10: error: unknown property type 'half': PLY's types are char, uchar, short, ushort, "
      "int, uint, float, double (or int8, uint8, int16, uint16, int32, uint32, float32, float64)");
  EXPECT_EQ(
      errorOf("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int128 vertex_indices\n"
              "end_header\n",
              "part.ply"),
      "part.ply:4:21: error: unknown property type 'int128': PLY's types are char, uchar, short, ushort, "
      "int, uint, float, double (or int8, uint8, int16, uint16, int32, uint32, float32, float64)");
}

TEST(PlyBadInput, HeaderWithoutEndHeader) {
  EXPECT_EQ(
      errorOf("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "part.ply"),
      "part.ply:4: error: the PLY header has no end_header line (the file is truncated or not a PLY file)");
}

TEST(PlyBadInput, MoreEntriesDeclaredThanTheDataHolds) {
  EXPECT_EQ(errorOf(plyHeader("ascii") + "0.0 0.0 0.0\n1.0 0.0 0.0\n", "part.ply"),
            "part.ply:11: error: the file ends after 2 of the 3 vertex entries the header declares (it looks "
            "truncated)");
  std::string binary = plyHeader("binary_little_endian");
  binary.append(3 * 12, '\0');
  binary += "\x03";
  binary.append(8, '\0');  // two of the three indices
  EXPECT_EQ(errorOf(binary, "part.ply"),
            "part.ply:@" + std::to_string(binary.size()) +
                ": error: the file ends inside face entry 1 of 1 (it looks truncated)");
}

TEST(PlyBadInput, AbsurdCountsAreRefusedBeforeAllocating) {
  EXPECT_EQ(
      errorOf(plyHeader("binary_little_endian", "4000000000 1") + "data", "part.ply"),
      "part.ply:@" + std::to_string(plyHeader("binary_little_endian", "4000000000 1").size()) +
          ": error: element vertex (header line 3) declares 4000000000 entries of at least 12 bytes each, "
          "but only 4 bytes remain in the file (truncated file or a corrupt count)");
  EXPECT_EQ(
      errorOf(plyHeader("ascii", "3 9000000000") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "part.ply"),
      "part.ply:7: error: element face declares 9000000000 entries of at least 2 bytes each, but only 26 "
      "bytes remain in the file (truncated file or a corrupt count)");
}

TEST(PlyBadInput, IndicesAndShapesTheReaderCannotUse) {
  EXPECT_EQ(errorOf(plyHeader("ascii") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "part.ply"),
            "part.ply:13:7: error: face 0 uses vertex 3, but the file has 3 vertices (numbered from 0)");
  EXPECT_EQ(errorOf(plyHeader("ascii") + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "part.ply"),
            "part.ply:13:5: error: face 0 uses vertex -1, but the file has 3 vertices (numbered from 0)");
  EXPECT_EQ(errorOf(plyHeader("ascii") + "0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n", "part.ply"),
            "part.ply:10:7: error: '7' after the values of a vertex entry: the header declares 3 properties");
  EXPECT_EQ(
      errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n"
              "0 0\n",
              "part.ply"),
      "part.ply:3: error: the vertex element has no scalar property z: a PLY vertex needs x, y and z");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement face 0\nend_header\n", "part.ply"),
            "part.ply: error: the PLY header declares no vertex element");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 0\nproperty list uchar int corners\nend_header\n",
                    "part.ply"),
            "part.ply:7: error: the face element has no vertex_indices (or vertex_index) list of integers");
  EXPECT_EQ(errorOf("ply\nformat binary_middle_endian 1.0\nend_header\n", "part.ply"),
            "part.ply:2:8: error: unknown PLY format 'binary_middle_endian': expected ascii, "
            "binary_little_endian or binary_big_endian");
}

TEST(SurfaceBadInput, PointsWithoutFacesHaveNothingToDraw) {
  const std::string cloud =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 1 1\n";
  EXPECT_EQ(
      nothingToDrawReason(readMeshFromMemory(std::span<const char>(cloud.data(), cloud.size()), "scan.ply")),
      "it holds no faces (2 points and no face element entries): lancer draws surfaces");
  const std::string points = "v 0 0 0\nv 1 0 0\n";
  EXPECT_EQ(
      nothingToDrawReason(readMeshFromMemory(std::span<const char>(points.data(), points.size()), "p.obj")),
      "it holds no faces (2 points and no f line): lancer draws surfaces");
}

}  // namespace
}  // namespace lancer
