#include "lancer/mesh/volume/field_line_tubes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {
namespace {

// Any unit vector at right angles to `t`.
Vec3d perpendicular(const Vec3d& t) {
  const Vec3d axis = std::abs(t.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  return normalize(cross(t, axis));
}

}  // namespace

Mesh fieldLineTubes(const VolumeMesh& volume, const VolumeLocator& locator, std::span<const FieldLine> lines,
                    double radius, int sides) {
  Mesh tubes;
  tubes.origin = volume.origin;
  tubes.source.path = "field lines";
  // The centre point each vertex takes its values from: (line, point).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertexPoint;
  const auto addFace = [&](MeshFace face) {
    tubes.faces.push_back(face);
    tubes.facePhysicalTag.push_back(0);
    tubes.faceEntityTag.push_back(0);
    tubes.faceEdgeMask.push_back(0);
  };
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const std::vector<Vec3d>& p = lines[l].points;
    if (p.size() < 2) continue;
    const auto base = static_cast<std::uint32_t>(tubes.positions.size());
    Vec3d normal{};
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3d ahead = p[std::min(i + 1, p.size() - 1)], behind = p[i == 0 ? 0 : i - 1];
      Vec3d tangent = ahead - behind;
      if (length(tangent) == 0) tangent = Vec3d{0, 0, 1};
      tangent = normalize(tangent);
      // Parallel transport: the last ring's normal, made square to the new tangent.
      normal = i == 0 ? perpendicular(tangent) : normal - tangent * dot(normal, tangent);
      if (length(normal) < 1e-6) normal = perpendicular(tangent);
      normal = normalize(normal);
      const Vec3d binormal = cross(tangent, normal);
      for (int s = 0; s < sides; ++s) {
        const double angle = 2 * std::numbers::pi * s / sides;
        const Vec3d offset = (normal * std::cos(angle) + binormal * std::sin(angle)) * radius;
        tubes.positions.push_back(toFloat(p[i] + offset));
        vertexPoint.emplace_back(static_cast<std::uint32_t>(l), static_cast<std::uint32_t>(i));
      }
    }
    const auto ring = [&](std::size_t i, int s) {
      return base + static_cast<std::uint32_t>(i * static_cast<std::size_t>(sides) +
                                               static_cast<std::size_t>((s + sides) % sides));
    };
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      for (int s = 0; s < sides; ++s)
        addFace(MeshFace{{ring(i, s), ring(i, s + 1), ring(i + 1, s + 1), ring(i + 1, s)}});
    // End caps: fans to the centre points.
    for (const std::size_t end : {std::size_t{0}, p.size() - 1}) {
      const auto centre = static_cast<std::uint32_t>(tubes.positions.size());
      tubes.positions.push_back(toFloat(p[end]));
      vertexPoint.emplace_back(static_cast<std::uint32_t>(l), static_cast<std::uint32_t>(end));
      for (int s = 0; s < sides; ++s) {
        if (end == 0)
          addFace(MeshFace{{centre, ring(end, s + 1), ring(end, s), kNoVertex}});
        else
          addFace(MeshFace{{centre, ring(end, s), ring(end, s + 1), kNoVertex}});
      }
    }
  }
  for (const VolumeField& field : volume.fields) {
    MeshField out;
    out.name = field.name;
    out.at = FieldAt::kNode;
    out.components = field.components;
    out.step = field.step;
    out.time = field.time;
    const auto components = static_cast<std::size_t>(field.components);
    out.values.resize(vertexPoint.size() * components);
    for (std::size_t v = 0; v < vertexPoint.size(); ++v) {
      float* value = out.values.data() + v * components;
      // A ring's vertices share their centre point: interpolated once.
      if (v > 0 && vertexPoint[v] == vertexPoint[v - 1]) {
        std::copy_n(value - components, components, value);
        continue;
      }
      const auto [l, i] = vertexPoint[v];
      locator.interpolate(field, lines[l].where[i], value);
    }
    tubes.fields.push_back(std::move(out));
  }
  return tubes;
}

}  // namespace lancer
