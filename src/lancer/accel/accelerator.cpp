#include "lancer/accel/accelerator.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "lancer/util/stopwatch.hpp"

namespace lancer {

AccelKind parseAccelKind(std::string_view name) {
  if (name == "kdtree-sah") return AccelKind::KdTreeSah;
  if (name == "kdtree-median") return AccelKind::KdTreeMedian;
  if (name == "naive") return AccelKind::Naive;
  throw std::invalid_argument("unknown accelerator '" + std::string(name) +
                              "': expected kdtree-sah, kdtree-median or naive");
}

std::string_view accelKindName(AccelKind kind) {
  switch (kind) {
    case AccelKind::KdTreeSah:
      return "kdtree-sah";
    case AccelKind::KdTreeMedian:
      return "kdtree-median";
    case AccelKind::Naive:
      return "naive";
  }
  return "unknown";
}

bool Accelerator::intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const {
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(ray, tMin, tMax, filter, hit);
  return std::get<NaiveAccel>(impl_).intersect(ray, tMin, tMax, filter, hit);
}

bool Accelerator::occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const {
  if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->occluded(ray, tMin, tMax, filter);
  return std::get<NaiveAccel>(impl_).occluded(ray, tMin, tMax, filter);
}

Accelerator Accelerator::build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                               AccelKind kind, const KdBuildOptions& options) {
  switch (kind) {
    case AccelKind::KdTreeSah: {
      KdTree tree = KdTree::buildSah(positions, faces, options);
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

}  // namespace lancer
