// Files that are not gmsh meshes are recognised by content first, then by extension. The gmsh-made
// ones (STL, STEP, BREP, VTK, .geo) are also run through the CLI in the bad-input catalogue;
// here: formats gmsh cannot write here (IGES, OBJ) as short samples, content under a wrong name,
// and what must not be taken for a foreign file (meshes, scenes, unknown bytes).
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh/foreign_formats.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

std::string messageFor(const std::string& text, const std::string& path) {
  return foreignFileMessage(std::span<const char>(text.data(), text.size()), text.size(), path);
}

std::string readerFile(const std::string& name) {
  const std::vector<char> bytes = test::readFileBytes(std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name);
  return {bytes.begin(), bytes.end()};
}

TEST(ForeignFormats, IgesIsRecognisedByItsEightyColumnRecords) {
  // The start of an IGES file: a Start section line, 80 columns, 'S' in column 73.
  const std::string line =
      std::string("IGES file written by a CAD system") + std::string(39, ' ') + "S      1\n";
  ASSERT_EQ(line.size(), 81u);
  EXPECT_EQ(
      messageFor(line + line, "part.dat"),
      "this is an IGES CAD model, not a mesh: rename it to part.iges, then mesh it with 'gmsh part.iges -2 "
      "-o part.msh'");
  EXPECT_EQ(messageFor("anything", "part.igs"),
            "this is an IGES CAD model, not a mesh: mesh it with 'gmsh part.igs -2 -o part.msh'");
}

TEST(ForeignFormats, ObjIsRecognisedByItsVertexAndFaceLines) {
  const std::string obj = "# exported\no part\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
  EXPECT_NE(messageFor(obj, "model.txt").find("Wavefront OBJ"), std::string::npos);
}

TEST(ForeignFormats, ContentWinsOverTheName) {
  EXPECT_NE(messageFor(readerFile("box.step"), "box.txt").find("rename it to box.step, then mesh it"),
            std::string::npos);
  EXPECT_NE(messageFor(readerFile("sphere.stl"), "sphere.msh").find("STL surface (ASCII)"),
            std::string::npos);
  const std::string binary = readerFile("sphere_binary.stl");
  EXPECT_NE(messageFor(binary, "sphere.bin").find("STL surface (binary)"), std::string::npos);
  EXPECT_NE(messageFor(readerFile("sphere.vtk"), "sphere").find("VTK file"), std::string::npos);
  // A list-based .pos view is read (the mesh reader takes it before it asks this), not refused.
  EXPECT_EQ(messageFor(readerFile("temperature.pos"), "t.txt"), "");
  EXPECT_NE(messageFor("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n", "model")
                .find("-3 -o model.msh"),
            std::string::npos);
  EXPECT_NE(messageFor("Point(1) = {0, 0, 0};\n", "sketch.txt").find("-2 -o sketch.msh"), std::string::npos);
}

TEST(ForeignFormats, MeshesScenesAndUnknownBytesAreNotForeign) {
  const std::vector<char> mesh = test::readFileBytes(test::mshFixture("square_tri3_v41_bin.msh"));
  EXPECT_TRUE(looksLikeMsh(mesh));
  EXPECT_EQ(foreignFileMessage(mesh, mesh.size(), "square.stl"), "");  // a mesh by content, whatever its name
  EXPECT_EQ(messageFor("[render]\nwidth = 64\n\n[[mesh]]\nfile = \"part.msh\"\n", "scene.toml"), "");
  EXPECT_EQ(messageFor("hello world\n", "notes.msh"), "");
  EXPECT_EQ(messageFor(std::string(100, '\0'), "zeros.bin"), "");
}

}  // namespace
}  // namespace lancer
