#include "support/files.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace lancer::test {

namespace fs = std::filesystem;

ScratchFolder::ScratchFolder() {
  std::string pattern = (fs::temp_directory_path() / "lancer-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  // Tests make read-only folders; give them back to the owner so that everything can go.
  std::error_code ignored;
  fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
  for (const auto& entry : fs::recursive_directory_iterator(path_, ignored))
    fs::permissions(entry.path(), fs::perms::owner_all, fs::perm_options::add, ignored);
  fs::remove_all(path_, ignored);
}

std::vector<std::string> ScratchFolder::entries() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> ScratchFolder::entriesBelow() const {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(path_))
    names.push_back(fs::relative(entry.path(), path_).string());
  std::sort(names.begin(), names.end());
  return names;
}

void ScratchFolder::write(const std::string& name, const std::string& text) const {
  fs::create_directories((path_ / name).parent_path());
  std::ofstream(path_ / name, std::ios::binary) << text;
}

void ScratchFolder::copy(const fs::path& from, const std::string& name) const {
  fs::copy_file(from, path_ / name);
}

std::string ScratchFolder::read(const std::string& name) const { return readText(path_ / name); }

void expectOnlyFile(const ScratchFolder& folder, const std::string& name,
                    const std::vector<std::uint8_t>& bytes) {
  EXPECT_EQ(readBytes(folder.file(name)), bytes) << name;
  EXPECT_EQ(folder.entries(), std::vector<std::string>{name});
}

std::vector<std::uint8_t> readPictureBytes(const std::string& path) {
  std::vector<std::uint8_t> bytes = readBytes(path);
  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) return bytes;
  std::vector<std::uint8_t> kept(bytes.begin(), bytes.begin() + 8);
  std::size_t at = 8;
  while (at + 12 <= bytes.size()) {  // length (big-endian), type, data, CRC: PNG 1.2 section 3.2
    const std::size_t length =
        static_cast<std::size_t>(bytes[at]) << 24 | bytes[at + 1] << 16 | bytes[at + 2] << 8 | bytes[at + 3];
    const std::string type(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                           bytes.begin() + static_cast<std::ptrdiff_t>(at + 8));
    const std::size_t end = std::min(bytes.size(), at + 12 + length);
    if (type != "tEXt" && type != "iTXt" && type != "zTXt")
      kept.insert(kept.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at),
                  bytes.begin() + static_cast<std::ptrdiff_t>(end));
    at = end;
  }
  kept.insert(kept.end(), bytes.begin() + static_cast<std::ptrdiff_t>(std::min(at, bytes.size())),
              bytes.end());
  return kept;
}

void expectSameFile(const std::string& actual, const std::string& expected) {
  ASSERT_TRUE(std::filesystem::exists(actual)) << actual;
  EXPECT_TRUE(readPictureBytes(actual) == readPictureBytes(expected))
      << actual << " differs from " << expected;
}

std::vector<std::uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<char> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string dataFile(const std::string& relative) {
  return std::string(LANCER_TEST_DATA_DIR) + "/" + relative;
}

std::string mshFixture(const std::string& name) { return dataFile("msh/" + name); }

std::string fixtureTestName(const std::string& file) {
  std::string name = file.substr(0, file.size() - 4);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

}  // namespace lancer::test
