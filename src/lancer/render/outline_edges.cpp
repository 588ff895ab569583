#include "lancer/render/outline_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "lancer/render/edge_overlay.hpp"

namespace lancer {
namespace {

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace

OutlineEdges::OutlineEdges(const Scene& scene, const Camera& camera, int imageWidth, int imageHeight)
    : scene_(&scene), camera_(&camera) {
  if (scene.edgeStyles.size() <= 1 || scene.faceEdgeStyle.empty()) return;
  // The drawn edges and the faces on each (a drawn edge is marked by every element it belongs to).
  struct Sides {
    std::uint32_t faces[2] = {kNoFace, kNoFace};
    int count = 0;
  };
  std::unordered_map<std::uint64_t, Sides> edges;
  for (std::uint32_t f = 0; f < scene.faces.size(); ++f) {
    if (scene.faceEdgeStyle[f] == 0) continue;
    const MeshFace& face = scene.faces[f];
    const int n = face.cornerCount();
    for (int i = 0; i < n; ++i) {
      if (!(scene.faceEdgeMask[f] & (1u << i))) continue;
      Sides& sides = edges[edgeKey(face.vertex[i], face.vertex[(i + 1) % n])];
      if (sides.count < 2) sides.faces[sides.count] = f;
      ++sides.count;
    }
  }
  // Which side of each face the eye is on; an outline edge has one face, or faces on both sides
  // (more than two faces: taken as an outline when its first two disagree).
  const bool perspective = camera.projection() == Projection::Perspective;
  auto facesEye = [&](std::uint32_t f) {
    const Vec3& corner = scene.positions[scene.faces[f].vertex[0]];
    const Vec3 toEye = perspective ? camera.position() - corner : -camera.forward();
    return dot(scene.faceNormals[f], toEye) > 0.0f;
  };
  for (const auto& [key, sides] : edges) {
    if (sides.count == 2 && facesEye(sides.faces[0]) == facesEye(sides.faces[1])) continue;
    Segment segment;
    segment.a = scene.positions[static_cast<std::uint32_t>(key >> 32)];
    segment.b = scene.positions[static_cast<std::uint32_t>(key & 0xFFFFFFFFu)];
    segment.faces[0] = sides.faces[0];
    segment.faces[1] = sides.count >= 2 ? sides.faces[1] : kNoFace;
    segment.style = scene.faceEdgeStyle[sides.faces[0]];
    segments_.push_back(segment);
  }
  if (segments_.empty()) return;
  // Stable order whatever the hash map did: images are deterministic.
  std::sort(segments_.begin(), segments_.end(), [](const Segment& l, const Segment& r) {
    return l.faces[0] != r.faces[0] ? l.faces[0] < r.faces[0] : l.faces[1] < r.faces[1];
  });

  // Bin each segment's screen box, widened by half its line and a pixel, in cells (two passes:
  // count, then fill).
  cellsX_ = (imageWidth + kCellPixels - 1) / kCellPixels;
  cellsY_ = (imageHeight + kCellPixels - 1) / kCellPixels;
  std::vector<std::array<int, 4>> boxes(segments_.size(), {0, -1, 0, -1});
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    float ax, ay, bx, by;
    // An edge crossing the plane of a perspective eye is skipped (it cannot lie along the outline
    // of anything in view).
    if (!camera.project(segments_[s].a, ax, ay) || !camera.project(segments_[s].b, bx, by)) continue;
    const float margin = 0.5f * scene.edgeStyles[segments_[s].style].widthPixels + 1.0f;
    const auto cell = [](float v) { return static_cast<int>(std::floor(v / kCellPixels)); };
    boxes[s] = {std::max(cell(std::min(ax, bx) - margin), 0), std::min(cell(std::max(ax, bx) + margin), cellsX_ - 1),
                std::max(cell(std::min(ay, by) - margin), 0), std::min(cell(std::max(ay, by) + margin), cellsY_ - 1)};
  }
  cellStart_.assign(static_cast<std::size_t>(cellsX_) * cellsY_ + 1, 0);
  for (const auto& box : boxes)
    for (int y = box[2]; y <= box[3]; ++y)
      for (int x = box[0]; x <= box[1]; ++x) ++cellStart_[static_cast<std::size_t>(y) * cellsX_ + x + 1];
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  cellSegments_.resize(cellStart_.back());
  std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t s = 0; s < segments_.size(); ++s)
    for (int y = boxes[s][2]; y <= boxes[s][3]; ++y)
      for (int x = boxes[s][0]; x <= boxes[s][1]; ++x)
        cellSegments_[fill[static_cast<std::size_t>(y) * cellsX_ + x]++] = static_cast<std::uint32_t>(s);
}

int OutlineEdges::cellOf(const Ray& ray) const {
  float x = 0, y = 0;
  if (!camera_->project(ray.origin + ray.direction, x, y)) return -1;
  const int cx = static_cast<int>(std::floor(x / kCellPixels)), cy = static_cast<int>(std::floor(y / kCellPixels));
  if (cx < 0 || cy < 0 || cx >= cellsX_ || cy >= cellsY_) return -1;
  return cy * cellsX_ + cx;
}

bool OutlineEdges::near(const Ray& ray) const {
  if (segments_.empty()) return false;
  const int cell = cellOf(ray);
  return cell >= 0 && cellStart_[static_cast<std::size_t>(cell) + 1] > cellStart_[static_cast<std::size_t>(cell)];
}

float OutlineEdges::coverage(const Ray& ray, std::uint32_t hitFace, float hitDistance,
                             const PixelFootprint& footprint, Vec3& color) const {
  const int cell = cellOf(ray);
  if (cell < 0) return 0.0f;
  const Vec3 direction = normalize(ray.direction);
  float best = 0.0f;
  for (std::uint32_t i = cellStart_[static_cast<std::size_t>(cell)]; i < cellStart_[static_cast<std::size_t>(cell) + 1];
       ++i) {
    const Segment& segment = segments_[cellSegments_[i]];
    if (hitFace != kNoFace && (segment.faces[0] == hitFace || segment.faces[1] == hitFace)) continue;  // drawn
    // The segment's point nearest the ray: in front of what the ray hit, and not cut away.
    const Vec3 w = segment.a - ray.origin, e = segment.b - segment.a;
    const Vec3 wAcross = w - direction * dot(w, direction), eAcross = e - direction * dot(e, direction);
    const float eLength2 = dot(eAcross, eAcross);
    const float u = eLength2 > 0.0f ? std::clamp(-dot(wAcross, eAcross) / eLength2, 0.0f, 1.0f) : 0.0f;
    const Vec3 nearest = segment.a + e * u;
    const float along = dot(nearest - ray.origin, direction);
    if (!(along > 0.0f) || !(along < hitDistance)) continue;
    if (isClipped(nearest, scene_->clipPlanes)) continue;
    if (const FaceClipRange* range = scene_->meshClips.rangeOf(segment.faces[0]);
        range != nullptr && isClipped(nearest, scene_->meshClips.planesOf(*range)))
      continue;
    const EdgeStyle& style = scene_->edgeStyles[segment.style];
    const float pixels = length(wAcross + eAcross * u) / footprint.at(along);
    const float covered = lineCoverage(pixels, style.widthPixels);
    if (covered > best) {
      best = covered;
      color = style.color;
    }
  }
  return best;
}

}  // namespace lancer
