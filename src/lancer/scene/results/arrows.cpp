#include "lancer/scene/results/arrows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <unordered_map>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/scene/face_elements.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/color_by.hpp"

namespace lancer {
namespace {

// The arrow's proportions, relative to its length.
constexpr double kShaftRadius = 0.05;
constexpr double kHeadRadius = 0.12;
constexpr double kHeadLength = 0.3;

Vec3d vectorAt(const MeshField& field, std::uint32_t vertex) {
  const std::size_t i = static_cast<std::size_t>(vertex) * 3;
  return {field.values[i], field.values[i + 1], field.values[i + 2]};
}

bool usable(const Vec3d& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && length(v) > 0;
}

// Appends one arrow from `base` along unit `direction`, `arrowLength` long, with `magnitude` as its
// vertices' field value.
void appendArrow(Mesh& out, std::vector<float>& values, const Vec3d& base, const Vec3d& direction,
                 double arrowLength, float magnitude) {
  // An orthonormal frame around the direction (Duff et al., "Building an Orthonormal Basis, Revisited").
  const double sign = std::copysign(1.0, direction.z);
  const double a = -1.0 / (sign + direction.z), b = direction.x * direction.y * a;
  const Vec3d u{1 + sign * direction.x * direction.x * a, sign * b, -sign * direction.x};
  const Vec3d w{b, sign + direction.y * direction.y * a, -direction.y};
  const double shaftR = kShaftRadius * arrowLength, headR = kHeadRadius * arrowLength;
  const Vec3d neck = base + direction * (arrowLength * (1 - kHeadLength));
  const Vec3d tip = base + direction * arrowLength;
  const auto first = static_cast<std::uint32_t>(out.positions.size());
  auto add = [&](const Vec3d& p) {
    out.positions.push_back(toFloat(p - out.origin));
    values.push_back(magnitude);
  };
  // Rings: base (shaft), neck (shaft), neck (head); then the base centre and the tip.
  for (const auto& [centre, radius] :
       {std::pair{base, shaftR}, std::pair{neck, shaftR}, std::pair{neck, headR}})
    for (int k = 0; k < kArrowSides; ++k) {
      const double angle = 2 * std::numbers::pi * k / kArrowSides;
      add(centre + (u * std::cos(angle) + w * std::sin(angle)) * radius);
    }
  add(base);
  add(tip);
  const std::uint32_t baseCentre = first + 3 * kArrowSides, tipVertex = baseCentre + 1;
  auto ring = [&](int r, int k) {
    return first + static_cast<std::uint32_t>(r * kArrowSides + (k % kArrowSides));
  };
  auto triangle = [&](std::uint32_t p, std::uint32_t q, std::uint32_t s) {
    out.faces.push_back(MeshFace{{p, q, s, kNoVertex}});
  };
  for (int k = 0; k < kArrowSides; ++k) {
    triangle(baseCentre, ring(0, k + 1), ring(0, k));      // the shaft's bottom, facing back
    triangle(ring(0, k), ring(0, k + 1), ring(1, k + 1));  // the shaft's side
    triangle(ring(0, k), ring(1, k + 1), ring(1, k));
    triangle(ring(1, k), ring(1, k + 1), ring(2, k + 1));  // under the head
    triangle(ring(1, k), ring(2, k + 1), ring(2, k));
    triangle(ring(2, k), ring(2, k + 1), tipVertex);  // the head
  }
}

}  // namespace

namespace {

// One per occupied cell of a grid of cubes over `lower`.., as fine as keeps the occupied cells at
// most maxCount: in each, the point nearest the cell's centre. `points` in the mesh's local frame;
// `area`: the surface's, which sets the first cell size.
struct GridChoice {
  double cellSize = 0;
  std::vector<std::uint32_t> chosen;  // indices into the points, sorted
};
GridChoice chooseOnGrid(const std::vector<Vec3d>& points, const Vec3d& lower, double area, int maxCount) {
  GridChoice choice;
  if (points.empty() || area <= 0) return choice;
  // About maxCount cells of a surface of this area; coarser until the occupied ones are few enough.
  double cell = std::sqrt(area / maxCount);
  for (;;) {
    std::unordered_map<std::uint64_t, std::pair<double, std::uint32_t>> nearest;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      const Vec3d p = points[i] - lower;
      const double cx = std::floor(p.x / cell), cy = std::floor(p.y / cell), cz = std::floor(p.z / cell);
      const std::uint64_t key = (static_cast<std::uint64_t>(cx) << 42) ^
                                (static_cast<std::uint64_t>(cy) << 21) ^ static_cast<std::uint64_t>(cz);
      const Vec3d centre{(cx + 0.5) * cell, (cy + 0.5) * cell, (cz + 0.5) * cell};
      const double d = length(p - centre);
      auto [it, inserted] = nearest.try_emplace(key, d, i);
      if (!inserted && (d < it->second.first || (d == it->second.first && i < it->second.second)))
        it->second = {d, i};
    }
    if (static_cast<int>(nearest.size()) <= maxCount) {
      for (const auto& [key, chosen] : nearest) choice.chosen.push_back(chosen.second);
      std::sort(choice.chosen.begin(), choice.chosen.end());
      choice.cellSize = cell;
      return choice;
    }
    cell *= 1.15;
  }
}

double surfaceArea(const Mesh& mesh) {
  double area = 0;
  for (const MeshFace& face : mesh.faces) {
    const Vec3 e1 = mesh.positions[face.vertex[1]] - mesh.positions[face.vertex[0]];
    const Vec3 e2 = mesh.positions[face.vertex[2]] - mesh.positions[face.vertex[0]];
    area += 0.5 * length(cross(e1, e2)) * (face.isQuad() ? 2 : 1);
  }
  return area;
}

// Where each arrow stands (world coordinates, before a warp) and which of the field's items gives
// its vector: a vertex (node data) or an element's first face (element data).
struct ArrowSites {
  double cellSize = 0;
  std::vector<std::uint32_t> items;
  std::vector<Vec3d> bases;
};

// Element data: one arrow at each element's centroid (a volume's skin: each drawn face of its
// elements); more elements than maxCount are thinned on the grid as vertices are.
ArrowSites elementArrowSites(const Mesh& mesh, const MeshField& field, int maxCount,
                             const std::vector<Vec3d>& positions, const FaceElements& elements) {
  const ElementCentroids centroids = elementCentroids(mesh, elements, positions);
  std::vector<Vec3d> points;
  std::vector<std::uint32_t> elementOf;
  Aabb bounds;
  for (const Vec3& p : mesh.positions) bounds.extend(p);
  for (std::uint32_t e = 0; e < elements.count(); ++e)
    if (usable(vectorAt(field, elements.first[e]))) {
      points.push_back(centroids.centroid[e]);
      elementOf.push_back(e);
    }
  // Every element while they are few enough, the longest arrow then 0.9 of an element's mean size;
  // else as many as the grid keeps.
  const double area = surfaceArea(mesh);
  GridChoice choice;
  if (static_cast<int>(points.size()) <= maxCount) {
    choice.chosen.resize(points.size());
    std::iota(choice.chosen.begin(), choice.chosen.end(), 0u);
    choice.cellSize = points.empty() ? 0 : std::sqrt(area / static_cast<double>(points.size()));
  } else {
    choice = chooseOnGrid(points, toDouble(bounds.lower), area, maxCount);
  }
  ArrowSites sites;
  sites.cellSize = choice.cellSize;
  for (const std::uint32_t i : choice.chosen) {
    sites.items.push_back(elements.first[elementOf[i]]);
    sites.bases.push_back(mesh.origin + points[i]);
  }
  return sites;
}

}  // namespace

ArrowPlacement placeArrows(const Mesh& mesh, const MeshField& field, int maxCount) {
  std::vector<std::uint8_t> used(mesh.positions.size(), 0);
  Aabb bounds;
  for (const MeshFace& face : mesh.faces)
    for (int c = 0; c < face.cornerCount(); ++c) {
      used[face.vertex[c]] = 1;
      bounds.extend(mesh.positions[face.vertex[c]]);
    }
  std::vector<std::uint32_t> candidates;
  std::vector<Vec3d> points;
  for (std::uint32_t v = 0; v < used.size(); ++v)
    if (used[v] && usable(vectorAt(field, v))) {
      candidates.push_back(v);
      points.push_back(toDouble(mesh.positions[v]));
    }
  const GridChoice choice = chooseOnGrid(points, toDouble(bounds.lower), surfaceArea(mesh), maxCount);
  ArrowPlacement placement;
  placement.cellSize = choice.cellSize;
  for (const std::uint32_t i : choice.chosen) placement.vertices.push_back(candidates[i]);
  return placement;
}

Mesh arrowMesh(const ArrowSpec& spec, const Mesh& mesh, const StepSelection& when, const WarpSettings* warp) {
  // Element-node data stands at the nodes by the mean of what the elements give each one.
  const MeshField field =
      vertexMeans(mesh, meshFieldAt("arrows", spec.field, spec.step, mesh, when, spec.where));
  if (field.components != 3)
    throw InputError(
        spec.where,
        fmt::format("arrows field \"{}\" must be a vector of 3 components (node, element or "
                    "element-node data), but it is {} data of {} component{}",
                    spec.field, fieldAtName(field.at), field.components, field.components == 1 ? "" : "s"));
  std::optional<MeshField> displacement;
  if (warp)
    displacement = vertexMeans(mesh, meshFieldAt("warp", warp->field, std::nullopt, mesh, when, warp->where));
  const bool warped = displacement && displacement->components == 3;
  // Where a vertex is drawn: moved by the warp where it gives a finite vector.
  const auto drawnPosition = [&](std::uint32_t v) {
    const Vec3d base = mesh.worldPosition(v);
    if (!warped) return base;
    const Vec3d moved = base + vectorAt(*displacement, v) * warp->factor;
    return std::isfinite(moved.x) && std::isfinite(moved.y) && std::isfinite(moved.z) ? moved : base;
  };
  ArrowSites sites;
  if (field.at == FieldAt::kElement) {
    std::vector<Vec3d> local(mesh.positions.size());
    for (std::uint32_t v = 0; v < local.size(); ++v) local[v] = drawnPosition(v) - mesh.origin;
    sites = elementArrowSites(mesh, field, spec.maxCount, local, faceElements(mesh));
  } else {
    const ArrowPlacement placement = placeArrows(mesh, field, spec.maxCount);
    sites.cellSize = placement.cellSize;
    sites.items = placement.vertices;
    for (const std::uint32_t v : placement.vertices) sites.bases.push_back(drawnPosition(v));
  }
  // The longest arrow of the step shown, or of every step when they follow the scene's: an arrow's
  // length means the same magnitude in every frame of an animation.
  double largest = 0;
  std::vector<const MeshField*> steps{&field};
  if (!spec.step) steps = viewSteps(mesh, spec.field);
  for (const MeshField* step : steps) {
    // A step left in its file (mesh_field.hpp) is not read back for this, nor an element-node step
    // averaged: its largest magnitude over every item, which the reader kept, stands in for the
    // largest at the arrows' items.
    if (step->isStored() || step->at == FieldAt::kCorner)
      largest = std::max(largest, componentRange(*step, FieldComponent{}).second);
    if (step->values.size() == field.values.size())
      for (const std::uint32_t item : sites.items) largest = std::max(largest, length(vectorAt(*step, item)));
  }
  ArrowVectors arrows;
  arrows.cellSize = sites.cellSize;
  arrows.largest = largest;
  arrows.bases = std::move(sites.bases);
  for (const std::uint32_t item : sites.items) arrows.vectors.push_back(vectorAt(field, item));
  return arrowsAlong(spec, arrows, mesh.origin, mesh.source.path, field.time);
}

Mesh arrowsAlong(const ArrowSpec& spec, const ArrowVectors& arrows, const Vec3d& origin,
                 const std::string& path, double time) {
  const double scale =
      spec.scale ? *spec.scale : (arrows.largest > 0 ? 0.9 * arrows.cellSize / arrows.largest : 0);
  Mesh out;
  out.origin = origin;
  out.source.path = path;
  std::vector<float> magnitudes;
  for (std::size_t i = 0; i < arrows.bases.size(); ++i) {
    const Vec3d& vector = arrows.vectors[i];
    if (!usable(vector)) continue;
    const double magnitude = length(vector);
    const double arrowLength = spec.drawsFixedLength() ? 0.8 * arrows.cellSize : scale * magnitude;
    if (!(arrowLength > 0)) continue;
    appendArrow(out, magnitudes, arrows.bases[i], vector * (1 / magnitude), arrowLength,
                static_cast<float>(magnitude));
  }
  out.facePhysicalTag.assign(out.faces.size(), 0);
  out.faceEntityTag.assign(out.faces.size(), 1);
  out.faceEdgeMask.assign(out.faces.size(), kAllEdges);
  MeshField magnitude;
  magnitude.name = spec.field + " magnitude";
  magnitude.step = 0;
  magnitude.time = time;
  magnitude.values = std::move(magnitudes);
  out.fields.push_back(std::move(magnitude));
  return out;
}

}  // namespace lancer
