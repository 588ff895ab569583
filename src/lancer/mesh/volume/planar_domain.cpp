#include "lancer/mesh/volume/planar_domain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lancer {
namespace {

// Twice the face's area along its normal (Newell's method: exact for a planar polygon).
Vec3d areaVector(const Mesh& mesh, const MeshFace& face) {
  Vec3d sum{};
  const int n = face.cornerCount();
  for (int c = 0; c < n; ++c) {
    const Vec3d a = toDouble(mesh.positions[face.vertex[c]]);
    const Vec3d b = toDouble(mesh.positions[face.vertex[(c + 1) % n]]);
    sum = sum + cross(a, b);
  }
  return sum;
}

double halton(std::uint32_t index, std::uint32_t base) {
  double result = 0, fraction = 1.0 / base;
  for (; index > 0; index /= base, fraction /= base) result += fraction * (index % base);
  return result;
}

}  // namespace

PlaneFit fitPlane(const Mesh& surface) {
  PlaneFit fit;
  Vec3d largest{};
  for (const MeshFace& face : surface.faces) {
    const Vec3d area = areaVector(surface, face);
    if (length(area) > length(largest)) largest = area;
  }
  if (!(length(largest) > 0)) return fit;
  Vec3d normal{};
  Vec3d sum{};
  std::size_t corners = 0;
  Aabbd box;
  for (const MeshFace& face : surface.faces) {
    const Vec3d area = areaVector(surface, face);
    normal = normal + (dot(area, largest) >= 0 ? area : area * -1.0);
    for (int c = 0; c < face.cornerCount(); ++c) {
      const Vec3d p = toDouble(surface.positions[face.vertex[c]]);
      sum = sum + p;
      box.extend(p);
      ++corners;
    }
  }
  normal = normalize(normal);
  const double axes[3] = {normal.x, normal.y, normal.z};
  const auto dominant =
      std::max_element(axes, axes + 3, [](double a, double b) { return std::abs(a) < std::abs(b); });
  if (*dominant < 0) normal = normal * -1.0;
  fit.normal = normal;
  fit.point = sum * (1.0 / static_cast<double>(corners));
  fit.diagonal = length(box.extent());
  for (const MeshFace& face : surface.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) {
      const Vec3d p = toDouble(surface.positions[face.vertex[c]]);
      const double distance = std::abs(dot(p - fit.point, normal));
      if (distance > fit.farthest) {
        fit.farthest = distance;
        fit.farthestVertex = p;
      }
    }
  }
  return fit;
}

PlanarDomain planarDomain(const Mesh& surface, const PlaneFit& fit) {
  PlanarDomain domain;
  domain.point = fit.point;
  domain.normal = fit.normal;
  VolumeMesh& volume = domain.volume;
  volume.origin = surface.origin;

  // The vertices the faces use, each as a node of both layers (bottom at layer[v], top one past the
  // bottom layer's count).
  std::vector<std::uint32_t> layer(surface.positions.size(), kNoVertex);
  std::vector<std::uint32_t> used;
  double area = 0;
  for (const MeshFace& face : surface.faces) {
    area += 0.5 * length(areaVector(surface, face));
    for (int c = 0; c < face.cornerCount(); ++c) {
      const std::uint32_t v = face.vertex[c];
      if (layer[v] == kNoVertex) {
        layer[v] = static_cast<std::uint32_t>(used.size());
        used.push_back(v);
      }
    }
  }
  domain.cellSize = std::sqrt(area / static_cast<double>(std::max<std::size_t>(surface.faces.size(), 1)));
  // As thick as a cell is wide: the volume's integrator then sizes its steps as for the 2D cells,
  // and rounding never carries a line out through the top or the bottom.
  domain.thickness = domain.cellSize;
  const auto layerCount = static_cast<std::uint32_t>(used.size());
  volume.nodes.reserve(2 * used.size());
  for (const double side : {-0.5, 0.5})
    for (const std::uint32_t v : used) {
      const Vec3d p = toDouble(surface.positions[v]);
      // Each layer on the plane's side: a vertex off the plane by rounding is put on it.
      volume.nodes.push_back(
          toFloat(p - fit.normal * dot(p - fit.point, fit.normal) + fit.normal * (side * domain.thickness)));
    }

  volume.cells.reserve(surface.faces.size());
  for (std::size_t f = 0; f < surface.faces.size(); ++f) {
    const MeshFace& face = surface.faces[f];
    const int n = face.cornerCount();
    std::array<std::uint32_t, kMaxCellCorners> cell;
    cell.fill(kNoVertex);
    for (int c = 0; c < n; ++c) {
      cell[static_cast<std::size_t>(c)] = layer[face.vertex[c]];
      cell[static_cast<std::size_t>(c + n)] = layer[face.vertex[c]] + layerCount;
    }
    volume.cells.push_back(cell);
    volume.shapes.push_back(n == 4 ? CellShape::kHexahedron : CellShape::kPrism);
    volume.cellPhysicalTag.push_back(surface.facePhysicalTag[f]);
    volume.cellEntityTag.push_back(surface.faceEntityTag[f]);
  }

  for (const MeshField& stepOrStored : surface.fields) {
    const MeshField step = stepOrStored.isStored() ? loadedField(stepOrStored) : stepOrStored;
    VolumeField field;
    field.name = step.name;
    field.at = step.at;
    field.components = step.components;
    field.step = step.step;
    field.time = step.time;
    const auto components = static_cast<std::size_t>(step.components);
    switch (step.at) {
      case FieldAt::kNode:
        field.values.resize(2 * used.size() * components);
        for (std::size_t k = 0; k < used.size(); ++k)
          for (std::size_t c = 0; c < components; ++c)
            field.values[k * components + c] = field.values[(k + used.size()) * components + c] =
                step.values[used[k] * components + c];
        break;
      case FieldAt::kElement:
        field.values = step.values;
        break;
      case FieldAt::kCorner:
        field.values.assign(surface.faces.size() * kMaxCellCorners * components,
                            std::numeric_limits<float>::quiet_NaN());
        for (std::size_t f = 0; f < surface.faces.size(); ++f) {
          const MeshFace& face = surface.faces[f];
          const int n = face.cornerCount();
          for (int c = 0; c < n; ++c) {
            const float* value =
                step.values.data() +
                (f * kCornerSlots + static_cast<std::size_t>(cornerSlot(face, c))) * components;
            for (const int corner : {c, c + n})
              std::copy_n(value, components,
                          field.values.data() +
                              (f * kMaxCellCorners + static_cast<std::size_t>(corner)) * components);
          }
        }
        break;
    }
    volume.fields.push_back(std::move(field));
  }
  return domain;
}

void projectIntoPlane(VolumeField& field, const Vec3d& normal) {
  if (field.components != 3) return;
  for (std::size_t i = 0; i + 2 < field.values.size(); i += 3) {
    const Vec3d v{field.values[i], field.values[i + 1], field.values[i + 2]};
    const Vec3d inPlane = v - normal * dot(v, normal);
    field.values[i] = static_cast<float>(inPlane.x);
    field.values[i + 1] = static_cast<float>(inPlane.y);
    field.values[i + 2] = static_cast<float>(inPlane.z);
  }
}

std::vector<Vec3d> automaticPlanarSeeds(const PlanarDomain& domain, const VolumeLocator& locator, int count) {
  std::vector<Vec3d> seeds;
  if (domain.volume.empty() || count <= 0) return seeds;
  const Vec3d& n = domain.normal;
  const Vec3d u = normalize(cross(n, std::abs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0})), v = cross(n, u);
  double lowU = std::numeric_limits<double>::infinity(), highU = -lowU, lowV = lowU, highV = -lowU;
  for (const Vec3& node : domain.volume.nodes) {
    const Vec3d d = toDouble(node) - domain.point;
    lowU = std::min(lowU, dot(d, u));
    highU = std::max(highU, dot(d, u));
    lowV = std::min(lowV, dot(d, v));
    highV = std::max(highV, dot(d, v));
  }
  // A domain that fills a hundredth of its rectangle still gets its seeds.
  const auto wanted = static_cast<std::uint32_t>(count);
  for (std::uint32_t i = 1; seeds.size() < wanted && i < 100 * wanted + 1000; ++i) {
    const Vec3d p = domain.point + u * (lowU + halton(i, 2) * (highU - lowU)) +
                    v * (lowV + halton(i, 3) * (highV - lowV));
    if (locator.locate(p).inside()) seeds.push_back(p);
  }
  return seeds;
}

Vec3d ontoPlane(const PlanarDomain& domain, const Vec3d& point) {
  return point - domain.normal * dot(point - domain.point, domain.normal);
}

void liftOntoPlane(std::vector<FieldLine>& lines, const PlanarDomain& domain, double height) {
  for (FieldLine& line : lines)
    for (Vec3d& p : line.points) p = ontoPlane(domain, p) + domain.normal * height;
}

}  // namespace lancer
