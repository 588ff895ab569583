#include "lancer/mesh/mesh_from_elements.hpp"

#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/mesh_assembler.hpp"
#include "lancer/mesh/msh/volume_capture.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

int elementNodeCount(int type) {
  return type >= 1 && type <= kMaxMshElementType ? mshElementType(type).nodeCount : 0;
}

Mesh meshFromElements(std::span<const Vec3d> points, std::span<const ElementBlock> blocks,
                      std::vector<PhysicalGroup> namedGroups, const std::string& name,
                      std::span<const NodeFieldInput> nodeFields,
                      std::span<const ElementFieldInput> elementFields,
                      std::span<const ElementNodeFieldInput> elementNodeFields, bool keepVolume) {
  const Stopwatch stopwatch;
  MshMeshAssembler assembler;
  // Tags 1..N, as gmsh numbers nodes: every node counts as one the caller gave (for node fields).
  // Huge pages, as the reader's arrays: first-touch page faults would otherwise be a third of the time.
  std::vector<std::uint64_t>& tags = assembler.nodes.tags();
  tags.reserve(points.size());
  adviseHugePages(tags);
  for (std::size_t i = 0; i < points.size(); ++i) tags.push_back(i + 1);
  std::vector<Vec3d>& coords = assembler.nodes.coords();
  coords.reserve(points.size());
  adviseHugePages(coords);
  coords.assign(points.begin(), points.end());
  std::size_t faceEstimate = 0;
  for (const ElementBlock& block : blocks) {
    const int nodeCount = elementNodeCount(block.type);
    if (block.dimension == 2 && nodeCount > 0)
      faceEstimate += block.nodes.size() / static_cast<std::size_t>(nodeCount);
  }
  assembler.reserveFaces(faceEstimate);
  // Faces remember their element only when a field needs it (8 bytes a face), as in the reader.
  if (!elementFields.empty() || !elementNodeFields.empty()) assembler.trackElements();
  if (keepVolume) assembler.keepVolume();
  for (const ElementBlock& block : blocks) {
    const auto nodeCount = static_cast<std::size_t>(elementNodeCount(block.type));
    if (nodeCount == 0) continue;  // the caller checked the types; an unknown one has no nodes to read
    assembler.setGroup(block.dimension, block.physical, block.entity);
    const bool tagged = assembler.tracksElements() && !block.tags.empty();
    for (std::size_t at = 0, element = 0; at + nodeCount <= block.nodes.size(); at += nodeCount, ++element)
      assembler.addElement(block.type, block.nodes.data() + at, tagged ? block.tags[element] : 0);
  }
  for (const NodeFieldInput& input : nodeFields) {
    MeshField field;
    field.name = input.name;
    field.components = input.components;
    field.step = input.step;
    field.time = input.time;
    field.values.assign(input.values.begin(), input.values.end());
    assembler.nodeFields.push_back(std::move(field));
  }
  for (const ElementFieldInput& input : elementFields) {
    MshMeshAssembler::ElementField raw;
    raw.field.name = input.name;
    raw.field.at = FieldAt::kElement;
    raw.field.components = input.components;
    raw.field.step = input.step;
    raw.field.time = input.time;
    raw.field.values.assign(input.values.begin(), input.values.end());
    raw.tags.assign(input.tags.begin(), input.tags.end());
    assembler.elementFields.push_back(std::move(raw));
  }
  for (const ElementNodeFieldInput& input : elementNodeFields) {
    MshMeshAssembler::ElementNodeField raw;
    raw.field.name = input.name;
    raw.field.at = FieldAt::kCorner;
    raw.field.components = input.components;
    raw.field.step = input.step;
    raw.field.time = input.time;
    raw.records.tags.assign(input.tags.begin(), input.tags.end());
    raw.records.nodeCount.assign(input.nodeCounts.begin(), input.nodeCounts.end());
    std::uint64_t first = 0;
    for (const std::uint32_t nodes : input.nodeCounts) {
      raw.records.firstValue.push_back(first);
      first += std::uint64_t{nodes} * static_cast<std::uint64_t>(input.components);
    }
    raw.records.values.assign(input.values.begin(), input.values.end());
    assembler.elementNodeFields.push_back(std::move(raw));
  }
  MeshSourceInfo source;
  source.path = name;
  source.nodeCount = points.size();
  Mesh mesh = assembler.finish(std::move(source), std::move(namedGroups));
  if (keepVolume && !assembler.volumeCapture()->empty()) mesh.volume = assembler.volumeCapture()->take();
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

Mesh meshFromFaces(std::span<const Vec3d> points, SurfaceFacesInput faces,
                   std::vector<PhysicalGroup> namedGroups, const std::string& name, int threads) {
  const Stopwatch stopwatch;
  MshMeshAssembler assembler;
  assembler.setThreads(threads);
  // The points are read where they are; no node tags (they only serve node fields).
  assembler.adoptSurfaceMesh(points, std::move(faces.faces), std::move(faces.physical),
                             std::move(faces.entity));
  MeshSourceInfo source;
  source.path = name;
  source.nodeCount = points.size();
  Mesh mesh = assembler.finish(std::move(source), std::move(namedGroups));
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

}  // namespace lancer
