// Load time of the .msh reader on the big meshes bench/msh_load_vs_gmsh.sh makes (bench/data/),
// and bytes per triangle of the resulting Mesh. Files that are missing are skipped.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "lancer/mesh/msh_reader.hpp"

namespace {

std::string benchFile(const char* name) {
  // bench/data beside this source file, unless LANCER_BENCH_DATA names another folder.
  const char* dir = std::getenv("LANCER_BENCH_DATA");
  const std::filesystem::path folder =
      dir ? std::filesystem::path(dir) : std::filesystem::path(__FILE__).parent_path() / "data";
  return (folder / name).string();
}

std::size_t meshBytes(const lancer::Mesh& mesh) {
  return mesh.positions.capacity() * sizeof(lancer::Vec3) + mesh.faces.capacity() * sizeof(lancer::MeshFace) +
         mesh.facePhysicalTag.capacity() * sizeof(std::int32_t) +
         mesh.faceEntityTag.capacity() * sizeof(std::int32_t) +
         mesh.faceEdgeMask.capacity() * sizeof(std::uint8_t);
}

void loadMsh(benchmark::State& state, const char* name) {
  const std::string path = benchFile(name);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("missing " + path + ": run bench/msh_load_vs_gmsh.sh").c_str());
    return;
  }
  std::size_t faces = 0, bytes = 0;
  for (auto _ : state) {
    const lancer::Mesh mesh = lancer::readMsh(path);
    faces = mesh.faceCount();
    bytes = meshBytes(mesh);
    benchmark::DoNotOptimize(mesh.faces.data());
  }
  state.counters["faces"] = static_cast<double>(faces);
  state.counters["bytes_per_face"] = faces ? static_cast<double>(bytes) / static_cast<double>(faces) : 0;
  state.counters["file_MB_per_s"] =
      benchmark::Counter(static_cast<double>(std::filesystem::file_size(path)) * 1e-6,
                         benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK_CAPTURE(loadMsh, v41_binary, "big_sphere_v41_bin.msh")->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(loadMsh, v41_ascii, "big_sphere_v41_ascii.msh")->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(loadMsh, v22_binary, "big_sphere_v22_bin.msh")->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(loadMsh, v22_ascii, "big_sphere_v22_ascii.msh")->Unit(benchmark::kMillisecond)->MinTime(2);

}  // namespace

BENCHMARK_MAIN();
