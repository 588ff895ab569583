// Files gmsh writes with views, read back (tests/data/reader, scripts/make_reader_fixtures.sh):
// views appended with gmsh.view.write(..., append=True) after a repeat of the mesh, views with
// values for nodes and elements the file does not save, a section end gmsh accepts
// ($EndElememtData, as in gmsh's tutorial view5.msh) and a field section lancer cannot read.
// The mesh always loads; the view "x" holds each node's x coordinate, the oracle for where values land.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/mesh/msh_reader.hpp"

namespace lancer {
namespace {

std::string readerFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name;
}

const MeshField* fieldNamed(const Mesh& mesh, const std::string& name) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name) return &field;
  return nullptr;
}

// Every vertex's value of the view "x" is its x coordinate.
void expectXField(const Mesh& mesh) {
  const MeshField* x = fieldNamed(mesh, "x");
  ASSERT_NE(x, nullptr);
  ASSERT_EQ(x->itemCount(), mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    EXPECT_NEAR(x->scalar(v), mesh.worldPosition(static_cast<std::uint32_t>(v)).x, 1e-6) << "vertex " << v;
}

TEST(MshAppendedViews, ARepeatedIdenticalMeshIsAcceptedAndItsViewKept) {
  for (const char* file :
       {"appended_view_v41_ascii.msh", "appended_view_v41_bin.msh", "appended_view_v22_ascii.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(readerFixture(file));
    EXPECT_GT(mesh.faceCount(), 0u);
    EXPECT_TRUE(mesh.source.warnings.empty()) << mesh.source.warnings.front();
    ASSERT_EQ(mesh.fields.size(), 1u);
    expectXField(mesh);
  }
}

TEST(MshAppendedViews, ADifferentSecondMeshIsRefused) {
  try {
    readMsh(readerFixture("appended_view_changed_v41_ascii.msh"));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(
        std::string(error.what()).find(":287:1: error: a second $Nodes section that differs from the first"),
        std::string::npos)
        << error.what();
  }
}

TEST(MshAppendedViews, ValuesForUnsavedNodesAndElementsAreDroppedWithAWarning) {
  for (const char* file : {"partial_view_v41_ascii.msh", "partial_view_v22_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(readerFixture(file));
    EXPECT_GT(mesh.faceCount(), 0u);
    ASSERT_FALSE(mesh.source.warnings.empty());
    EXPECT_NE(mesh.source.warnings.front().find(
                  "warning: $NodeData 'x' gives values for 30 nodes that $Nodes does not define"),
              std::string::npos)
        << mesh.source.warnings.front();
    expectXField(mesh);  // the values that match are all there, in the right places
    // The element view over both squares' triangles: each saved face has its element's value.
    const MeshField* element = fieldNamed(mesh, "element number");
    ASSERT_NE(element, nullptr);
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_FALSE(std::isnan(element->scalar(f))) << f;
  }
  const Mesh text = readMsh(readerFixture("partial_view_v41_ascii.msh"));
  ASSERT_EQ(text.source.warnings.size(), 2u);
  EXPECT_EQ(text.source.warnings[1],
            readerFixture("partial_view_v41_ascii.msh") +
                ":617:1: warning: $ElementData 'element number' gives values for 42 elements that $Elements "
                "does not hold (the first: element 83); they were dropped and the other 42 kept");
}

TEST(MshAppendedViews, AnyEndMarkerGmshAcceptsEndsAFieldSection) {
  const Mesh mesh = readMsh(readerFixture("misspelt_end_v22_ascii.msh"));
  EXPECT_TRUE(mesh.source.warnings.empty());
  const MeshField* temperature = fieldNamed(mesh, "temperature");
  ASSERT_NE(temperature, nullptr);
  EXPECT_EQ(temperature->at, FieldAt::kElement);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_FALSE(std::isnan(temperature->scalar(f))) << f;
}

TEST(MshAppendedViews, AnUnreadableFieldSectionIsSkippedWithAWarningAndTheMeshLoads) {
  const Mesh mesh = readMsh(readerFixture("unreadable_nodedata_v41_ascii.msh"));
  EXPECT_EQ(mesh.faceCount(), 32u);
  EXPECT_TRUE(mesh.fields.empty());
  ASSERT_EQ(mesh.source.warnings.size(), 1u);
  const std::string expected =
      readerFixture("unreadable_nodedata_v41_ascii.msh") +
      ":194:1: warning: $NodeData \"temperature\" skipped: 0 components in $NodeData: "
      "expected 1 to 9";
  EXPECT_EQ(mesh.source.warnings[0], expected);
  ASSERT_EQ(mesh.source.skippedFields.size(), 1u);
  EXPECT_EQ(mesh.source.skippedFields[0].first, "temperature");
}

}  // namespace
}  // namespace lancer
