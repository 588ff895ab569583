// The figures of docs/volume.md: on a volume written by bench/make_volume_bench_data.py (a gmsh-made
// box of about a million tetrahedra, the scalar s and the vector b at the nodes), the time to build
// the isosurface s = 0 against the BVH build over its triangles, and the time to trace 1,000 field
// lines of b of 1,000 steps each. Medians of --reps runs, wall and CPU seconds of the process.
//   volume_timings bench/data/volume_box.msh [--reps N] [--threads T]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/volume/field_lines.hpp"
#include "lancer/mesh/volume/volume_cut.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"

namespace {

struct Seconds {
  double wall, cpu;
};

template <typename Work>
Seconds timed(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  work();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
          static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC};
}

Seconds median(std::vector<Seconds> runs) {
  const auto middle = [&](auto member) {
    std::vector<double> values;
    for (const Seconds& run : runs) values.push_back(run.*member);
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2),
                     values.end());
    return values[values.size() / 2];
  };
  return {middle(&Seconds::wall), middle(&Seconds::cpu)};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lancer;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s VOLUME.msh [--reps N] [--threads T]\n", argv[0]);
    return 2;
  }
  int reps = 3, threads = 2;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    if (option == "--reps") reps = std::max(1, std::atoi(argv[i + 1]));
    if (option == "--threads") threads = std::max(1, std::atoi(argv[i + 1]));
  }
  MeshWithVolume read;
  const Seconds load = timed([&] { read = readMshWithVolume(argv[1], threads); });
  const VolumeMesh& volume = *read.volume;
  std::printf("read %s with its volume: %zu cells, %zu nodes, %.3f s wall\n", argv[1], volume.cellCount(),
              volume.nodes.size(), load.wall);
  const VolumeField* s = volume.findField("s", 0);
  const VolumeField* b = volume.findField("b", 0);
  if (!s || !b) {
    std::fprintf(stderr, "the file has no fields s and b: write it with bench/make_volume_bench_data.py\n");
    return 2;
  }

  // The isosurface s = 0 (one thread: the cut is serial) against the BVH build over its triangles.
  const CellLevels levels = [&](std::uint32_t cell, float* out) { cellPointValues(volume, *s, cell, out); };
  std::vector<Seconds> cuts, builds;
  VolumeCut cut;
  for (int r = 0; r < reps; ++r) cuts.push_back(timed([&] { cut = cutVolume(volume, levels, 0.0F, true); }));
  KdBuildOptions options;
  options.threads = threads;
  for (int r = 0; r < reps; ++r)
    builds.push_back(timed([&] {
      const Accelerator tree =
          Accelerator::build(cut.surface.positions, cut.surface.faces, kDefaultAccel, options);
      (void)tree;
    }));
  const Seconds cutTime = median(cuts), buildTime = median(builds);
  std::printf("isosurface s = 0: %zu triangles, %zu vertices: %.3f s wall, %.3f s CPU\n",
              cut.surface.faceCount(), cut.surface.positions.size(), cutTime.wall, cutTime.cpu);
  std::printf("BVH build over them (%d threads): %.3f s wall, %.3f s CPU; isosurface / build: %.2f (wall)\n",
              threads, buildTime.wall, buildTime.cpu, cutTime.wall / buildTime.wall);

  // The slice through the box's middle, against the BVH build over it (a plane through a plane of
  // nodes: the awkward case for the cut).
  for (const double z : {0.5001, 0.5}) {
    VolumeCut slice;
    const Seconds sliceTime = timed([&] {
      slice = sliceVolume(volume, Vec3d{0.5, 0.5, z} - volume.origin, {0, 0, 1});
    });
    double boxArea = 0;
    int slivers = 0;
    for (const MeshFace& face : slice.surface.faces) {
      Aabb box;
      for (int c = 0; c < 3; ++c) box.extend(slice.surface.positions[face.vertex[c]]);
      const Vec3 e = box.extent();
      boxArea += double(e.x) * e.y;
      const Vec3d a = toDouble(slice.surface.positions[face.vertex[0]]);
      const Vec3d ab = toDouble(slice.surface.positions[face.vertex[1]]) - a,
                  ac = toDouble(slice.surface.positions[face.vertex[2]]) - a;
      const double longest = std::max({length(ab), length(ac), length(ab - ac)});
      if (length(cross(ab, ac)) / longest < 1e-4 * longest) ++slivers;
    }
    int nonFinite = 0;
    for (const Vec3& p : slice.surface.positions) nonFinite += !std::isfinite(p.x + p.y + p.z);
    std::vector<std::array<std::uint32_t, 3>> keys;
    for (const MeshFace& face : slice.surface.faces) {
      std::array<std::uint32_t, 3> k{face.vertex[0], face.vertex[1], face.vertex[2]};
      std::sort(k.begin(), k.end());
      keys.push_back(k);
    }
    std::sort(keys.begin(), keys.end());
    const auto duplicates =
        keys.size() - static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
    std::printf("z = %g: sum of triangle boxes' areas %.4f, slivers %d, non-finite %d, duplicate faces %zu\n",
                z, boxArea, slivers, nonFinite, duplicates);
    Aabb box;
    for (const Vec3& p : slice.surface.positions) box.extend(p);
    double area = 0, largest = 0;
    for (const MeshFace& face : slice.surface.faces) {
      const Vec3d a = toDouble(slice.surface.positions[face.vertex[0]]);
      const double twice = length(cross(toDouble(slice.surface.positions[face.vertex[1]]) - a,
                                        toDouble(slice.surface.positions[face.vertex[2]]) - a));
      area += 0.5 * twice;
      largest = std::max(largest, 0.5 * twice);
    }
    std::printf("slice area %.6f (largest triangle %.3g)\n", area, largest);
    KdBuildOptions one;
    one.threads = threads;
    const Seconds sliceBuild = timed([&] {
      const Accelerator tree =
          Accelerator::build(slice.surface.positions, slice.surface.faces, kDefaultAccel, one);
      (void)tree;
    });
    std::printf("slice z = 0.5: %zu triangles, %zu vertices, box z %.9g .. %.9g: %.3f s; its BVH %.3f s\n",
                slice.surface.faceCount(), slice.surface.positions.size(), box.lower.z + volume.origin.z,
                box.upper.z + volume.origin.z, sliceTime.wall, sliceBuild.wall);
  }

  // 1,000 field lines of b from seeds within 0.45 of the box's axis, forward, 1,000 steps each.
  const VolumeLocator locator(volume);
  std::vector<Vec3d> seeds;
  for (int i = 0; i < 1000; ++i) {
    const double t = (i + 0.5) / 1000;
    seeds.push_back(Vec3d{0.5 + 0.45 * t, 0.5, 0.1 + 0.8 * t} - volume.origin);
  }
  FieldLineSettings settings;
  settings.backward = false;
  settings.maxSteps = 1000;
  settings.maxLength = 1e30;
  settings.threads = threads;
  std::vector<Seconds> traces;
  std::vector<FieldLine> lines;
  for (int r = 0; r < reps; ++r)
    traces.push_back(timed([&] { lines = traceFieldLines(volume, locator, *b, seeds, settings); }));
  std::size_t steps = 0, full = 0;
  for (const FieldLine& line : lines) {
    steps += line.points.empty() ? 0 : line.points.size() - 1;
    full += line.forwardEnd == FieldLineEnd::kSteps;
  }
  const Seconds traceTime = median(traces);
  std::printf(
      "field lines: %zu lines, %zu steps (%zu lines ran all 1,000), %d threads: %.3f s wall, %.3f s CPU\n",
      lines.size(), steps, full, threads, traceTime.wall, traceTime.cpu);
  return 0;
}
