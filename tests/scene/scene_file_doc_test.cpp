// docs/scene_file.md against the loader: every key a scene table accepts (scene_keys.hpp, the lists
// the loader checks files against) has a row in the manual, and every row names a key the loader
// accepts. The page's convention, stated at its top: a heading names its tables in backticks
// (`[render]`, `[[light]]`, `[material.NAME]`, `[mesh.edges]`), and each key is a table row
// "| `key` | type | default | meaning |" under it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lancer/scene/scene_keys.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

const std::string kPage = std::string(LANCER_SOURCE_DIR) + "/docs/scene_file.md";

// "render.width", "material.NAME.ka", "mesh.edges.color"; "" tables give the key alone.
std::string qualified(const std::string& table, const std::string& key) {
  return table.empty() ? key : table + "." + key;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> result;
  std::stringstream in(row.substr(1));
  std::string cell;
  while (std::getline(in, cell, '|')) {
    const auto first = cell.find_first_not_of(' ');
    const auto last = cell.find_last_not_of(' ');
    result.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return result;
}

struct DocumentedKeys {
  std::set<std::string> keys;       // qualified
  std::set<std::string> tables;     // "render", "material.NAME", ...
  std::vector<std::string> errors;  // rows that do not follow the convention
};

DocumentedKeys readPage(const std::string& text) {
  static const std::regex kTableName(R"(`\[{1,2}([A-Za-z_.]+)\]{1,2}`)");
  static const std::regex kKeyRow(R"(^\| `([A-Za-z_0-9]+)` \|.*)");
  DocumentedKeys page;
  std::vector<std::string> section;  // the tables the current heading names
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  bool inCode = false;  // a fenced code block: its lines are examples, never headings or rows
  while (std::getline(lines, line)) {
    ++number;
    if (line.starts_with("```")) inCode = !inCode;
    if (inCode) continue;
    if (line.starts_with("#")) {
      section.clear();
      for (std::sregex_iterator it(line.begin(), line.end(), kTableName), end; it != end; ++it)
        section.push_back((*it)[1]);
      page.tables.insert(section.begin(), section.end());
      continue;
    }
    std::smatch match;
    if (section.empty() || !std::regex_match(line, match, kKeyRow)) continue;
    const std::vector<std::string> row = cells(line);
    if (row.size() < 4 || row[1].empty() || row[2].empty() || row[3].empty())
      page.errors.push_back(
          fmt::format("line {}: a key row needs | `key` | type | default | meaning |", number));
    for (const std::string& table : section) page.keys.insert(qualified(table, match[1]));
  }
  return page;
}

TEST(SceneFileDoc, ListsEveryKeyTheLoaderAcceptsAndNoOther) {
  const DocumentedKeys page = readPage(test::readText(kPage));
  for (const std::string& error : page.errors) ADD_FAILURE() << kPage << ": " << error;

  std::set<std::string> accepted;
  for (const SceneTableKeys& table : sceneFileKeys()) {
    if (table.table == SceneTable::Document) continue;
    for (std::string_view key : table.keys)
      accepted.insert(qualified(std::string(table.header), std::string(key)));
    EXPECT_TRUE(page.tables.count(std::string(table.header)))
        << kPage << " has no section for [" << table.header << "]: add a heading naming `[" << table.header
        << "]`";
  }
  std::string undocumented, unknown;
  for (const std::string& key : accepted)
    if (!page.keys.count(key)) undocumented += "\n  " + key;
  for (const std::string& key : page.keys)
    if (!accepted.count(key)) unknown += "\n  " + key;
  EXPECT_TRUE(undocumented.empty()) << "the loader accepts keys that " << kPage
                                    << " does not list (add a row | `key` | type | default | meaning |):"
                                    << undocumented;
  EXPECT_TRUE(unknown.empty()) << kPage << " lists keys that the loader does not accept:" << unknown;
}

TEST(SceneFileDoc, ReadsKeysUnderTheTablesTheirHeadingNames) {
  const DocumentedKeys page = readPage(
      "| `ignored` | before any table | - | - |\n"
      "## `[render]`: the image\n"
      "| key | type | default | meaning |\n|---|---|---|---|\n"
      "| `width` | integer | 800 | pixels |\n"
      "### `[[clip]]` and `[[mesh.clip]]`\n"
      "| `cap` | boolean | true | a face at the cut |\n"
      "| `point` | [x, y, z] | | |\n"
      "```toml\n# a comment, not a heading\n| `code` | in a code block | - | - |\n```\n"
      "| `normal` | [x, y, z] | *required* | the removed side |\n"
      "## Examples\n"
      "| `after` | a heading without tables | - | - |\n");
  EXPECT_EQ(page.keys, (std::set<std::string>{"render.width", "clip.cap", "mesh.clip.cap", "clip.point",
                                              "mesh.clip.point", "clip.normal", "mesh.clip.normal"}));
  EXPECT_EQ(page.tables, (std::set<std::string>{"render", "clip", "mesh.clip"}));
  ASSERT_EQ(page.errors.size(), 1u);
  EXPECT_EQ(page.errors[0], "line 8: a key row needs | `key` | type | default | meaning |");
}

// The top level holds the tables: each has a section whose heading starts with its name.
TEST(SceneFileDoc, HasASectionForEveryTopLevelTable) {
  const DocumentedKeys page = readPage(test::readText(kPage));
  std::set<std::string> documented;
  for (const std::string& table : page.tables) documented.insert(table.substr(0, table.find('.')));
  for (std::string_view name : sceneKeys(SceneTable::Document))
    EXPECT_TRUE(documented.count(std::string(name))) << kPage << " has no section for the table " << name;
}

}  // namespace
}  // namespace lancer
