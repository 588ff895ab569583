#include "lancer/scene/results/warp.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/suggest.hpp"

namespace lancer {

void removeMeshFaces(Mesh& mesh, const std::vector<std::uint8_t>& removed,
                     std::vector<float>* perFaceValues) {
  const bool sides = !mesh.volumeSides.empty();
  // One value per face (element data) or kCornerSlots (element-node data).
  std::size_t stride = 0;
  if (perFaceValues && !mesh.faces.empty() && perFaceValues->size() % mesh.faces.size() == 0)
    stride = perFaceValues->size() / mesh.faces.size();
  std::size_t kept = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (removed[f]) continue;
    mesh.faces[kept] = mesh.faces[f];
    mesh.facePhysicalTag[kept] = mesh.facePhysicalTag[f];
    mesh.faceEntityTag[kept] = mesh.faceEntityTag[f];
    if (f < mesh.faceEdgeMask.size()) mesh.faceEdgeMask[kept] = mesh.faceEdgeMask[f];
    if (sides) {
      mesh.volumeSides.side[kept] = mesh.volumeSides.side[f];
      mesh.volumeSides.outerPhysicalTag[kept] = mesh.volumeSides.outerPhysicalTag[f];
      mesh.volumeSides.outerEntityTag[kept] = mesh.volumeSides.outerEntityTag[f];
    }
    if (stride)
      std::copy_n(perFaceValues->begin() + static_cast<std::ptrdiff_t>(f * stride), stride,
                  perFaceValues->begin() + static_cast<std::ptrdiff_t>(kept * stride));
    ++kept;
  }
  mesh.faces.resize(kept);
  mesh.facePhysicalTag.resize(kept);
  mesh.faceEntityTag.resize(kept);
  if (mesh.faceEdgeMask.size() > kept) mesh.faceEdgeMask.resize(kept);
  if (sides) {
    mesh.volumeSides.side.resize(kept);
    mesh.volumeSides.outerPhysicalTag.resize(kept);
    mesh.volumeSides.outerEntityTag.resize(kept);
  }
  if (stride) perFaceValues->resize(kept * stride);
}

ViewValues warpDisplacement(const Mesh& fields, const WarpSettings& warp, const StepSelection& when,
                            std::size_t vertexCount) {
  const std::string& file = fields.source.path;
  const std::vector<const MeshField*> steps = viewSteps(fields, warp.field);
  if (steps.empty()) {
    // A view the reader skipped (a NaN, a bad count) is named with the reader's reason.
    for (const auto& [skipped, warning] : fields.source.skippedFields)
      if (skipped == warp.field)
        throw InputError(
            warp.where,
            fmt::format("warp field \"{}\": its section in {} could not be read and was skipped ({})",
                        warp.field, file, warning));
    throw InputError(warp.where,
                     fields.fields.empty()
                         ? fmt::format("warp field \"{}\": {} has no views ($NodeData); a warp needs a node "
                                       "vector such as a displacement",
                                       warp.field, file)
                         : fmt::format("warp field \"{}\" is not in {}{}; it has {}", warp.field, file,
                                       didYouMean(warp.field, viewNames(fields)), describeViews(fields)));
  }
  const MeshField& first = *steps.front();
  if (first.at == FieldAt::kElement)
    throw InputError(warp.where,
                     fmt::format("warp field \"{}\" in {} is element data ($ElementData), one value "
                                 "per element: a warp moves nodes, give a node or element-node view of 3 "
                                 "components (colour by this one instead)",
                                 warp.field, file));
  if (first.components != 3)
    throw InputError(warp.where,
                     fmt::format("warp field \"{}\" in {} has {} component{} per node: a warp needs a vector "
                                 "of 3 (a displacement); colour by this view instead",
                                 warp.field, file, first.components, first.components == 1 ? "" : "s"));
  std::string problem;
  std::optional<ViewValues> step = viewValuesAt(steps, when, problem);
  if (!step)
    throw InputError(warp.where, fmt::format("warp field \"{}\" {} in {}{}", warp.field, problem, file,
                                             when.where.empty() ? "" : fmt::format(" ({})", when.where)));
  // Element-node data moves each node by the mean of what its elements give it (a displacement is
  // continuous: they agree up to the solver's rounding).
  if (first.at == FieldAt::kCorner) step = vertexMeans(fields, *step);
  if (step->size() != vertexCount * 3)
    throw InputError(warp.where,
                     fmt::format("warp field \"{}\" step {} in {} has values for {} nodes, the mesh "
                                 "has {}: the view belongs to another mesh",
                                 warp.field, step->field->step, file, step->size() / 3, vertexCount));
  return std::move(*step);
}

WarpReport warpMesh(Mesh& mesh, const Mesh& fields, const WarpSettings& warp, const StepSelection& when,
                    std::vector<float>* perFaceValues) {
  const std::string& file = fields.source.path;
  const ViewValues step = warpDisplacement(fields, warp, when, mesh.positions.size());
  std::uint64_t missing = 0;
  const auto factor = static_cast<float>(warp.factor);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 d{step[3 * v], step[3 * v + 1], step[3 * v + 2]};
    if (std::isnan(d.x) || std::isnan(d.y) || std::isnan(d.z)) {
      ++missing;
      continue;
    }
    mesh.positions[v] += factor * d;
  }
  if (missing)
    throw InputError(
        warp.where,
        fmt::format("warp field \"{}\" step {} in {} gives no vector for {} of the mesh's {} nodes; "
                    "a warp needs one for every node (save the view on all nodes in gmsh)",
                    warp.field, step.field->step, file, missing, mesh.positions.size()));
  WarpReport report;
  std::vector<std::uint8_t> collapsed(mesh.faces.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const MeshFace& face = mesh.faces[f];
    bool finite = true;
    for (int c = 0; c < face.cornerCount(); ++c) finite = finite && isFinite(mesh.positions[face.vertex[c]]);
    if (!finite || isDegenerateFace(mesh.positions.data(), face)) collapsed[f] = 1, ++report.collapsedFaces;
  }
  if (report.collapsedFaces) removeMeshFaces(mesh, collapsed, perFaceValues);
  return report;
}

Aabbd warpedWorldBounds(const SceneDescription& description, const std::vector<Mesh>& meshes) {
  Aabbd box;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const Mesh& mesh = meshes[i];
    const InstanceTransform transform(description.meshes[i]);
    std::optional<ViewValues> displacement;
    float factor = 0;
    if (const std::optional<WarpSettings>& warp = description.meshes[i].warp) {
      std::string problem;
      const std::vector<const MeshField*> steps = viewSteps(mesh, warp->field);
      if (!steps.empty() && steps.front()->components == 3 && steps.front()->at != FieldAt::kElement)
        displacement = viewValuesAt(steps, description.when, problem);
      if (displacement) displacement = vertexMeans(mesh, *displacement);
      if (displacement && displacement->size() != 3 * mesh.positions.size()) displacement.reset();
      factor = static_cast<float>(warp->factor);
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      Vec3 p = mesh.positions[v];
      if (displacement) {
        const ViewValues& d = *displacement;
        const Vec3 moved = p + factor * Vec3{d[3 * v], d[3 * v + 1], d[3 * v + 2]};
        if (isFinite(moved)) p = moved;
      }
      box.extend(transform.apply(mesh.origin + toDouble(p)));
    }
  }
  return box;
}

}  // namespace lancer
