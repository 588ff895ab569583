#include "lancer/accel/accelerator.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "lancer/util/stopwatch.hpp"

namespace lancer {

AccelKind parseAccelKind(std::string_view name) {
  std::string expected;
  for (std::size_t k = 0; k < kAccelNames.size(); ++k) {
    if (name == kAccelNames[k]) return static_cast<AccelKind>(k);
    expected += k == 0 ? "" : (k + 1 == kAccelNames.size() ? " or " : ", ");
    expected += kAccelNames[k];
  }
  throw std::invalid_argument("unknown accelerator '" + std::string(name) + "': expected " + expected);
}

std::string_view accelKindName(AccelKind kind) {
  const auto k = static_cast<std::size_t>(kind);
  return k < kAccelNames.size() ? kAccelNames[k] : "unknown";
}

bool Accelerator::intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->intersect(ray, tMin, tMax, filter, hit);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(ray, tMin, tMax, filter, hit);
  return std::get<NaiveAccel>(impl_).intersect(ray, tMin, tMax, filter, hit);
}

bool Accelerator::occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->occluded(ray, tMin, tMax, filter);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->occluded(ray, tMin, tMax, filter);
  return std::get<NaiveAccel>(impl_).occluded(ray, tMin, tMax, filter);
}

namespace {

// A packet query of the brute-force reference: lane by lane.
template <typename Query>
std::uint32_t laneByLane(std::uint32_t active, Query&& query) {
  std::uint32_t answered = 0;
  for (int i = 0; i < kPacketSize; ++i) {
    if ((active >> i & 1u) != 0 && query(i)) answered |= 1u << i;
  }
  return answered;
}

}  // namespace

std::uint32_t Accelerator::intersect(const RayPacket& packet, std::uint32_t active,
                                     std::span<Hit, kPacketSize> hits) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->intersect(packet, active, hits);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(packet, active, hits);
  const NaiveAccel& naive = std::get<NaiveAccel>(impl_);
  return laneByLane(
      active, [&](int i) { return naive.intersect(packet.ray[i], packet.tMin[i], packet.tMax[i], hits[i]); });
}

std::uint32_t Accelerator::occluded(const RayPacket& packet, std::uint32_t active) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->occluded(packet, active);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->occluded(packet, active);
  const NaiveAccel& naive = std::get<NaiveAccel>(impl_);
  return laneByLane(active,
                    [&](int i) { return naive.occluded(packet.ray[i], packet.tMin[i], packet.tMax[i]); });
}

std::uint32_t Accelerator::intersect(const RayPacket& packet, std::uint32_t active, const HitFilter& filter,
                                     std::span<Hit, kPacketSize> hits) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->intersect(packet, active, filter, hits);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(packet, active, filter, hits);
  const NaiveAccel& naive = std::get<NaiveAccel>(impl_);
  return laneByLane(active, [&](int i) {
    return naive.intersect(packet.ray[i], packet.tMin[i], packet.tMax[i], filter, hits[i]);
  });
}

std::uint32_t Accelerator::occluded(const RayPacket& packet, std::uint32_t active,
                                    const HitFilter& filter) const {
  if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->occluded(packet, active, filter);
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->occluded(packet, active, filter);
  const NaiveAccel& naive = std::get<NaiveAccel>(impl_);
  return laneByLane(
      active, [&](int i) { return naive.occluded(packet.ray[i], packet.tMin[i], packet.tMax[i], filter); });
}

Accelerator Accelerator::build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                               AccelKind kind, const KdBuildOptions& options) {
  switch (kind) {
    case AccelKind::Bvh: {
      BvhBuildOptions bvhOptions;
      bvhOptions.threads = options.threads;
      Bvh bvh = Bvh::build(positions, faces, bvhOptions);
      AccelStats stats = bvh.stats();
      return Accelerator(std::move(bvh), kind, std::move(stats));
    }
    case AccelKind::KdTreeSah: {
      KdTree tree = KdTree::buildSah(positions, faces, options);
      AccelStats stats = tree.stats();
      return Accelerator(std::move(tree), kind, std::move(stats));
    }
    case AccelKind::KdTreeSahExact: {
      KdTree tree = KdTree::buildSahExact(positions, faces, options);
      AccelStats stats = tree.stats();
      return Accelerator(std::move(tree), kind, std::move(stats));
    }
    case AccelKind::KdTreeMedian: {
      KdTree tree = KdTree::buildMedian(positions, faces, options);
      AccelStats stats = tree.stats();
      return Accelerator(std::move(tree), kind, std::move(stats));
    }
    case AccelKind::Naive:
      break;
  }
  const Stopwatch stopwatch;
  NaiveAccel naive(positions, faces);
  AccelStats stats;
  stats.kind = "naive";
  stats.faces = faces.size();
  for (const MeshFace& face : faces) stats.triangles += face.isQuad() ? 2 : 1;
  stats.nodes = stats.leaves = 1;
  stats.triangleReferences = stats.triangles;
  stats.meanTrianglesPerLeaf = double(stats.triangles);
  stats.sahCost = options.intersectionCost * double(stats.triangles);
  stats.bytes = naive.memoryBytes();
  stats.buildSeconds = stopwatch.seconds();
  return Accelerator(std::move(naive), kind, std::move(stats));
}

bool Accelerator::update(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                         const KdBuildOptions& options) {
  if (Bvh* bvh = std::get_if<Bvh>(&impl_)) {
    const Stopwatch stopwatch;
    if (bvh->refit(positions, faces, options.threads) && !bvh->rebuildPays()) {
      stats_ = bvh->stats();
      stats_.buildSeconds = stopwatch.seconds();
      return true;
    }
  }
  *this = build(positions, faces, kind_, options);
  return false;
}

}  // namespace lancer
