// lancer's kd-tree alone: both builds (SAH and spatial median) on the bracket meshes, build
// time and structure, and ray throughput for primary, shadow and incoherent rays on 1 and 2 threads.
// Run through bench/run_accel_bench.sh, which makes the meshes and prints the tables.
#include "accel_bench_support.hpp"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (const std::string& mesh : lancer::bench::meshNames()) {
    lancer::bench::registerLancer("kdtree-sah", mesh);
    lancer::bench::registerLancer("kdtree-median", mesh);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
