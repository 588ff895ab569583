// Files that lancer does not read are recognised by content first, then by extension, and answered
// with the command that converts them (each run on Debian 12's gmsh 4.8.4 and python3-meshio 7.0.0,
// docs/gmsh_files.md). The gmsh-made ones (STEP, BREP, VTK, .geo) are also run through the CLI in
// the bad-input catalogue; here: the starts of files gmsh and meshio write (IGES, OFF, UNV, Abaqus,
// ANSYS, VTU) as short samples, content under a wrong name, and what must not be taken for a foreign
// file (meshes, the surfaces lancer reads, scenes, unknown bytes).
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh/foreign_formats.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

std::string messageFor(const std::string& text, const std::string& path) {
  return foreignFileMessage(std::span<const char>(text.data(), text.size()), path);
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

TEST(ForeignFormats, GmshReadsUniversalFiles) {
  const std::string unv =
      "    -1\n  2411\n         1         1         1        11\n"
      "   0.0000000000000000D+00   0.0000000000000000D+00   1.0000000000000000D+00\n";
  EXPECT_EQ(
      messageFor(unv, "part.unv"),
      "this is an I-deas universal file (UNV), not a gmsh mesh: convert it with 'gmsh part.unv -save -o "
      "part.msh'");
  // gmsh picks its reader by the extension.
  EXPECT_EQ(messageFor(unv, "part.txt"),
            "this is an I-deas universal file (UNV), not a gmsh mesh: rename it to part.unv, then convert it "
            "with 'gmsh part.unv -save -o part.msh'");
}

TEST(ForeignFormats, MeshioConvertsWhatGmshDoesNotRead) {
  EXPECT_EQ(messageFor("OFF\n# Created by meshio\n\n272 540 0\n", "part.dat"),
            "this is an OFF surface, not a gmsh mesh: convert it with meshio (Debian's python3-meshio): "
            "'meshio convert part.dat part.msh --input-format off --output-format gmsh22'");
  EXPECT_EQ(messageFor("*Heading\n box.inp\n*NODE\n1, 0, 0, 1\n", "box.inp"),
            "this is an Abaqus input file (.inp), not a gmsh mesh: convert it with meshio (Debian's "
            "python3-meshio): 'meshio convert box.inp box.msh --input-format abaqus --output-format gmsh22'");
  EXPECT_EQ(messageFor("** comment\n*Part, name=beam\n", "beam.txt").find("an Abaqus input file"), 8u);
  // An ANSYS mesh is a .msh too: converted beside itself, not onto itself.
  EXPECT_EQ(
      messageFor("(1 \"meshio 5.0.0\")\n(2 3)\n(10 (0 1 110 0))\n", "part.msh"),
      "this is an ANSYS Fluent mesh, not a gmsh mesh: convert it with meshio (Debian's python3-meshio): "
      "'meshio convert part.msh part_gmsh.msh --input-format ansys --output-format gmsh22'");
  EXPECT_EQ(
      messageFor("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n", "p.vtu"),
      "this is a VTK XML file (.vtu), not a gmsh mesh: convert it with meshio (Debian's python3-meshio): "
      "'meshio convert p.vtu p.msh --input-format vtu --output-format gmsh22'");
}

TEST(ForeignFormats, ContentWinsOverTheName) {
  EXPECT_NE(messageFor(readerFile("box.step"), "box.txt").find("rename it to box.step, then mesh it"),
            std::string::npos);
  EXPECT_EQ(messageFor(readerFile("sphere.vtk"), "sphere"),
            "this is a legacy VTK file, not a gmsh mesh: convert it with meshio (Debian's python3-meshio): "
            "'meshio convert sphere sphere.msh --input-format vtk --output-format gmsh22'");
  // A list-based .pos view is read (the mesh reader takes it before it asks this), not refused.
  EXPECT_EQ(messageFor(readerFile("temperature.pos"), "t.txt"), "");
  EXPECT_NE(messageFor("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n", "model")
                .find("-3 -o model.msh"),
            std::string::npos);
  EXPECT_NE(messageFor("Point(1) = {0, 0, 0};\n", "sketch.txt").find("-2 -o sketch.msh"), std::string::npos);
}

TEST(ForeignFormats, MeshesSurfacesScenesAndUnknownBytesAreNotForeign) {
  // STL, OBJ and PLY are read (mesh_file.hpp), whatever their names.
  EXPECT_EQ(messageFor(readerFile("sphere.stl"), "sphere.msh"), "");
  EXPECT_EQ(messageFor("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "part.obj"), "");
  EXPECT_EQ(messageFor("ply\nformat ascii 1.0\n", "part.ply"), "");
  const std::vector<char> mesh = test::readFileBytes(test::mshFixture("square_tri3_v41_bin.msh"));
  EXPECT_TRUE(looksLikeMsh(mesh));
  EXPECT_EQ(foreignFileMessage(mesh, "square.stl"), "");  // a mesh by content, whatever its name
  EXPECT_EQ(messageFor("[render]\nwidth = 64\n\n[[mesh]]\nfile = \"part.msh\"\n", "scene.toml"), "");
  EXPECT_EQ(messageFor("hello world\n", "notes.msh"), "");
  EXPECT_EQ(messageFor(std::string(100, '\0'), "zeros.bin"), "");
}

}  // namespace
}  // namespace lancer
