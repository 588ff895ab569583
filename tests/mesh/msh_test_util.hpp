// Helpers shared by the mesh reader tests: fixture paths and reading a fixture into memory.
#pragma once

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace lancer::test {

inline std::string mshFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/msh/" + name;
}

inline std::vector<char> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace lancer::test
