// Reading one scalar step on a 1M-triangle plate as a list-based .pos view (one ST per triangle),
// parsed alone and read as a mesh (readMsh: parse, nodes merged, faces assembled, values mapped),
// against the same values as $NodeData in an ASCII .msh, and the mesh alone; the files are made by
// bench/make_pos_bench_data.py (bench/data/, or LANCER_BENCH_DATA). Wall time: readMsh and
// readPosFile run on lancer's default thread count (threads = 0: the .pos text parsed in pieces, the
// mesh assembled on every core) or on one; CPU is the calling thread's alone.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"

namespace {

std::string benchFile(const char* name) {
  const char* dir = std::getenv("LANCER_BENCH_DATA");
  const std::filesystem::path folder =
      dir ? std::filesystem::path(dir) : std::filesystem::path(__FILE__).parent_path() / "data";
  return (folder / name).string();
}

bool present(benchmark::State& state, const std::string& path) {
  if (std::filesystem::exists(path)) return true;
  state.SkipWithError(("missing " + path + ": run bench/make_pos_bench_data.py").c_str());
  return false;
}

void fileRate(benchmark::State& state, const std::string& path) {
  state.counters["file_MB_per_s"] =
      benchmark::Counter(static_cast<double>(std::filesystem::file_size(path)) * 1e-6,
                         benchmark::Counter::kIsIterationInvariantRate);
}

void loadPos(benchmark::State& state, int threads) {
  const std::string path = benchFile("plate.pos");
  if (!present(state, path)) return;
  std::size_t elements = 0;
  for (auto _ : state) {
    const lancer::PosFile file = lancer::readPosFile(path, threads);
    elements = file.views.front().elementCount();
    benchmark::DoNotOptimize(file.views.front().blocks.front().values.data());
  }
  state.counters["elements"] = static_cast<double>(elements);
  fileRate(state, path);
}

// The .pos through the one door (readMsh): parsed, then the mesh its elements carry built, the
// view's step put on its faces as element-node values.
void loadPosMesh(benchmark::State& state, int threads) {
  const std::string path = benchFile("plate.pos");
  if (!present(state, path)) return;
  std::size_t faces = 0;
  for (auto _ : state) {
    const lancer::Mesh mesh = lancer::readMsh(path, threads);
    faces = mesh.faces.size();
    benchmark::DoNotOptimize(mesh.fields.front().values.data());
  }
  state.counters["faces"] = static_cast<double>(faces);
  fileRate(state, path);
}

void loadMsh(benchmark::State& state, const char* name, int threads) {
  const std::string path = benchFile(name);
  if (!present(state, path)) return;
  std::size_t fields = 0;
  for (auto _ : state) {
    const lancer::Mesh mesh = lancer::readMsh(path, threads);
    fields = mesh.fields.size();
    benchmark::DoNotOptimize(mesh.faces.data());
  }
  state.counters["fields"] = static_cast<double>(fields);
  fileRate(state, path);
}

BENCHMARK_CAPTURE(loadPos, parse, 0)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);
BENCHMARK_CAPTURE(loadPos, parse_1_thread, 1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);
BENCHMARK_CAPTURE(loadPosMesh, mesh, 0)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);
BENCHMARK_CAPTURE(loadPosMesh, mesh_1_thread, 1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);
BENCHMARK_CAPTURE(loadMsh, nodedata, "plate_nodedata.msh", 0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3);
BENCHMARK_CAPTURE(loadMsh, nodedata_1_thread, "plate_nodedata.msh", 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3);
// Per value, $ElementNodeData (3 values a triangle) against $NodeData: (file - mesh alone) / values.
BENCHMARK_CAPTURE(loadMsh, elementnodedata_1_thread, "plate_elementnodedata.msh", 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3);
BENCHMARK_CAPTURE(loadMsh, mesh_alone_1_thread, "plate_mesh.msh", 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3);
BENCHMARK_CAPTURE(loadMsh, mesh_alone, "plate_mesh.msh", 0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3);

}  // namespace

BENCHMARK_MAIN();
