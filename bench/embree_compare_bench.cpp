// lancer's default accelerator (the BVH) and its SAH kd-tree against Intel Embree 3 on the same meshes
// and ray sets, in the same process, so bench/run_accel_bench.sh can print lancer/Embree ratios
// measured side by side: builds (Embree HIGH and MEDIUM), single rays (rtcIntersect1 / rtcOccluded1,
// HIGH's tree) and packets of eight of the same rays (lancer's packet queries against rtcIntersect8 /
// rtcOccluded8).
#include <embree3/rtcore.h>

#include <stdexcept>

#include "accel_bench_support.hpp"

namespace lancer::bench {
namespace {

std::atomic<std::int64_t> embreeBytes{0};

bool trackMemory(void*, ssize_t bytes, bool) {
  embreeBytes += bytes;
  return true;
}

// An Embree scene of the mesh's triangles (quads split like lancer's), sharing the mesh's buffers.
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<float> vertices;  // x, y, z, pad: Embree reads 16 bytes past the last vertex
  std::vector<std::uint32_t> indices;
  double buildSeconds = 0;
  std::int64_t bytes = 0;

  EmbreeScene(const Mesh& mesh, int threads, RTCBuildQuality quality = RTC_BUILD_QUALITY_HIGH) {
    device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
    if (!device) throw std::runtime_error("rtcNewDevice failed");
    rtcSetDeviceMemoryMonitorFunction(device, trackMemory, nullptr);
    for (const Vec3& p : mesh.positions) vertices.insert(vertices.end(), {p.x, p.y, p.z, 0.0f});
    for (const MeshFace& f : mesh.faces) {
      indices.insert(indices.end(), {f.vertex[0], f.vertex[1], f.vertex[2]});
      if (f.isQuad()) indices.insert(indices.end(), {f.vertex[0], f.vertex[2], f.vertex[3]});
    }
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t before = embreeBytes;
    scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, quality);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, quality);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0,
                               4 * sizeof(float), mesh.positions.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0,
                               3 * sizeof(std::uint32_t), indices.size() / 3);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bytes = embreeBytes - before;
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  bool intersect(const Ray& ray, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    setRay(rh.ray, ray, tMin, tMax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  bool occluded(const Ray& ray, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    setRay(r, ray, tMin, tMax);
    rtcOccluded1(scene, &context, &r);
    return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
  }
  // Embree's own packets on the same rays (rtcIntersect8 / rtcOccluded8, coherent context):
  // the lanes that hit.
  std::uint32_t intersect8(const RayPacket& packet, std::uint32_t active) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) int valid[kPacketSize];
    alignas(32) RTCRayHit8 rh;
    setRays(rh.ray, valid, packet, active);
    for (int i = 0; i < kPacketSize; ++i) rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect8(valid, scene, &context, &rh);
    std::uint32_t hit = 0;
    for (int i = 0; i < kPacketSize; ++i)
      hit |= valid[i] && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID ? 1u << i : 0u;
    return hit;
  }
  std::uint32_t occluded8(const RayPacket& packet, std::uint32_t active) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) int valid[kPacketSize];
    alignas(32) RTCRay8 r;
    setRays(r, valid, packet, active);
    rtcOccluded8(valid, scene, &context, &r);
    std::uint32_t hit = 0;
    for (int i = 0; i < kPacketSize; ++i) hit |= valid[i] && r.tfar[i] < 0.0f ? 1u << i : 0u;
    return hit;
  }
  static void setRays(RTCRay8& r, int* valid, const RayPacket& packet, std::uint32_t active) {
    for (int i = 0; i < kPacketSize; ++i) {
      const Ray& ray = packet.ray[i];
      valid[i] = (active >> i & 1u) != 0 ? -1 : 0;
      r.org_x[i] = ray.origin.x;
      r.org_y[i] = ray.origin.y;
      r.org_z[i] = ray.origin.z;
      r.dir_x[i] = ray.direction.x;
      r.dir_y[i] = ray.direction.y;
      r.dir_z[i] = ray.direction.z;
      r.tnear[i] = packet.tMin[i];
      r.tfar[i] = packet.tMax[i];
      r.time[i] = 0.0f;
      r.mask[i] = 0xFFFFFFFFu;
      r.id[i] = 0;
      r.flags[i] = 0;
    }
  }
  static void setRay(RTCRay& r, const Ray& ray, float tMin, float tMax) {
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = tMin;
    r.tfar = tMax;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
  }
};

void registerEmbree(const std::string& mesh) {
  for (const auto& [name, quality] : {std::pair{"embree-high", RTC_BUILD_QUALITY_HIGH},
                                      std::pair{"embree-medium", RTC_BUILD_QUALITY_MEDIUM}}) {
    for (int threads : {1, 2}) {
      benchmark::RegisterBenchmark(
          ("build/" + std::string(name) + "/" + mesh + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            double seconds = 0;
            std::int64_t bytes = 0;
            std::size_t triangles = 0;
            for (auto _ : state) {
              EmbreeScene scene(ctx.mesh, threads, quality);
              seconds = scene.buildSeconds;
              bytes = scene.bytes;
              triangles = scene.indices.size() / 3;
              state.SetIterationTime(seconds);
            }
            state.counters["Mtris_per_s"] = double(triangles) / seconds * 1e-6;
            state.counters["triangles"] = double(triangles);
            state.counters["bytes_per_tri"] = double(bytes) / double(triangles);
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
  }
  static std::map<std::string, std::shared_ptr<EmbreeScene>> scenes;
  for (const char* rayKind : kRayKinds) {
    for (int threads : {1, 2}) {
      const std::string rk = rayKind;
      benchmark::RegisterBenchmark(
          ("trace/embree-high/" + mesh + "/" + rk + "/threads:" + std::to_string(threads)).c_str(),
          [=](benchmark::State& state) {
            MeshContext& ctx = meshContext(mesh);
            if (!scenes.count(mesh)) {
              scenes.clear();  // one mesh's scene in memory at a time
              scenes[mesh] = std::make_shared<EmbreeScene>(ctx.mesh, 2);
            }
            const RaySet& set = ctx.rays(rk);
            const EmbreeScene& s = *scenes[mesh];
            if (set.anyHit) {
              traceBenchmark(state, set, threads,
                             [&](const Ray& r, float t0, float t1) { return s.occluded(r, t0, t1); });
            } else {
              traceBenchmark(state, set, threads,
                             [&](const Ray& r, float t0, float t1) { return s.intersect(r, t0, t1); });
            }
          })
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

void registerEmbreePackets(const std::string& mesh) {
  static std::map<std::string, std::shared_ptr<EmbreeScene>> scenes;
  registerPacketRows("embree-high", mesh, [mesh](MeshContext& ctx, bool anyHit) {
    if (!scenes.count(mesh)) {
      scenes.clear();
      scenes[mesh] = std::make_shared<EmbreeScene>(ctx.mesh, 2);
    }
    const EmbreeScene* s = scenes[mesh].get();
    return [s, anyHit](const RayPacket& packet, std::uint32_t active) {
      return anyHit ? s->occluded8(packet, active) : s->intersect8(packet, active);
    };
  });
}

}  // namespace
}  // namespace lancer::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (const std::string& mesh : lancer::bench::meshNames()) {
    lancer::bench::registerLancer("bvh", mesh);
    lancer::bench::registerLancerInFlight(mesh);
    lancer::bench::registerLancer("kdtree-sah", mesh);
    lancer::bench::registerEmbree(mesh);
    lancer::bench::registerLancerPackets("bvh", mesh);
    lancer::bench::registerLancerPackets("kdtree-sah", mesh);
    lancer::bench::registerEmbreePackets(mesh);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
