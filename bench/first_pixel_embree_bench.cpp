// Time to first pixel, stage by stage, on one MSH 4.1 binary mesh: a minimal reader's parse (the
// floor of what reading can cost), lancer's read and scene preparation (the CLI's quick look),
// the kd-tree builds (the default binned one and the exact kdtree-sah-exact) and Embree 3's MEDIUM
// and HIGH builds on 1 and 2 threads, and the trace cost of each tree on the accelerator bench's ray
// sets (what the fast build costs in tree quality). With LANCER_BENCH_KD_BINNED_ABOVE or
// LANCER_BENCH_KD_CLIP_ABOVE set, a variant build with those options runs beside the default one
// ("kdtree-sah-variant"), build and trace: how the build's options were tuned. Repetitions are
// interleaved so that every stage sees the same swings in machine load; the median is printed,
// one JSON object per line, for bench/time_to_first_pixel.sh to tabulate.
//   first_pixel_embree_bench MESH.msh [repetitions]
#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

#include "accel_bench_support.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/util/stage_times.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer::bench {
namespace {

// Nodes and triangles of an MSH 4.1 binary file and nothing else: no entities, groups, quads,
// volumes or checks. What any reader must at least do, for the "load against parse" ratio.
struct MinimalMesh {
  std::vector<float> xyz;
  std::vector<std::uint32_t> triangles;
};

MinimalMesh minimalParse(const std::string& path) {
  // The whole file in one read, as a minimal reader would.
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  std::string data(static_cast<std::size_t>(file.tellg()), '\0');
  file.seekg(0);
  if (!file.read(data.data(), static_cast<std::streamsize>(data.size())))
    throw std::runtime_error(path + ": cannot read");
  auto section = [&](const char* name) {
    const std::size_t at = data.find(name);
    if (at == std::string::npos) throw std::runtime_error(path + ": no " + name);
    return data.data() + at + std::strlen(name);
  };
  if (data.find("$MeshFormat\n4.1 1 8") == std::string::npos)
    throw std::runtime_error(path + ": not MSH 4.1 binary");
  auto take = [](const char*& p, auto& value) {
    std::memcpy(&value, p, sizeof value);
    p += sizeof value;
  };
  MinimalMesh mesh;
  const char* p = section("\n$Nodes\n");
  std::uint64_t blocks = 0, count = 0, minTag = 0, maxTag = 0;
  take(p, blocks), take(p, count), take(p, minTag), take(p, maxTag);
  std::vector<std::uint32_t> indexOfTag(maxTag + 1, 0);
  mesh.xyz.reserve(3 * count);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    int dim = 0, entity = 0, parametric = 0;
    std::uint64_t n = 0;
    take(p, dim), take(p, entity), take(p, parametric), take(p, n);
    if (parametric) throw std::runtime_error(path + ": parametric nodes");
    const char* tags = p;
    p += 8 * n;
    for (std::uint64_t i = 0; i < n; ++i) {
      std::uint64_t tag = 0;
      std::memcpy(&tag, tags + 8 * i, 8);
      indexOfTag[tag] = static_cast<std::uint32_t>(mesh.xyz.size() / 3);
      for (int c = 0; c < 3; ++c) {
        double x = 0;
        take(p, x);
        mesh.xyz.push_back(static_cast<float>(x));
      }
    }
  }
  p = section("\n$Elements\n");
  take(p, blocks), take(p, count), take(p, minTag), take(p, maxTag);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    int dim = 0, entity = 0, type = 0;
    std::uint64_t n = 0;
    take(p, dim), take(p, entity), take(p, type), take(p, n);
    const int nodes = type == 2 ? 3 : type == 15 ? 1 : type == 1 ? 2 : type == 3 ? 4 : type == 4 ? 4 : -1;
    if (nodes < 0) throw std::runtime_error(path + ": element type " + std::to_string(type));
    for (std::uint64_t i = 0; i < n; ++i) {
      p += 8;  // element tag
      std::uint64_t node[4] = {};
      for (int c = 0; c < nodes; ++c) take(p, node[c]);
      if (type == 2)
        for (int c = 0; c < 3; ++c) mesh.triangles.push_back(indexOfTag[node[c]]);
    }
  }
  return mesh;
}

struct EmbreeBuild {
  double seconds = 0;
  explicit EmbreeBuild(const Scene& scene, int threads, RTCBuildQuality quality) {
    RTCDevice device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
    if (!device) throw std::runtime_error("rtcNewDevice failed");
    std::vector<float> vertices;  // x, y, z, pad: Embree reads 16 bytes past the last vertex
    std::vector<std::uint32_t> indices;
    for (const Vec3& p : scene.geometry.positions) vertices.insert(vertices.end(), {p.x, p.y, p.z, 0.0f});
    for (const MeshFace& f : scene.geometry.faces) {
      indices.insert(indices.end(), {f.vertex[0], f.vertex[1], f.vertex[2]});
      if (f.isQuad()) indices.insert(indices.end(), {f.vertex[0], f.vertex[2], f.vertex[3]});
    }
    const Stopwatch stopwatch;
    RTCScene embreeScene = rtcNewScene(device);
    rtcSetSceneBuildQuality(embreeScene, quality);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, quality);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0,
                               4 * sizeof(float), scene.geometry.positions.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0,
                               3 * sizeof(std::uint32_t), indices.size() / 3);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embreeScene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(embreeScene);
    seconds = stopwatch.seconds();
    rtcReleaseScene(embreeScene);
    rtcReleaseDevice(device);
  }
};

// CPU seconds of the calling thread: the trace comparison runs on one thread, and CPU time is far
// steadier than wall time on a shared machine.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

bool variantWanted() {
  return std::getenv("LANCER_BENCH_KD_BINNED_ABOVE") != nullptr ||
         std::getenv("LANCER_BENCH_KD_CLIP_ABOVE") != nullptr;
}

// The default build's options with the binning threshold and clipping fraction from the environment.
KdBuildOptions variantOptions() {
  KdBuildOptions options;
  if (const char* v = std::getenv("LANCER_BENCH_KD_BINNED_ABOVE"))
    options.binnedAbove = static_cast<std::uint32_t>(std::atoi(v));
  if (const char* v = std::getenv("LANCER_BENCH_KD_CLIP_ABOVE"))
    options.clipAboveFraction = std::strtof(v, nullptr);
  return options;
}

double processCpuSeconds() { return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID); }

}  // namespace
}  // namespace lancer::bench

int main(int argc, char** argv) {
  using namespace lancer;
  using namespace lancer::bench;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH.msh [repetitions]\n", argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  const int repetitions = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;

  // What each stage needs, made once outside the timings.
  const Mesh fileMesh = readMsh(path);
  const SceneDescription description = quickLookScene(path, fileMesh);
  const Scene scene = buildScene(description, {fileMesh});
  std::size_t triangles = 0;
  for (const MeshFace& f : scene.geometry.faces) triangles += f.isQuad() ? 2 : 1;

  struct Stage {
    std::string name;
    int threads;
    std::function<double()> run;  // returns the seconds it measured
    std::vector<double> seconds;
    std::vector<double> cpuSeconds;  // of the whole process: every thread's work
    double sahCost = 0, bytes = 0;
    std::map<std::string, std::vector<double>> parts;  // the scene's own stage times, per repetition
  };
  std::vector<Stage> stages;
  auto timed = [](auto&& work) {
    return [work] {
      const Stopwatch stopwatch;
      work();
      return stopwatch.seconds();
    };
  };
  auto addStage = [&](std::string name, int threads, std::function<double()> run) {
    Stage stage;
    stage.name = std::move(name);
    stage.threads = threads;
    stage.run = std::move(run);
    stages.push_back(std::move(stage));
  };
  addStage("minimal parse", 1, timed([&] { (void)minimalParse(path).triangles.size(); }));
  addStage("lancer read", 1, timed([&] { (void)readMsh(path).faces.size(); }));
  for (const int threads : {1, 2}) {
    const std::size_t index = stages.size();
    addStage("lancer scene", threads, [&, threads, index] {
      std::vector<Mesh> meshes{fileMesh};  // the copy is not timed
      StageTimes parts;
      const Stopwatch stopwatch;
      const Scene built = buildScene(description, std::move(meshes), threads, &parts);
      const double seconds = stopwatch.seconds();
      for (const StageTimes::Stage& part : parts.stages)
        stages[index].parts[part.name].push_back(part.seconds);
      return seconds + 0.0 * double(built.geometry.faces.size());
    });
  }
  std::map<std::string, KdTree> trees;
  for (const int threads : {1, 2}) {
    for (const std::string name : {"kdtree-sah", "kdtree-sah-exact", "kdtree-sah-variant"}) {
      const bool variant = name == "kdtree-sah-variant";
      if (variant && !variantWanted()) continue;
      const std::size_t index = stages.size();
      addStage(name + " build", threads, [&, variant, threads, name, index] {
        KdBuildOptions options = variant ? variantOptions() : KdBuildOptions{};
        options.threads = threads;
        KdTree tree = name == "kdtree-sah-exact"
                          ? KdTree::buildSahExact(scene.geometry.positions, scene.geometry.faces, options)
                          : KdTree::buildSah(scene.geometry.positions, scene.geometry.faces, options);
        const double seconds = tree.stats().buildSeconds;
        stages[index].sahCost = tree.stats().sahCost;
        stages[index].bytes = double(tree.stats().bytes);
        if (threads == 2) trees.insert_or_assign(name, std::move(tree));
        return seconds;
      });
    }
    addStage("embree-medium build", threads,
             [&, threads] { return EmbreeBuild(scene, threads, RTC_BUILD_QUALITY_MEDIUM).seconds; });
    addStage("embree-high build", threads,
             [&, threads] { return EmbreeBuild(scene, threads, RTC_BUILD_QUALITY_HIGH).seconds; });
  }
  for (int r = 0; r < repetitions; ++r) {
    // Rotate the order each repetition so no stage always runs right after the same one.
    for (std::size_t k = 0; k < stages.size(); ++k) {
      Stage& stage = stages[(k + std::size_t(r)) % stages.size()];
      const double cpu = processCpuSeconds();
      stage.seconds.push_back(stage.run());
      stage.cpuSeconds.push_back(processCpuSeconds() - cpu);
    }
  }
  for (const Stage& stage : stages) {
    std::string parts;
    for (const auto& [name, seconds] : stage.parts)
      parts += fmt::format(", \"{}\": {:.4f}", name, median(seconds));
    std::printf(
        "{\"mesh\": \"%s\", \"triangles\": %zu, \"stage\": \"%s\", \"threads\": %d, \"seconds\": %.4f, "
        "\"cpu_seconds\": %.4f, \"sah_cost\": %.2f, \"bytes\": %.0f%s}\n",
        path.c_str(), triangles, stage.name.c_str(), stage.threads, median(stage.seconds),
        median(stage.cpuSeconds), stage.sahCost, stage.bytes, parts.c_str());
  }

  // Tree quality: each tree's single-thread CPU time on the same ray sets, interleaved.
  const Aabb box = scene.geometry.bounds;
  const RaySet primary = primaryRays(box, 512, 512);
  const RaySet shadow = shadowRays(box, primary, trees.at("kdtree-sah"));
  const RaySet incoherent = incoherentRays(box, 1u << 17);
  const std::pair<const char*, const RaySet*> sets[] = {
      {"primary", &primary}, {"shadow", &shadow}, {"incoherent", &incoherent}};
  std::map<std::string, std::vector<double>> traceSeconds;
  for (int r = 0; r < 2 * repetitions + 1; ++r) {
    for (const auto& [name, tree] : trees) {
      for (const auto& [kind, set] : sets) {
        const double start = threadCpuSeconds();
        std::uint64_t hits = 0;
        for (std::size_t i = 0; i < set->rays.size(); ++i) {
          if (set->anyHit) {
            hits += tree.occluded(set->rays[i], set->tMin, set->tMax[i]);
          } else {
            Hit hit;
            hits += tree.intersect(set->rays[i], set->tMin, set->tMax[i], hit);
          }
        }
        traceSeconds[name + "/" + kind].push_back((threadCpuSeconds() - start) + 0.0 * double(hits));
      }
    }
  }
  for (const auto& [name, tree] : trees) {
    for (const auto& [kind, set] : sets) {
      const double seconds = median(traceSeconds[name + "/" + kind]);
      std::printf(
          "{\"mesh\": \"%s\", \"triangles\": %zu, \"stage\": \"%s trace %s\", \"threads\": 1, \"seconds\": "
          "%.4f, \"mrays_per_cpu_s\": %.3f}\n",
          path.c_str(), triangles, name.c_str(), kind, seconds, double(set->rays.size()) / seconds * 1e-6);
    }
  }
  return 0;
}
