// Results saved one file per time step, as solvers write them: `file = "result_*.msh"` in a [[mesh]]
// (or a quoted pattern on the command line) names every matching file, in natural order (result_2
// before result_10); each file is one step of its views, on one mesh that every file must share.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/stage_times.hpp"

namespace lancer {

// Whether a mesh path is a pattern (has * or ? in its file name).
bool isStepFilePattern(const std::string& path);

// The files a pattern names, in natural order (runs of digits compared as numbers). Throws
// InputError at `where` when none matches, naming the folder and what is in it.
std::vector<std::string> matchStepFiles(const std::string& pattern, const SourceLocation& where);

// "a2b" < "a10b": strings compared with their runs of digits as numbers.
bool naturalLess(const std::string& a, const std::string& b);

// Reads the files as one mesh whose views have one step per file: file k's fields become step k
// (their times kept when they increase from file to file, else the step index is the time). The
// first file's mesh is the mesh; a file whose mesh differs is an InputError naming both files. The
// mesh's source.path is "PATTERN (N files)" for messages.
Mesh readStepFiles(const std::string& pattern, const std::vector<std::string>& files, int threads,
                   const SourceLocation& where);

// readSceneMeshes (scene.hpp) with meshes already in memory (Python's Scene.add_mesh): `given[i]`,
// when set, is mesh i, copied instead of reading description.meshes[i].file, with its `views` added.
// Its volume is the one it was made with, else givenVolumes[i] when set (the volume of the file it
// was read from, which the caller reads once and keeps); without either, a [[mesh]] that draws inside
// a volume is an InputError.
std::vector<Mesh> readSceneMeshes(const SceneDescription& description, int threads, StageTimes* times,
                                  std::vector<std::shared_ptr<const VolumeMesh>>* volumes,
                                  std::span<const std::shared_ptr<const Mesh>> given,
                                  std::span<const std::shared_ptr<const VolumeMesh>> givenVolumes = {});

}  // namespace lancer
