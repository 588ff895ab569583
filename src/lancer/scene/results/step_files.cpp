#include "lancer/scene/results/step_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

// fnmatch-like matching of * and ? (no character classes): the shell's globs people type.
bool globMatch(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p, ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string describeMeshDifference(const Mesh& first, const Mesh& other) {
  if (first.positions.size() != other.positions.size())
    return fmt::format("{} nodes against {}", other.positions.size(), first.positions.size());
  if (first.faces.size() != other.faces.size())
    return fmt::format("{} faces against {}", other.faces.size(), first.faces.size());
  for (std::size_t v = 0; v < first.positions.size(); ++v)
    if (other.worldPosition(static_cast<std::uint32_t>(v)) !=
        first.worldPosition(static_cast<std::uint32_t>(v)))
      return fmt::format("node {} of the mesh moved", v + 1);
  for (std::size_t f = 0; f < first.faces.size(); ++f)
    for (int c = 0; c < 4; ++c)
      if (first.faces[f].vertex[c] != other.faces[f].vertex[c])
        return fmt::format("face {} uses other nodes", f + 1);
  return {};
}

}  // namespace

bool isStepFilePattern(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return name.find_first_of("*?") != std::string::npos;
}

bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      std::size_t ei = i, ej = j;
      while (ei < a.size() && digit(a[ei])) ++ei;
      while (ej < b.size() && digit(b[ej])) ++ej;
      // Compare as numbers: strip leading zeros, then the longer run is larger.
      std::size_t si = i, sj = j;
      while (si + 1 < ei && a[si] == '0') ++si;
      while (sj + 1 < ej && b[sj] == '0') ++sj;
      if (ei - si != ej - sj) return ei - si < ej - sj;
      const int order = a.compare(si, ei - si, b, sj, ej - sj);
      if (order != 0) return order < 0;
      i = ei, j = ej;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

std::vector<std::string> matchStepFiles(const std::string& pattern, const SourceLocation& where) {
  const std::filesystem::path path(pattern);
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::string name = path.filename().string();
  std::vector<std::string> matches;
  std::error_code error;
  std::vector<std::string> others;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string entry = it->path().filename().string();
    if (globMatch(name, entry))
      matches.push_back(path.has_parent_path() ? (folder / entry).string() : entry);
    else if (entry.ends_with(".msh"))
      others.push_back(entry);
  }
  if (error && matches.empty())
    throw InputError(where, fmt::format("the steps' files '{}': cannot read the folder '{}': {}", pattern,
                                        folder.string(), error.message()));
  if (matches.empty()) {
    std::sort(others.begin(), others.end(), naturalLess);
    std::string seen = others.empty() ? "it has no .msh file" : "its .msh files: ";
    for (std::size_t i = 0; i < others.size() && i < 5; ++i) seen += (i ? ", " : "") + others[i];
    if (others.size() > 5) seen += ", ...";
    throw InputError(where, fmt::format("no file matches '{}' in '{}' ({}); give a pattern such as "
                                        "\"result_*.msh\" that names one file per step",
                                        name, folder.string(), seen));
  }
  std::sort(matches.begin(), matches.end(), naturalLess);
  return matches;
}

Mesh readStepFiles(const std::string& pattern, const std::vector<std::string>& files, int threads,
                   const SourceLocation& where) {
  // The files' steps together decide whether they stay in memory, as one file's would: when the
  // first file's times the file count exceed the budget, every file's steps are left in the file.
  const std::uint64_t budget = defaultResidentFieldBytes();
  Mesh mesh = readMsh(files.front(), threads, budget);
  std::uint64_t stepBytes = 0;
  for (const MeshField& field : mesh.fields)
    stepBytes += field.itemCount() * static_cast<std::uint64_t>(field.components) * sizeof(float);
  const bool store = stepBytes > 0 && files.size() > budget / stepBytes;
  if (store && !mesh.fields.empty() && !mesh.fields.front().isStored())
    mesh = readMsh(files.front(), threads, 0);
  // A file may hold several steps of a view: the files' steps follow each other, each file's in its
  // own order (its steps' indices ranked), so that three files of two steps make steps 0 to 5.
  std::map<std::string, int> firstFreeStep;  // per view
  const auto numberSteps = [&](std::vector<MeshField>& fields) {
    std::map<std::string, std::vector<int>> indices;  // each view's step indices in this file
    for (const MeshField& field : fields) indices[field.name].push_back(field.step);
    for (auto& [name, own] : indices) {
      std::sort(own.begin(), own.end());
      own.erase(std::unique(own.begin(), own.end()), own.end());
    }
    for (MeshField& field : fields) {
      const std::vector<int>& own = indices[field.name];
      const auto rank = std::lower_bound(own.begin(), own.end(), field.step) - own.begin();
      field.step = firstFreeStep[field.name] + static_cast<int>(rank);
    }
    for (const auto& [name, own] : indices) firstFreeStep[name] += static_cast<int>(own.size());
  };
  numberSteps(mesh.fields);
  for (std::size_t k = 1; k < files.size(); ++k) {
    Mesh next = readMsh(files[k], threads, store ? 0 : UINT64_MAX);
    if (const std::string difference = describeMeshDifference(mesh, next); !difference.empty())
      throw InputError(where,
                       fmt::format("{} is step {} of the pattern, but its mesh differs from {}'s ({}): "
                                   "steps in several files need one mesh; keep only that mesh's "
                                   "results in the pattern",
                                   files[k], k, files.front(), difference));
    numberSteps(next.fields);
    for (MeshField& field : next.fields) mesh.fields.push_back(std::move(field));
  }
  if (files.size() > 1) mesh.source.path = fmt::format("{} ({} files)", pattern, files.size());
  return mesh;
}

namespace {

Mesh readInstanceMesh(const MeshInstance& instance, int threads, std::shared_ptr<const VolumeMesh>* volume) {
  for (const std::string& view : instance.views) {
    std::error_code error;
    if (!std::filesystem::exists(view, error))
      throw InputError(instance.where, fmt::format("view file '{}' does not exist", view));
  }
  if (isStepFilePattern(instance.file)) {
    if (volume && instance.volume.any())
      throw InputError(instance.where,
                       fmt::format("slices and isosurfaces are drawn from one file; '{}' is a "
                                   "pattern of step files: give one of them",
                                   instance.file));
    Mesh mesh =
        readStepFiles(instance.file, matchStepFiles(instance.file, instance.where), threads, instance.where);
    addViewFiles(mesh, instance.views);
    if (const std::string reason = nothingToDrawReason(mesh); !reason.empty())
      throw InputError(instance.where,
                       fmt::format("mesh '{}' has nothing to draw: {}", instance.file, reason));
    return mesh;
  }
  std::error_code error;
  if (!std::filesystem::exists(instance.file, error))
    throw InputError(instance.where, fmt::format("mesh file '{}' does not exist", instance.file));
  Mesh mesh;
  if (volume) {
    MeshWithVolume read = readMeshFileWithVolume(instance.file, threads);
    addViewFiles(read, instance.views);
    mesh = std::move(read.mesh);
    *volume = std::move(read.volume);
  } else {
    mesh = readMeshFile(instance.file, threads);
    addViewFiles(mesh, instance.views);
  }
  if (const std::string reason = nothingToDrawReason(mesh); !reason.empty())
    throw InputError(instance.where, fmt::format("mesh '{}' has nothing to draw: {}", instance.file, reason));
  return mesh;
}

// A mesh the caller holds in memory, in place of a file: its views added, and its volume: the one it
// was made with (lancer.Mesh from arrays of tetrahedra, ...), else `fileVolume`, the one its file
// holds, which the caller read for it (lancer.read_msh's Mesh: an empty one when the file has no
// volume elements, which addVolumeViews then says as for a file); else its faces are all there is
// (coloured caps stay flat, volume views cannot be drawn).
Mesh givenInstanceMesh(const MeshInstance& instance, const Mesh& given,
                       const std::shared_ptr<const VolumeMesh>& fileVolume,
                       std::shared_ptr<const VolumeMesh>* volume) {
  const std::shared_ptr<const VolumeMesh>& own = given.volume ? given.volume : fileVolume;
  if (instance.volume.any() && !fileVolume && !(given.volume && !given.volume->empty()))
    throw InputError(instance.where,
                     fmt::format("'{}' is a mesh in memory without volume elements: slices, isosurfaces and "
                                 "field lines are drawn inside volumes; give the mesh file instead, or make "
                                 "the mesh with its tetrahedra (or hexahedra, prisms, pyramids)",
                                 given.source.path));
  MeshWithVolume read{given, own};
  addViewFiles(read, instance.views);
  read.mesh.volume = read.volume;
  if (volume) *volume = read.volume;
  if (const std::string reason = nothingToDrawReason(read.mesh); !reason.empty())
    throw InputError(instance.where,
                     fmt::format("mesh '{}' has nothing to draw: {}", given.source.path, reason));
  return std::move(read.mesh);
}

}  // namespace

std::vector<Mesh> readSceneMeshes(const SceneDescription& description, int threads, StageTimes* times,
                                  std::vector<std::shared_ptr<const VolumeMesh>>* volumes,
                                  std::span<const std::shared_ptr<const Mesh>> given,
                                  std::span<const std::shared_ptr<const VolumeMesh>> givenVolumes) {
  const Stopwatch read;
  std::vector<Mesh> meshes;
  meshes.reserve(description.meshes.size());
  if (volumes) volumes->assign(description.meshes.size(), nullptr);
  for (std::size_t i = 0; i < description.meshes.size(); ++i) {
    const MeshInstance& instance = description.meshes[i];
    if (i < given.size() && given[i]) {
      const std::shared_ptr<const VolumeMesh> none;
      meshes.push_back(givenInstanceMesh(instance, *given[i],
                                         i < givenVolumes.size() ? givenVolumes[i] : none,
                                         volumes ? &(*volumes)[i] : nullptr));
      continue;
    }
    const bool withVolume = volumes && needsVolume(description, instance);
    meshes.push_back(readInstanceMesh(instance, threads, withVolume ? &(*volumes)[i] : nullptr));
  }
  if (times) times->add("read", read.seconds());
  return meshes;
}

std::vector<Mesh> readSceneMeshes(const SceneDescription& description, int threads, StageTimes* times,
                                  std::vector<std::shared_ptr<const VolumeMesh>>* volumes) {
  return readSceneMeshes(description, threads, times, volumes, {});
}

}  // namespace lancer
