#include "lancer/scene/geometry_overlap.hpp"

#include <utility>

namespace lancer {

GeometryOverlap::~GeometryOverlap() { abandon(); }

void GeometryOverlap::start(std::span<const Vec3> positions, std::span<const MeshFace> faces) {
  started_ = true;
  running_ = std::async(std::launch::async, [this, positions, faces] { task_(positions, faces); });
}

void GeometryOverlap::facesChanged(std::vector<MeshFace> given) {
  stale_ = true;
  heldFaces_ = std::move(given);
}

void GeometryOverlap::abandon() noexcept {
  if (!running_.valid()) return;
  running_.wait();
  try {
    running_.get();
  } catch (...) {  // dropped: the error that unwinds is the caller's
  }
}

bool GeometryOverlap::finish() {
  if (!started_) return false;
  if (running_.valid()) running_.get();
  std::vector<MeshFace>().swap(heldFaces_);
  return !stale_;
}

}  // namespace lancer
