// The kd-tree builds alone, for tuning them: each build's wall and CPU seconds (medians), its SAH
// cost and size, and (with --trace) the single-thread CPU time of each tree on the accelerator
// bench's primary, shadow and incoherent rays. Quicker than bench/time_to_first_pixel.sh (no
// Embree, no load stages); the builds run interleaved so that each sees the same machine load.
// Each build's layout is hashed (FNV-1a over its words): the same hash, the same tree.
//   kd_build_bench MESH.msh [--reps N] [--threads 1,2] [--exact] [--median] [--trace] [--clip F]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "accel_bench_support.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/scene.hpp"

int main(int argc, char** argv) {
  using namespace lancer;
  using namespace lancer::bench;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH.msh [--reps N] [--threads 1,2] [--exact] [--trace] [--clip F]\n",
                 argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  int reps = 3;
  std::vector<int> threadCounts = {1, 2};
  bool exact = false, withMedian = false, trace = false;
  float clip = -1.0f;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) {
      reps = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--threads" && i + 1 < argc) {
      threadCounts.clear();
      std::stringstream list(argv[++i]);
      for (std::string t; std::getline(list, t, ',');) threadCounts.push_back(std::atoi(t.c_str()));
    } else if (a == "--exact") {
      exact = true;
    } else if (a == "--median") {
      withMedian = true;
    } else if (a == "--trace") {
      trace = true;
    } else if (a == "--clip" && i + 1 < argc) {
      clip = std::strtof(argv[++i], nullptr);
    } else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  const Mesh mesh = readMsh(path);
  const Scene scene = buildScene(quickLookScene(path, mesh), {mesh});
  const auto& positions = scene.geometry.positions;
  const auto& faces = scene.geometry.faces;

  struct Run {
    std::string name;
    int threads;
    int kind;  // 0 binned, 1 exact, 2 median
    std::vector<double> wall, cpu;
    AccelStats stats;
    std::uint64_t hash = 0;
  };
  std::vector<Run> runs;
  for (const int t : threadCounts) {
    runs.push_back({"kdtree-sah", t, 0, {}, {}, {}});
    if (exact) runs.push_back({"kdtree-sah-exact", t, 1, {}, {}, {}});
    if (withMedian) runs.push_back({"kdtree-median", t, 2, {}, {}, {}});
  }
  std::map<std::string, KdTree> trees;
  for (int r = 0; r < reps; ++r) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      Run& run = runs[(k + std::size_t(r)) % runs.size()];
      KdBuildOptions options;
      options.threads = run.threads;
      if (clip >= 0.0f) options.clipAboveFraction = clip;
      const double cpu = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
      KdTree tree = run.kind == 1   ? KdTree::buildSahExact(positions, faces, options)
                    : run.kind == 2 ? KdTree::buildMedian(positions, faces, options)
                                    : KdTree::buildSah(positions, faces, options);
      run.cpu.push_back(cpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu);
      run.wall.push_back(tree.stats().buildSeconds);
      run.stats = tree.stats();
      std::uint64_t hash = 1469598103934665603ull;
      for (const KdNode& node : tree.layout()) {
        for (const std::uint32_t word : {node.payload, node.bits}) hash = (hash ^ word) * 1099511628211ull;
      }
      run.hash = hash;
      if (trace && !trees.contains(run.name)) trees.emplace(run.name, std::move(tree));
    }
  }
  for (const Run& run : runs) {
    const AccelStats& s = run.stats;
    std::printf(
        "%-17s threads %d: wall %.3f s (min %.3f)  cpu %.3f s (min %.3f)  SAH %.2f  nodes %llu  leaves %llu  "
        "refs %llu  "
        "depth %llu  bytes/tri %.1f  hash %016llx\n",
        run.name.c_str(), run.threads, median(run.wall), *std::min_element(run.wall.begin(), run.wall.end()),
        median(run.cpu), *std::min_element(run.cpu.begin(), run.cpu.end()), s.sahCost,
        static_cast<unsigned long long>(s.nodes), static_cast<unsigned long long>(s.leaves),
        static_cast<unsigned long long>(s.triangleReferences), static_cast<unsigned long long>(s.depth),
        s.bytesPerTriangle(), static_cast<unsigned long long>(run.hash));
  }
  if (!trace) return 0;
  const Aabb box = scene.geometry.bounds;
  const RaySet primary = primaryRays(box, 512, 512);
  const RaySet shadow = shadowRays(box, primary, trees.begin()->second);
  const RaySet incoherent = incoherentRays(box, 1u << 17);
  const std::pair<const char*, const RaySet*> sets[] = {
      {"primary", &primary}, {"shadow", &shadow}, {"incoherent", &incoherent}};
  std::map<std::string, std::vector<double>> seconds;
  for (int r = 0; r < 2 * reps + 1; ++r) {
    for (const auto& [name, tree] : trees) {
      for (const auto& [kind, set] : sets) {
        const double start = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
        std::uint64_t hits = 0;
        for (std::size_t i = 0; i < set->rays.size(); ++i) {
          if (set->anyHit) {
            hits += tree.occluded(set->rays[i], set->tMin, set->tMax[i]);
          } else {
            Hit hit;
            hits += tree.intersect(set->rays[i], set->tMin, set->tMax[i], hit);
          }
        }
        seconds[name + "/" + kind].push_back(cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - start +
                                             0.0 * double(hits));
      }
    }
  }
  for (const auto& [name, tree] : trees) {
    std::printf("%-17s trace Mrays/cpu-s:", name.c_str());
    for (const auto& [kind, set] : sets)
      std::printf("  %s %.3f", kind, double(set->rays.size()) / median(seconds[name + "/" + kind]) * 1e-6);
    std::printf("\n");
  }
  return 0;
}
