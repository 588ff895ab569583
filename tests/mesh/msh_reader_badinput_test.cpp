// Every broken file in tests/data/msh/broken/ (made by scripts/make_fixtures.sh from gmsh output) is
// refused with an InputError whose message says what is wrong and where; truncating or corrupting a
// valid file anywhere gives an InputError or a mesh, never a crash, a hang or another exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

using test::mshFixture;

struct BrokenCase {
  const char* file;
  // ":LINE:" for text, ":@OFFSET:" for binary, "" for whole-file errors; null for a file that reads
  // as an empty mesh, which render refuses with `message` (nothingToDrawReason) and info describes.
  const char* location;
  const char* message;
};

std::ostream& operator<<(std::ostream& out, const BrokenCase& c) { return out << c.file; }

class BrokenMshTest : public testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenMshTest, IsRefusedWithItsMessage) {
  const BrokenCase& c = GetParam();
  const std::string path = mshFixture(std::string("broken/") + c.file);
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  if (c.location == nullptr) {
    const Mesh mesh = readMsh(path);
    EXPECT_EQ(mesh.faceCount(), 0u);
    EXPECT_NE(nothingToDrawReason(mesh).find(c.message), std::string::npos) << nothingToDrawReason(mesh);
    return;
  }
  try {
    readMsh(path);
    FAIL() << "no error for " << c.file;
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find(c.message), std::string::npos) << what;
    EXPECT_EQ(what.rfind(path + c.location + (c.location[0] ? " error: " : ": error: "), 0), 0u) << what;
  }
}

const BrokenCase kBroken[] = {
    {"empty.msh", "", "the file is empty"},
    {"random_bytes.msh", ":1:2:", "not a gmsh mesh: a .msh file starts with $MeshFormat"},
    {"msh1.msh", ":1:1:", "this is an MSH 1 file; lancer reads MSH 2.2, 4.0 and 4.1"},
    {"version_4_2.msh", ":2:1:", "MSH version '4.2' is not supported; lancer reads MSH 2.2, 4.0 and 4.1"},
    {"version_5.msh", ":2:1:", "MSH version '5.0' is not supported"},
    {"file_type_7.msh", ":2:5:", "file type 7 in $MeshFormat: expected 0 (ASCII) or 1 (binary)"},
    {"data_size_4.msh", ":2:7:", "data size 4 in $MeshFormat"},
    {"binary_v40.msh", ":2:3:", "binary MSH 4.0 is not supported"},
    {"byte_swapped.msh", ":@20:", "the binary data is byte-swapped"},
    {"bad_check_word.msh", ":@20:", "the endianness check word in $MeshFormat is 7, expected 1"},
    {"no_end_mesh_format.msh",
     ":3:1:", "expected $EndMeshFormat after the $MeshFormat header, found '$EndMeshFormt'"},
    {"only_mesh_format.msh", nullptr, "it holds no elements (no $Elements section, or an empty one)"},
    {"truncated_nodes_ascii.msh",
     ":81:39:", "expected the node's x coordinate (a number), found the end of the file"},
    {"truncated_elements_ascii.msh", ":137:1:", "found the end of the file (the file looks truncated)"},
    {"truncated_nodes_bin.msh",
     ":@765:", "$Nodes (blocks) declares 9 entries of at least 20 bytes each, but only 161"},
    {"truncated_elements_bin.msh", ":@1798:", "$Elements declares 48 entries of at least 16 bytes each"},
    {"truncated_nodes_v22_bin.msh",
     ":@124:", "$Nodes declares 25 entries of at least 28 bytes each, but only 90"},
    {"missing_end_elements.msh",
     ":139:1:", "expected $EndElements after the 48 elements $Elements declares, found the end"},
    {"missing_node_v41.msh",
     ":107:1:", "element 17 (3-node triangle) uses node 9001, which $Nodes does not define"},
    {"missing_node_v22.msh",
     ":56:1:", "element 17 (3-node triangle) uses node 777, which $Nodes does not define"},
    {"nan_coordinate.msh", ":13:1:", "node 2 has a non-finite coordinate (nan, 0, 0)"},
    {"inf_coordinate.msh", ":29:1:", "node 2 has a non-finite coordinate (1, inf, 0)"},
    {"nan_coordinate_bin.msh", ":@793:", "node 1 has a non-finite coordinate (nan, 0, 0)"},
    {"huge_node_count.msh", ":23:20:", "$Nodes declares 999999999999 entries"},
    {"huge_node_count_bin.msh", ":@765:", "$Nodes declares 4611686018427387904 entries"},
    {"huge_element_count_v22.msh", ":39:15:", "$Elements declares 12345678901280 entries"},
    {"node_count_mismatch.msh",
     ":64:1:", "node blocks hold more than the 24 nodes the $Nodes header declares"},
    {"negative_count.msh", ":11:1:", "expected the number of nodes (a non-negative integer), found '-25'"},
    {"bad_number.msh", ":13:3:", "expected the node's x coordinate (a number), found '1.0abc'"},
    {"unknown_element_type.msh", ":106:1:", "element type 999 is not a gmsh element type"},
    {"polygon_element_type.msh", ":56:4:", "element type 34 is a variable-size type"},
    {"elements_before_nodes.msh", ":22:1:", "$Elements comes before $Nodes"},
    {"duplicate_node_tag.msh", ":10:1:", "node tag 1 is defined twice in $Nodes"},
    {"unterminated_name.msh", ":7:5:", "the physical group's name has no closing quote"},
    {"unclosed_section.msh", ":140:1:", "section $Periodic has no $EndPeriodic"},
    {"stray_end.msh", ":4:1:", "$EndNodes closes a section that was never opened"},
    {"garbage_between_sections.msh",
     ":10:1:", "expected a section such as $Nodes or $Elements, found 'hello'"},
};

INSTANTIATE_TEST_SUITE_P(Corpus, BrokenMshTest, testing::ValuesIn(kBroken),
                         [](const testing::TestParamInfo<BrokenCase>& param) {
                           std::string name = param.param.file;
                           return name.substr(0, name.size() - 4);
                         });

TEST(BrokenMsh, EveryCorpusFileHasACase) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(mshFixture("broken"))) {
    ++files;
    const std::string name = entry.path().filename().string();
    bool listed = false;
    for (const BrokenCase& c : kBroken) listed |= name == c.file;
    EXPECT_TRUE(listed) << name << " has no expected message";
  }
  EXPECT_GE(files, 25u);
}

std::string errorOf(const std::string& path) {
  return test::messageOf([&] { readMsh(path); });
}

TEST(BrokenMsh, MissingFileAndDirectory) {
  const std::string missing = mshFixture("no_such_file.msh");
  EXPECT_EQ(errorOf(missing), missing + ": error: cannot open the file: No such file or directory");
  const std::string directory = mshFixture("broken");
  EXPECT_EQ(errorOf(directory), directory + ": error: is a directory, not a .msh file");
}

// Parses bytes; fails the test on anything but success or an InputError naming the file.
void expectCleanOutcome(std::span<const char> bytes, const std::string& what) {
  try {
    readMshFromMemory(bytes, "mutant.msh");
  } catch (const InputError& error) {
    ASSERT_EQ(std::string(error.what()).rfind("mutant.msh", 0), 0u) << what << ": " << error.what();
  } catch (const std::exception& error) {
    FAIL() << what << ": unexpected exception " << error.what();
  }
}

class MutatedMshTest : public testing::TestWithParam<const char*> {};

TEST_P(MutatedMshTest, EveryTruncationIsHandled) {
  const std::vector<char> bytes = test::readFileBytes(mshFixture(GetParam()));
  ASSERT_FALSE(bytes.empty());
  for (std::size_t size = 0; size < bytes.size(); ++size)
    expectCleanOutcome(std::span<const char>(bytes.data(), size), "truncated at " + std::to_string(size));
}

TEST_P(MutatedMshTest, RandomByteChangesAreHandled) {
  const std::vector<char> original = test::readFileBytes(mshFixture(GetParam()));
  std::mt19937 random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<char> bytes = original;
    const int changes = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < changes; ++k) {
      const std::size_t at = random() % bytes.size();
      // Half the changes put a digit or a separator where gmsh wrote something else.
      static const char kInteresting[] = "0123456789 \n-.e$";
      bytes[at] =
          (random() & 1) ? kInteresting[random() % (sizeof(kInteresting) - 1)] : static_cast<char>(random());
    }
    expectCleanOutcome(bytes, "trial " + std::to_string(trial));
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, MutatedMshTest,
                         testing::Values("square_tri3_v41_bin.msh", "square_tri6_v41_ascii.msh",
                                         "square_quad8_v22_bin.msh", "square_tri3_v40_ascii.msh",
                                         "sphere_part2_v41_bin.msh", "cube_tet10_v22_ascii.msh"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           return test::fixtureTestName(param.param);
                         });

}  // namespace
}  // namespace lancer
