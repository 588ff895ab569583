#include "lancer/mesh/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "lancer/mesh/msh/foreign_formats.hpp"
#include "lancer/mesh/surface_formats/obj_reader.hpp"
#include "lancer/mesh/surface_formats/ply_header.hpp"
#include "lancer/mesh/surface_formats/ply_reader.hpp"
#include "lancer/mesh/surface_formats/stl_reader.hpp"
#include "lancer/util/mapped_file.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

constexpr std::size_t kHeadBytes = 4096;

enum class SurfaceFormat { kStlAscii, kStlBinary, kObj, kPly };

std::string lowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// The surface format of a file by its first bytes, then by its name (a broken .stl, .obj or .ply
// goes to its reader, which says what is wrong); nothing for a .msh, a view and every other file.
std::optional<SurfaceFormat> surfaceFormatOf(std::span<const char> head, std::uint64_t fileBytes,
                                             const std::string& path) {
  if (head.empty() || looksLikeMsh(head)) return std::nullopt;
  if (looksLikePly(head)) return SurfaceFormat::kPly;
  switch (stlKindOf(head, fileBytes)) {
    case StlKind::kAscii:
      return SurfaceFormat::kStlAscii;
    case StlKind::kBinary:
      return SurfaceFormat::kStlBinary;
    case StlKind::kNone:
      break;
  }
  if (looksLikeObj(head)) return SurfaceFormat::kObj;
  const std::string extension = lowerCaseExtension(path);
  if (extension == ".stl") return SurfaceFormat::kStlBinary;
  if (extension == ".obj") return SurfaceFormat::kObj;
  if (extension == ".ply") return SurfaceFormat::kPly;
  return std::nullopt;
}

Mesh readSurface(SurfaceFormat format, std::span<const char> bytes, const std::string& name) {
  switch (format) {
    case SurfaceFormat::kStlAscii:
      return readStl(bytes, name, StlKind::kAscii);
    case SurfaceFormat::kStlBinary:
      return readStl(bytes, name, StlKind::kBinary);
    case SurfaceFormat::kObj:
      return readObj(bytes, name);
    case SurfaceFormat::kPly:
      break;
  }
  return readPly(bytes, name);
}

std::span<const char> head(std::span<const char> bytes) {
  return bytes.first(std::min(bytes.size(), kHeadBytes));
}

// The surface read from `path` when it is one (its time in loadSeconds), else nothing: the .msh
// reader takes it (meshes, views, and the messages for every other format).
std::optional<Mesh> readIfSurface(const std::string& path) {
  const Stopwatch stopwatch;
  // A file that is not there, a folder or a device: the .msh reader's words, as before.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  const MappedFile file(path, "mesh file");
  const std::optional<SurfaceFormat> format = surfaceFormatOf(head(file.bytes()), file.bytes().size(), path);
  if (!format) return std::nullopt;
  Mesh mesh = readSurface(*format, file.bytes(), path);
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

}  // namespace

Mesh readMeshFile(const std::string& path, int threads) {
  return readMeshFile(path, threads, defaultResidentFieldBytes());
}

Mesh readMeshFile(const std::string& path, int threads, std::uint64_t residentFieldBytes) {
  if (std::optional<Mesh> surface = readIfSurface(path)) return std::move(*surface);
  return readMsh(path, threads, residentFieldBytes);
}

MeshWithVolume readMeshFileWithVolume(const std::string& path, int threads) {
  if (std::optional<Mesh> surface = readIfSurface(path))
    return MeshWithVolume{std::move(*surface), std::make_shared<const VolumeMesh>()};
  return readMshWithVolume(path, threads);
}

Mesh readMeshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads) {
  const Stopwatch stopwatch;
  if (const std::optional<SurfaceFormat> format = surfaceFormatOf(head(bytes), bytes.size(), nameForErrors)) {
    Mesh mesh = readSurface(*format, bytes, nameForErrors);
    mesh.source.loadSeconds = stopwatch.seconds();
    return mesh;
  }
  return readMshFromMemory(bytes, nameForErrors, threads);
}

bool isMeshFile(const std::string& path) {
  const std::string extension = lowerCaseExtension(path);
  if (extension == ".msh") return true;
  if (extension == ".toml") return false;
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes(kHeadBytes);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  const std::uint64_t fileBytes = error ? 0 : size;
  return looksLikeMsh(bytes) || isViewFile(path) || surfaceFormatOf(bytes, fileBytes, path).has_value() ||
         !foreignFileMessage(bytes, path).empty();
}

}  // namespace lancer
