#include "lancer/mesh/nothing_to_draw.hpp"

#include <fmt/format.h>

#include "lancer/mesh/msh/element_types.hpp"

namespace lancer {
namespace {

// "12 2-node lines, 4 1-node points": the element kinds the file holds.
std::string elementList(const MeshSourceInfo& source) {
  std::string list;
  for (const auto& [type, count] : source.elementsByType)
    list += fmt::format("{}{} {}{}", list.empty() ? "" : ", ", count, mshElementTypeName(type),
                        count == 1 ? "" : "s");
  return list;
}

}  // namespace

std::string nothingToDrawReason(const Mesh& mesh) {
  if (mesh.faceCount() > 0) return {};
  const MeshSourceInfo& source = mesh.source;
  bool onlyVolumeGroups = !mesh.physicalGroups.empty();
  for (const PhysicalGroup& group : mesh.physicalGroups) onlyVolumeGroups &= group.dimension == 3;
  // gmsh saves only the elements of physical groups: a model whose groups are all Physical Volumes,
  // meshed with -2, is saved with no elements (MSH 4: $Entities alone; MSH 2: empty sections).
  if (source.elementsByType.empty() && onlyVolumeGroups)
    return "it holds no elements, and its physical groups are volumes: mesh it with -3 (or save with "
           "-save_all)";
  // STL, OBJ and PLY (surface_formats/): points with no faces, as a scanner's point cloud is.
  if (source.elementsByType.empty() &&
      (source.format == "stl" || source.format == "obj" || source.format == "ply"))
    return fmt::format("it holds no faces ({} points and no {}): lancer draws surfaces", source.nodeCount,
                       source.format == "stl"   ? "facet"
                       : source.format == "obj" ? "f line"
                                                : "face element entries");
  if (source.elementsByType.empty())
    return "it holds no elements (no $Elements section, or an empty one): mesh the model with gmsh -2 "
           "(surfaces) or -3 (volumes) before saving";
  bool linesAndPoints = true, drawable = false;
  for (const auto& [type, count] : source.elementsByType) {
    const MshElementRole role = mshElementType(type).role;
    linesAndPoints &= role == MshElementRole::kIgnored;
    drawable |= role == MshElementRole::kSurface || role == MshElementRole::kVolume;
  }
  if (linesAndPoints)
    return fmt::format(
        "it holds only lines and points ({}); lancer draws surfaces and volumes: mesh it with "
        "gmsh -2 or -3{}",
        elementList(source), onlyVolumeGroups ? " (its physical groups are volumes: -3)" : "");
  if (!drawable) return fmt::format("it holds only elements lancer does not draw ({})", elementList(source));
  if (source.degenerateFacesDropped)
    return fmt::format("all its {} faces are degenerate (zero area) and were dropped",
                       source.degenerateFacesDropped);
  return "its volume elements have no outer faces (every face is shared by two elements)";
}

}  // namespace lancer
