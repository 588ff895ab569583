#include "lancer/render/outline_edges.hpp"

#include <algorithm>
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
  if (!scene.edges) return;
  const EdgeOverlay& overlay = *scene.edges;
  // The drawn edges and the faces on each (a drawn edge is marked by every element it belongs to).
  struct Sides {
    std::uint32_t faces[2] = {kNoFace, kNoFace};
    int count = 0;
  };
  std::unordered_map<std::uint64_t, Sides> edges;
  for (std::uint32_t f = 0; f < scene.geometry.faces.size(); ++f) {
    if (overlay.faceEdgeStyle[f] == 0) continue;
    const MeshFace& face = scene.geometry.faces[f];
    const int n = face.cornerCount();
    for (int i = 0; i < n; ++i) {
      if (!(overlay.faceEdgeMask[f] & (1u << i))) continue;
      Sides& sides = edges[edgeKey(face.vertex[i], face.vertex[(i + 1) % n])];
      if (sides.count < 2) sides.faces[sides.count] = f;
      ++sides.count;
    }
  }
  // Which side of each face the eye is on; an outline edge has one face, or faces on both sides
  // (more than two faces: taken as an outline when its first two disagree).
  const bool perspective = camera.projection() == Projection::Perspective;
  auto facesEye = [&](std::uint32_t f) {
    const Vec3& corner = scene.geometry.positions[scene.geometry.faces[f].vertex[0]];
    const Vec3 toEye = perspective ? camera.position() - corner : -camera.forward();
    return dot(scene.geometry.faceNormals[f], toEye) > 0.0f;
  };
  for (const auto& [key, sides] : edges) {
    if (sides.count == 2 && facesEye(sides.faces[0]) == facesEye(sides.faces[1])) continue;
    Segment segment;
    segment.a = scene.geometry.positions[static_cast<std::uint32_t>(key >> 32)];
    segment.b = scene.geometry.positions[static_cast<std::uint32_t>(key & 0xFFFFFFFFu)];
    segment.faces[0] = sides.faces[0];
    segment.faces[1] = sides.count >= 2 ? sides.faces[1] : kNoFace;
    segment.style = overlay.faceEdgeStyle[sides.faces[0]];
    segments_.push_back(segment);
  }
  if (segments_.empty()) return;
  // Stable order whatever the hash map did: images are deterministic.
  std::sort(segments_.begin(), segments_.end(), [](const Segment& l, const Segment& r) {
    return l.faces[0] != r.faces[0] ? l.faces[0] < r.faces[0] : l.faces[1] < r.faces[1];
  });

  // Bin each segment in the cells within half its line and a pixel of it, walking it on screen in
  // steps of half a cell, so the entries grow with its length, not with its screen box; two passes
  // (count, then fill), each cell taking a segment once. Cells grow with the image so that a huge
  // image keeps at most about kMaxCellsAcross^2 of them.
  cellPixels_ =
      std::max(kMinCellPixels, (std::max(imageWidth, imageHeight) + kMaxCellsAcross - 1) / kMaxCellsAcross);
  cellsX_ = (imageWidth + cellPixels_ - 1) / cellPixels_;
  cellsY_ = (imageHeight + cellPixels_ - 1) / cellPixels_;
  const std::size_t cellCount = static_cast<std::size_t>(cellsX_) * static_cast<std::size_t>(cellsY_);
  std::vector<std::uint32_t> lastSegment(cellCount, kNoFace);
  auto visitCells = [&](std::uint32_t s, auto&& onCell) {
    float ax, ay, bx, by;
    // An edge crossing the plane of a perspective eye is skipped (not binned).
    if (!camera.project(segments_[s].a, ax, ay) || !camera.project(segments_[s].b, bx, by)) return;
    const float margin = 0.5f * overlay.styles[segments_[s].style].widthPixels + 1.0f;
    // Liang-Barsky: the part of the segment inside the image widened by the margin.
    float t0 = 0.0f, t1 = 1.0f;
    const float dx = bx - ax, dy = by - ay;
    const float p[4] = {-dx, dx, -dy, dy};
    const float q[4] = {ax + margin, static_cast<float>(imageWidth) + margin - ax, ay + margin,
                        static_cast<float>(imageHeight) + margin - ay};
    for (int k = 0; k < 4; ++k) {
      if (p[k] == 0.0f) {
        if (q[k] < 0.0f) return;
        continue;
      }
      const float r = q[k] / p[k];
      if (p[k] < 0.0f)
        t0 = std::max(t0, r);
      else
        t1 = std::min(t1, r);
    }
    if (!(t0 <= t1)) return;
    const float length = std::hypot(dx, dy) * (t1 - t0);
    const int steps = static_cast<int>(std::ceil(length / (0.5f * static_cast<float>(cellPixels_)))) + 1;
    const auto cell = [&](float v, int count) {
      return std::clamp(static_cast<int>(std::floor(v / static_cast<float>(cellPixels_))), 0, count - 1);
    };
    // A pixel within the margin of the segment is within reach + a quarter cell of some step.
    const float reach = margin + 0.25f * static_cast<float>(cellPixels_);
    for (int i = 0; i <= steps; ++i) {
      const float t = t0 + (t1 - t0) * static_cast<float>(i) / static_cast<float>(steps);
      const float x = ax + dx * t, y = ay + dy * t;
      for (int cy = cell(y - reach, cellsY_); cy <= cell(y + reach, cellsY_); ++cy) {
        for (int cx = cell(x - reach, cellsX_); cx <= cell(x + reach, cellsX_); ++cx) {
          const std::size_t c =
              static_cast<std::size_t>(cy) * static_cast<std::size_t>(cellsX_) + static_cast<std::size_t>(cx);
          if (lastSegment[c] == s) continue;
          lastSegment[c] = s;
          onCell(c);
        }
      }
    }
  };
  cellStart_.assign(cellCount + 1, 0);
  for (std::uint32_t s = 0; s < segments_.size(); ++s)
    visitCells(s, [&](std::size_t c) { ++cellStart_[c + 1]; });
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  cellSegments_.resize(cellStart_.back());
  std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  std::fill(lastSegment.begin(), lastSegment.end(), kNoFace);
  for (std::uint32_t s = 0; s < segments_.size(); ++s)
    visitCells(s, [&](std::size_t c) { cellSegments_[fill[c]++] = s; });
}

int OutlineEdges::cellOf(const Ray& ray) const {
  float x = 0, y = 0;
  if (!camera_->project(ray.origin + ray.direction, x, y)) return -1;
  const int cx = static_cast<int>(std::floor(x / static_cast<float>(cellPixels_)));
  const int cy = static_cast<int>(std::floor(y / static_cast<float>(cellPixels_)));
  if (cx < 0 || cy < 0 || cx >= cellsX_ || cy >= cellsY_) return -1;
  return cy * cellsX_ + cx;
}

bool OutlineEdges::near(const Ray& ray) const {
  if (segments_.empty()) return false;
  const int cell = cellOf(ray);
  return cell >= 0 &&
         cellStart_[static_cast<std::size_t>(cell) + 1] > cellStart_[static_cast<std::size_t>(cell)];
}

float OutlineEdges::coverage(const Ray& ray, std::uint32_t hitFace, float hitDistance,
                             const PixelFootprint& footprint, Vec3& color) const {
  const int cell = cellOf(ray);
  if (cell < 0) return 0.0f;
  const Vec3 direction = normalize(ray.direction);
  float best = 0.0f;
  for (std::uint32_t i = cellStart_[static_cast<std::size_t>(cell)];
       i < cellStart_[static_cast<std::size_t>(cell) + 1]; ++i) {
    const Segment& segment = segments_[cellSegments_[i]];
    if (hitFace != kNoFace && (segment.faces[0] == hitFace || segment.faces[1] == hitFace))
      continue;  // drawn
    // The segment's point nearest the ray: in front of what the ray hit, and not cut away.
    const Vec3 w = segment.a - ray.origin, e = segment.b - segment.a;
    const Vec3 wAcross = w - direction * dot(w, direction), eAcross = e - direction * dot(e, direction);
    const float eLength2 = dot(eAcross, eAcross);
    const float u = eLength2 > 0.0f ? std::clamp(-dot(wAcross, eAcross) / eLength2, 0.0f, 1.0f) : 0.0f;
    const Vec3 nearest = segment.a + e * u;
    const float along = dot(nearest - ray.origin, direction);
    if (!(along > 0.0f) || !(along < hitDistance)) continue;
    if (isClipped(nearest, scene_->clipping.planes)) continue;
    if (const FaceClipRange* range = scene_->clipping.perMesh.rangeOf(segment.faces[0]);
        range != nullptr && isClipped(nearest, scene_->clipping.perMesh.planesOf(*range)))
      continue;
    const EdgeStyle& style = scene_->edges->styles[segment.style];
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
