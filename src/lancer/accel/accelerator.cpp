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

Accelerator Accelerator::kdTree(KdTree tree, AccelKind kind) {
  AccelStats stats = tree.stats();
  return Accelerator(std::move(tree), kind, std::move(stats));
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
    case AccelKind::KdTreeSah:
      return kdTree(KdTree::buildSah(positions, faces, options), kind);
    case AccelKind::KdTreeSahExact:
      return kdTree(KdTree::buildSahExact(positions, faces, options), kind);
    case AccelKind::KdTreeMedian:
      return kdTree(KdTree::buildMedian(positions, faces, options), kind);
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
                         const KdBuildOptions& options, const std::function<void()>& beforeBuild) {
  if (Bvh* bvh = std::get_if<Bvh>(&impl_)) {
    const Stopwatch stopwatch;
    if (bvh->refit(positions, faces, options.threads) && !bvh->rebuildPays()) {
      stats_ = bvh->stats();
      stats_.buildSeconds = stopwatch.seconds();
      return true;
    }
  }
  // The old tree goes before the new one is built: two trees of a large mesh at once would raise the
  // peak memory by a whole tree (an animation's warped frames rebuild when a refit no longer pays).
  impl_ = NaiveAccel({}, {});
  if (beforeBuild) beforeBuild();
  *this = build(positions, faces, kind_, options);
  return false;
}

}  // namespace lancer
