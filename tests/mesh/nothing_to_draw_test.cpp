// Why a mesh has nothing to draw, for files gmsh wrote (tests/data/reader, MSH 2.2 and 4.1 agree)
// and for element mixes gmsh does not write on its own (only polygons, all faces degenerate).
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"

namespace lancer {
namespace {

std::string reasonFor(const std::string& name) {
  return nothingToDrawReason(readMsh(std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name));
}

TEST(NothingToDraw, Msh22And41Agree) {
  for (const char* base : {"outline_only", "box_volume_group_2d", "square_unmeshed"}) {
    SCOPED_TRACE(base);
    const std::string v41 = reasonFor(std::string(base) + "_v41_ascii.msh");
    EXPECT_FALSE(v41.empty());
    EXPECT_EQ(reasonFor(std::string(base) + "_v22_ascii.msh"), v41);
  }
  EXPECT_EQ(
      reasonFor("outline_only_v41_ascii.msh"),
      "it holds only lines and points (16 2-node lines); lancer draws surfaces and volumes: mesh it with "
      "gmsh -2 or -3");
  EXPECT_EQ(
      reasonFor("box_volume_group_2d_v22_ascii.msh"),
      "it holds no elements, and its physical groups are volumes: mesh it with -3 (or save with -save_all)");
  EXPECT_EQ(reasonFor("two_plates_groups_v41_ascii.msh"), "");
}

TEST(NothingToDraw, ElementsLancerDoesNotDrawAndDegenerateFaces) {
  Mesh polygons;
  polygons.source.elementsByType = {{34, 3}, {15, 1}};
  EXPECT_EQ(nothingToDrawReason(polygons),
            "it holds only elements lancer does not draw (1 1-node point, 3 variable-size polygons)");
  Mesh flat;
  flat.source.elementsByType = {{2, 4}};
  flat.source.degenerateFacesDropped = 4;
  EXPECT_EQ(nothingToDrawReason(flat), "all its 4 faces are degenerate (zero area) and were dropped");
}

}  // namespace
}  // namespace lancer
