// Files for tests: scratch folders that are removed with everything in them at the end of the test,
// whole files read and written, and the paths of the committed fixtures in tests/data.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lancer::test {

// A fresh folder under $TMPDIR (else /tmp), removed at the end of the test even where a test took
// away its permissions.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // The names in the folder itself, sorted.
  std::vector<std::string> entries() const;
  // Every file and folder below it as a path relative to it ("ro/out.png"), sorted.
  std::vector<std::string> entriesBelow() const;

  // Writes `text` to the file `name`, making the folders on its way.
  void write(const std::string& name, const std::string& text) const;
  void copy(const std::filesystem::path& from, const std::string& name) const;
  std::string read(const std::string& name) const;

 private:
  std::filesystem::path path_;
};

// Adds gtest failures unless `folder` holds the file `name` alone, with exactly `bytes`: what a
// failed, interrupted or finished write must leave (no temporary file beside it).
void expectOnlyFile(const ScratchFolder& folder, const std::string& name,
                    const std::vector<std::uint8_t>& bytes);

std::vector<std::uint8_t> readBytes(const std::string& path);
// The file's bytes less a PNG's text chunks (tEXt, iTXt, zTXt: lancer's version and the command line
// that made the picture), which differ between two commands that make the same picture; any other
// file's bytes as they are.
std::vector<std::uint8_t> readPictureBytes(const std::string& path);
// Adds gtest failures unless `actual` exists and has exactly the bytes of `expected`, text chunks of a
// PNG aside (readPictureBytes).
void expectSameFile(const std::string& actual, const std::string& expected);
void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes);
// The whole file as text (or as bytes in a string).
std::string readText(const std::filesystem::path& path);
// The file as chars, the way readMshFromMemory takes it.
std::vector<char> readFileBytes(const std::string& path);

// A committed fixture: tests/data/RELATIVE.
std::string dataFile(const std::string& relative);
// A mesh fixture: tests/data/msh/NAME.
std::string mshFixture(const std::string& name);

// A test parameter's name for the fixture `file` ("cube_tet4_v41.msh" -> "cube_tet4_v41"): the name
// without its 4-character extension, characters other than letters and digits made '_'.
std::string fixtureTestName(const std::string& file);

// The committed 4-frame turntable scene the CLI tests render and animate.
inline const std::string kTurntableScene = std::string(LANCER_TEST_DATA_DIR) + "/render/turntable.toml";

}  // namespace lancer::test
