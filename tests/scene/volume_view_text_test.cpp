// The text forms of --slice, --isosurfaces and --streamlines (and Python's slices=, isosurfaces=,
// streamlines=): the planes and counts they say, and the messages for text that says none.
#include <gtest/gtest.h>

#include "lancer/scene/results/volume_view_text.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

TEST(VolumeViewText, SliceFromTextReadsAnAxisAValueOrAPointAndNormal) {
  const SliceSpec centre = sliceFromText("-y", SourceLocation{"--slice"});
  EXPECT_FALSE(centre.point.has_value());
  EXPECT_EQ(centre.normal, (Vec3d{0, -1, 0}));
  EXPECT_EQ(centre.where.file, "--slice");
  const SliceSpec value = sliceFromText("z=0.3", SourceLocation{"--slice"});
  ASSERT_TRUE(value.point.has_value());
  EXPECT_EQ(value.point->z, 0.3);
  EXPECT_EQ(value.normal, (Vec3d{0, 0, 1}));
  const SliceSpec plane = sliceFromText("1,2,3,0,1,1", SourceLocation{"slices"});
  EXPECT_EQ(*plane.point, (Vec3d{1, 2, 3}));
  EXPECT_EQ(plane.normal, (Vec3d{0, 1, 1}));  // normalised where the overrides are applied
}

TEST(VolumeViewText, SliceFromTextSaysWhatAPlaneIs) {
  EXPECT_EQ(test::messageOf([] { sliceFromText("w", SourceLocation{"--slice"}); }),
            "--slice: error: 'w' is not a plane: use AXIS (x, y or z: through the volume's centre), "
            "AXIS=VALUE (z=0.3) or PX,PY,PZ,NX,NY,NZ (a point and the normal)");
  EXPECT_NE(test::messageOf([] {
              sliceFromText("1,2,3", SourceLocation{"slices"});
            }).find("slices: error: '1,2,3'"),
            std::string::npos);
}

TEST(VolumeViewText, FieldAndCount) {
  EXPECT_EQ(fieldAndCountFromText("v", "--isosurfaces", 100),
            (std::pair<std::string, std::optional<int>>{"v", {}}));
  EXPECT_EQ(fieldAndCountFromText("a:b:7", "--isosurfaces", 100),
            (std::pair<std::string, std::optional<int>>{"a:b", 7}));
  for (const char* bad : {"v:0", "v:101", "v:2.5", "v:", "v:nan", "v:x"})
    EXPECT_EQ(test::messageOf([&] { fieldAndCountFromText(bad, "--isosurfaces", 100); }),
              std::string("--isosurfaces: error: '") + bad +
                  "' is not FIELD[:COUNT]: COUNT is a whole number from 1 to 100")
        << bad;
  EXPECT_EQ(test::messageOf([] { fieldAndCountFromText(":4", "--streamlines", 100000); }),
            "--streamlines: error: give the field: --streamlines FIELD[:COUNT]");
}

}  // namespace
}  // namespace lancer
