// Refit against rebuild of the default accelerator (the BVH) on a warped bench mesh: the time step of
// a deformed shape (every vertex moved by a smooth warp of 2% of the part's size, same faces), on 1
// and 2 threads, with the SAH cost of the refitted tree over the rebuilt one's.
//   build/bench/bvh_refit_bench --benchmark_filter=1m      (LANCER_BENCH_MESHES=1m, as the other benches)
#include <cmath>

#include "accel_bench_support.hpp"

namespace lancer::bench {
namespace {

std::vector<Vec3> warped(const Mesh& mesh, const Aabb& box) {
  const float amount = 0.02f * maxComponent(box.extent());
  const Vec3 e = box.extent();
  const Vec3 scale{6.2832f / std::max(e.x, 1e-6f), 6.2832f / std::max(e.y, 1e-6f),
                   6.2832f / std::max(e.z, 1e-6f)};
  std::vector<Vec3> out = mesh.positions;
  for (Vec3& p : out) {
    const Vec3 d = p - box.lower;
    const Vec3 q{d.x * scale.x, d.y * scale.y, d.z * scale.z};
    p = p + Vec3{std::sin(q.y), std::sin(q.z + 1.0f), std::cos(q.x)} * amount;
  }
  return out;
}

void registerRefit(const std::string& mesh) {
  for (int threads : {1, 2}) {
    for (const bool refit : {true, false}) {
      benchmark::RegisterBenchmark(
          ((refit ? "refit/bvh/" : "rebuild/bvh/") + mesh + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            static std::vector<Vec3> moved;
            static std::string movedOf;
            if (movedOf != mesh) {
              moved = warped(ctx.mesh, ctx.box);
              movedOf = mesh;
            }
            BvhBuildOptions options;
            options.threads = threads;
            Bvh bvh = Bvh::build(ctx.mesh.positions, ctx.mesh.faces, options);
            double growth = 0;
            for (auto _ : state) {
              const auto start = std::chrono::steady_clock::now();
              if (refit) {
                if (!bvh.refit(moved, ctx.mesh.faces, threads)) state.SkipWithError("refit refused");
              } else {
                bvh = Bvh::build(moved, ctx.mesh.faces, options);
              }
              state.SetIterationTime(
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
              growth = refit
                           ? bvh.stats().sahCost / Bvh::build(moved, ctx.mesh.faces, options).stats().sahCost
                           : 1.0;
            }
            state.counters["sah_vs_rebuild"] = growth;
            state.counters["triangles"] = double(bvh.stats().triangles);
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace
}  // namespace lancer::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (const std::string& mesh : lancer::bench::meshNames()) lancer::bench::registerRefit(mesh);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
