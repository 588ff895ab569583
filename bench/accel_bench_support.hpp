// What the accelerator benchmarks share: the gmsh meshes they load, the ray sets compared with Embree
// (1024x1024 pinhole primary rays framing the mesh, shadow rays to one light, incoherent rays in
// the bounding box) and a runner that traces a ray set on N threads in chunks, like the renderer,
// ray by ray or in packets of eight.
#pragma once

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/accel/ray_packet.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/mesh/msh_reader.hpp"

namespace lancer::bench {

// Seconds of CPU time on `clock` (CLOCK_PROCESS_CPUTIME_ID: every thread; CLOCK_THREAD_CPUTIME_ID:
// the caller's): on a shared machine steadier than wall time.
inline double cpuSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The middle value (the upper of the two middle ones for an even count; 0 for none).
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

// Mesh names from LANCER_BENCH_MESHES ("10k,100k"), loaded from bench/data/bracket_<name>.msh
// (bench/run_accel_bench.sh makes them with gmsh from bench/geo/).
inline std::vector<std::string> meshNames() {
  const char* env = std::getenv("LANCER_BENCH_MESHES");
  std::stringstream list(env && *env ? env : "10k,100k,1m,4m");
  std::vector<std::string> names;
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  return names;
}

inline std::string meshPath(const std::string& name) {
  const char* dir = std::getenv("LANCER_BENCH_DATA");
  return std::string(dir ? dir : LANCER_BENCH_DATA_DIR) + "/bracket_" + name + ".msh";
}

struct RaySet {
  std::vector<Ray> rays;
  std::vector<float> tMax;  // per ray (shadow rays stop at the light)
  float tMin = 0.0f;
  bool anyHit = false;
};

inline int benchThreads() {
  const char* env = std::getenv("LANCER_BENCH_THREADS");
  return env ? std::max(1, std::atoi(env)) : 2;
}

// Primary rays of a pinhole camera on the diagonal (1, -1.6, 0.9) of the box, framing its bounding
// sphere, in 8x8-pixel tiles (the renderer's order: neighbouring rays traced together).
inline RaySet primaryRays(const Aabb& box, int width = 1024, int height = 1024) {
  const Vec3 center = box.center();
  const float radius = 0.5f * length(box.extent());
  const Vec3 forward = normalize(Vec3{-1.0f, 1.6f, -0.9f});
  const float fov = 40.0f * 3.14159265f / 180.0f;
  const float distance = radius / std::sin(0.5f * fov);
  const Vec3 eye = center - forward * distance;
  const Vec3 right = normalize(cross(forward, Vec3{0, 0, 1}));
  const Vec3 up = cross(right, forward);
  const float scale = std::tan(0.5f * fov);
  RaySet set;
  for (int ty = 0; ty < height; ty += 8) {
    for (int tx = 0; tx < width; tx += 8) {
      for (int y = ty; y < std::min(ty + 8, height); ++y) {
        for (int x = tx; x < std::min(tx + 8, width); ++x) {
          const float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * scale;
          const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * scale;
          set.rays.emplace_back(eye, normalize(forward + right * sx + up * sy));
        }
      }
    }
  }
  set.tMax.assign(set.rays.size(), std::numeric_limits<float>::infinity());
  return set;
}

// Shadow rays from the primary hits towards one point light above and in front of the part.
inline RaySet shadowRays(const Aabb& box, const RaySet& primary, const KdTree& tree) {
  const Vec3 light = box.center() + Vec3{-0.6f, -1.0f, 1.4f} * length(box.extent());
  const float offset = 1e-4f * length(box.extent());
  RaySet set;
  set.anyHit = true;
  for (const Ray& ray : primary.rays) {
    Hit hit;
    if (!tree.intersect(ray, 0.0f, std::numeric_limits<float>::infinity(), hit)) continue;
    const Vec3 p = ray.at(hit.t);
    const Vec3 toLight = light - p;
    const float distance = length(toLight);
    const Vec3 dir = toLight * (1.0f / distance);
    set.rays.emplace_back(p + dir * offset, dir);
    set.tMax.push_back(distance - 2.0f * offset);
  }
  return set;
}

// Random origins and directions inside the box: incoherent rays, closest hit.
inline RaySet incoherentRays(const Aabb& box, std::size_t count = 1u << 18) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> n(0.0f, 1.0f);
  RaySet set;
  const Vec3 e = box.extent();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 o{box.lower.x + u(rng) * e.x, box.lower.y + u(rng) * e.y, box.lower.z + u(rng) * e.z};
    set.rays.emplace_back(o, normalize(Vec3{n(rng), n(rng), n(rng)}));
  }
  set.tMax.assign(set.rays.size(), std::numeric_limits<float>::infinity());
  return set;
}

// Runs trace(begin, end) over [0, count) in chunks of 4096 on `threads` threads; returns seconds.
template <typename Trace>
double runChunked(std::size_t count, int threads, Trace&& trace) {
  constexpr std::size_t kChunk = 4096;
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t begin; (begin = next.fetch_add(kChunk)) < count;)
      trace(begin, std::min(count, begin + kChunk));
  };
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lancer::bench

#include <benchmark/benchmark.h>

#include <memory>
#include <mutex>

namespace lancer::bench {

// The BVH's build options on `threads` threads; LANCER_BENCH_BVH_TRAVERSAL_COST overrides the SAH's
// node-step cost and LANCER_BENCH_BVH_CLUSTER_REFERENCES the clusters' size (for tuning runs).
inline BvhBuildOptions bvhBenchOptions(int threads) {
  BvhBuildOptions options;
  options.threads = threads;
  if (const char* cost = std::getenv("LANCER_BENCH_BVH_TRAVERSAL_COST"))
    options.traversalCost = std::stof(cost);
  if (const char* size = std::getenv("LANCER_BENCH_BVH_CLUSTER_REFERENCES"))
    options.maxClusterReferences = static_cast<std::uint32_t>(std::stoul(size));
  return options;
}

// One loaded mesh with its lazily built lancer trees and ray sets, shared by all benchmarks.
struct MeshContext {
  std::string name;
  Mesh mesh;
  Aabb box;
  std::map<std::string, std::unique_ptr<KdTree>> trees;  // by kind, built with 2 threads
  std::unique_ptr<Bvh> bvh;                              // the default accelerator ("bvh")
  std::unique_ptr<RaySet> primary, shadow, incoherent;

  // f(tree) with the structure itself (no Accelerator dispatch per ray): the BVH for "bvh", else the
  // kd-tree of that kind.
  template <typename F>
  void withTree(const std::string& kind, F&& f) {
    if (kind != "bvh") return f(tree(kind));
    if (!bvh) bvh = std::make_unique<Bvh>(Bvh::build(mesh.positions, mesh.faces, bvhBenchOptions(2)));
    f(*bvh);
  }

  const KdTree& tree(const std::string& kind) {
    std::unique_ptr<KdTree>& slot = trees[kind];
    if (!slot) {
      KdBuildOptions options;
      options.threads = 2;
      slot = std::make_unique<KdTree>(kind == "kdtree-median"
                                          ? KdTree::buildMedian(mesh.positions, mesh.faces, options)
                                          : KdTree::buildSah(mesh.positions, mesh.faces, options));
    }
    return *slot;
  }
  const RaySet& rays(const std::string& kind) {
    if (kind == "primary") {
      if (!primary) primary = std::make_unique<RaySet>(primaryRays(box));
      return *primary;
    }
    if (kind == "shadow") {
      if (!shadow) shadow = std::make_unique<RaySet>(shadowRays(box, rays("primary"), tree("kdtree-sah")));
      return *shadow;
    }
    if (!incoherent) incoherent = std::make_unique<RaySet>(incoherentRays(box));
    return *incoherent;
  }
};

inline MeshContext& meshContext(const std::string& name) {
  static std::map<std::string, std::unique_ptr<MeshContext>> cache;
  std::unique_ptr<MeshContext>& slot = cache[name];
  if (!slot) {
    // Only one mesh in memory at a time: the benchmarks run mesh by mesh.
    cache.clear();
    std::unique_ptr<MeshContext>& fresh = cache[name];
    fresh = std::make_unique<MeshContext>();
    fresh->name = name;
    fresh->mesh = readMsh(meshPath(name));
    fresh->box = faceBounds(fresh->mesh);
    return *fresh;
  }
  return *slot;
}

inline const char* const kRayKinds[] = {"primary", "shadow", "incoherent"};

// Traces `set` with `intersect(ray, tMin, tMax) -> bool` on `threads` threads; reports Mrays/s
// and the hit fraction (equal between accelerators: a cheap check that they trace the same thing).
// The counters every trace row reports: speed over the timed iterations, the hit fraction, the set's size.
inline void setRayCounters(benchmark::State& state, double raysPerIteration, double seconds, double hits) {
  state.counters["Mrays_per_s"] = raysPerIteration * double(state.iterations()) / seconds * 1e-6;
  state.counters["hit_fraction"] = hits / raysPerIteration;
  state.counters["rays"] = raysPerIteration;
}

template <typename Query>
void traceBenchmark(benchmark::State& state, const RaySet& set, int threads, Query&& query) {
  double seconds = 0;
  std::atomic<std::uint64_t> hits{0};
#ifdef LANCER_KD_COUNTERS
  // Profiling builds (-DLANCER_KD_COUNTERS): work per ray of the calling thread (all of it at 1 thread).
  kdTraversalCounters() = {};
#endif
  for (auto _ : state) {
    hits = 0;
    const double s = runChunked(set.rays.size(), threads, [&](std::size_t begin, std::size_t end) {
      std::uint64_t local = 0;
      for (std::size_t i = begin; i < end; ++i) local += query(set.rays[i], set.tMin, set.tMax[i]);
      hits += local;
    });
    state.SetIterationTime(s);
    seconds += s;
  }
  setRayCounters(state, double(set.rays.size()), seconds, double(hits));
#ifdef LANCER_KD_COUNTERS
  const KdTraversalCounters& c = kdTraversalCounters();
  if (threads == 1 && c.rays > 0) {
    state.counters["inner_per_ray"] = double(c.innerNodes) / double(c.rays);
    state.counters["leaves_per_ray"] = double(c.leaves) / double(c.rays);
    state.counters["tests_per_ray"] = double(c.triangleTests) / double(c.rays);
  }
#endif
}

// A ray set in packets of eight, in the set's order: the primary set's rows of 8 pixels of a tile,
// shadow rays from 8 neighbouring hits; the last packet may be partial.
struct PacketSet {
  std::vector<RayPacket> packets;
  std::vector<std::uint32_t> active;  // lane mask per packet
  std::size_t rays = 0;
  bool anyHit = false;
};

inline PacketSet packetsOf(const RaySet& set) {
  PacketSet packets;
  packets.anyHit = set.anyHit;
  packets.rays = set.rays.size();
  for (std::size_t first = 0; first < set.rays.size(); first += kPacketSize) {
    RayPacket& packet = packets.packets.emplace_back();
    std::uint32_t active = 0;
    for (std::size_t i = 0; i < kPacketSize && first + i < set.rays.size(); ++i) {
      packet.ray[i] = set.rays[first + i];
      packet.tMin[i] = set.tMin;
      packet.tMax[i] = set.tMax[first + i];
      active |= 1u << i;
    }
    packets.active.push_back(active);
  }
  return packets;
}

// Traces `set` with `query(packet, active) -> lanes hit` on `threads` threads (chunks of 4096
// packets); reports Mrays/s and the hit fraction, as traceBenchmark.
template <typename Query>
void tracePacketBenchmark(benchmark::State& state, const PacketSet& set, int threads, Query&& query) {
  double seconds = 0;
  std::atomic<std::uint64_t> hits{0};
  for (auto _ : state) {
    hits = 0;
    const double s = runChunked(set.packets.size(), threads, [&](std::size_t begin, std::size_t end) {
      std::uint64_t local = 0;
      for (std::size_t i = begin; i < end; ++i)
        local += static_cast<std::uint64_t>(std::popcount(query(set.packets[i], set.active[i])));
      hits += local;
    });
    state.SetIterationTime(s);
    seconds += s;
  }
  setRayCounters(state, double(set.rays), seconds, double(hits));
}

// The packet rows: `name`'s query on each ray set in packets, as "packet/<name>/<mesh>/<rays>/threads:N".
template <typename MakeQuery>
void registerPacketRows(const std::string& name, const std::string& mesh, MakeQuery makeQuery) {
  static std::map<std::string, std::shared_ptr<PacketSet>> sets;  // by mesh and ray kind
  for (const char* rayKind : kRayKinds) {
    for (int threads : {1, 2}) {
      const std::string rk = rayKind;
      benchmark::RegisterBenchmark(
          ("packet/" + name + "/" + mesh + "/" + rk + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            std::shared_ptr<PacketSet>& set = sets[mesh + "/" + rk];
            if (!set) set = std::make_shared<PacketSet>(packetsOf(ctx.rays(rk)));
            tracePacketBenchmark(state, *set, threads, makeQuery(ctx, set->anyHit));
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

inline void registerLancerPackets(const std::string& kind, const std::string& mesh) {
  registerPacketRows(kind, mesh, [kind](MeshContext& ctx, bool anyHit) {
    const KdTree* tree = nullptr;
    const Bvh* bvh = nullptr;
    ctx.withTree(kind, [&](const auto& t) {
      if constexpr (std::is_same_v<std::decay_t<decltype(t)>, Bvh>) {
        bvh = &t;
      } else {
        tree = &t;
      }
    });
    return [tree, bvh, anyHit](const RayPacket& packet, std::uint32_t active) {
      Hit hits[kPacketSize];
      if (bvh != nullptr)
        return anyHit ? bvh->occluded(packet, active) : bvh->intersect(packet, active, hits);
      return anyHit ? tree->occluded(packet, active) : tree->intersect(packet, active, hits);
    };
  });
}

// The BVH's closest hits of independent rays with several in flight (Bvh::intersect of a span of rays),
// as "trace/bvh-inflight/<mesh>/<rays>/threads:N": the same rays as the trace rows, chunk by chunk
// (shadow rays: the any-hit query, Bvh::occluded of a span). "occluded/bvh(-inflight)/<mesh>/
// incoherent/threads:N": the any-hit queries, single and in flight, of the incoherent rays (as a path
// tracer's shadow rays from its bounces would be).
inline void registerLancerInFlight(const std::string& mesh) {
  struct Row {
    std::string name, rays;
    bool anyHit, inFlight;
  };
  const Row rows[] = {{"trace/bvh-inflight", "primary", false, true},
                      {"trace/bvh-inflight", "shadow", true, true},
                      {"trace/bvh-inflight", "incoherent", false, true},
                      {"occluded/bvh", "incoherent", true, false},
                      {"occluded/bvh-inflight", "incoherent", true, true}};
  for (const Row& row : rows) {
    for (int threads : {1, 2}) {
      benchmark::RegisterBenchmark(
          (row.name + "/" + mesh + "/" + row.rays + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            const RaySet& set = ctx.rays(row.rays);
            const Bvh* tree = nullptr;
            ctx.withTree("bvh", [&](const auto& t) {
              if constexpr (std::is_same_v<std::decay_t<decltype(t)>, Bvh>) tree = &t;
            });
            const Bvh& bvh = *tree;
            double seconds = 0;
            std::atomic<std::uint64_t> hits{0};
            for (auto _ : state) {
              hits = 0;
              const double s = runChunked(set.rays.size(), threads, [&](std::size_t begin, std::size_t end) {
                const auto rays = std::span(set.rays).subspan(begin, end - begin);
                const auto ends = std::span(set.tMax).subspan(begin, end - begin);
                if (!row.inFlight) {
                  std::uint64_t blocked = 0;
                  for (std::size_t i = 0; i < rays.size(); ++i)
                    blocked += bvh.occluded(rays[i], set.tMin, ends[i]) ? 1 : 0;
                  hits += blocked;
                } else if (row.anyHit) {
                  std::vector<std::uint8_t> blocked(end - begin);
                  hits += bvh.occluded(rays, set.tMin, ends, std::span(blocked));
                } else {
                  std::vector<Hit> found(end - begin);
                  hits += bvh.intersect(rays, set.tMin, ends, std::span(found));
                }
              });
              state.SetIterationTime(s);
              seconds += s;
            }
            setRayCounters(state, double(set.rays.size()), seconds, double(hits));
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

// Build statistics of `kind` on `threads` threads.
inline AccelStats buildStats(const std::string& kind, const Mesh& mesh, int threads) {
  if (kind == "bvh") return Bvh::build(mesh.positions, mesh.faces, bvhBenchOptions(threads)).stats();
  KdBuildOptions options;
  options.threads = threads;
  return (kind == "kdtree-median" ? KdTree::buildMedian(mesh.positions, mesh.faces, options)
                                  : KdTree::buildSah(mesh.positions, mesh.faces, options))
      .stats();
}

inline void registerLancer(const std::string& kind, const std::string& mesh) {
  {
    for (int threads : {1, 2}) {
      benchmark::RegisterBenchmark(
          ("build/" + kind + "/" + mesh + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            AccelStats stats;
            for (auto _ : state) {
              stats = buildStats(kind, ctx.mesh, threads);
              state.SetIterationTime(stats.buildSeconds);
            }
            state.counters["Mtris_per_s"] = stats.buildMillionTrianglesPerSecond();
            state.counters["triangles"] = double(stats.triangles);
            state.counters["bytes_per_tri"] = stats.bytesPerTriangle();
            state.counters["nodes"] = double(stats.nodes);
            state.counters["leaves"] = double(stats.leaves);
            state.counters["depth"] = double(stats.depth);
            state.counters["tris_per_leaf"] = stats.meanTrianglesPerLeaf;
            state.counters["sah_cost"] = stats.sahCost;
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
    for (const char* rayKind : kRayKinds) {
      for (int threads : {1, 2}) {
        const std::string rk = rayKind;
        benchmark::RegisterBenchmark(
            ("trace/" + kind + "/" + mesh + "/" + rk + "/threads:" + std::to_string(threads)).c_str(),
            [=](benchmark::State& state) {
              MeshContext& ctx = meshContext(mesh);
              const RaySet& set = ctx.rays(rk);
              ctx.withTree(kind, [&](const auto& tree) {
                if (set.anyHit) {
                  traceBenchmark(state, set, threads,
                                 [&](const Ray& r, float t0, float t1) { return tree.occluded(r, t0, t1); });
                } else {
                  traceBenchmark(state, set, threads, [&](const Ray& r, float t0, float t1) {
                    Hit hit;
                    return tree.intersect(r, t0, t1, hit);
                  });
                }
              });
            })
            ->UseManualTime()
            ->Iterations(1)
            ->Repetitions(3)
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace lancer::bench
