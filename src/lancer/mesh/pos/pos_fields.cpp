#include "lancer/mesh/pos/pos_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "lancer/mesh/field_steps.hpp"

namespace lancer {
namespace {

const char* componentsName(int components) {
  return components == 1 ? "scalar" : components == 3 ? "vector" : "tensor";
}

// One past the greatest step index of the mesh's fields named `name` (0 when there is none).
int nextStepIndex(const std::vector<MeshField>& fields, const std::string& name) {
  int next = 0;
  for (const MeshField& field : fields)
    if (field.name == name) next = std::max(next, field.step + 1);
  return next;
}

// The records of one step: per drawn element with a tag, its values at its nodes in the known order.
ElementNodeRecords stepRecords(const PosView& view, int step, const PosElementTags& elements) {
  ElementNodeRecords records;
  std::size_t count = 0, values = 0;
  for (const PosElementBlock& block : view.blocks) {
    if (!drawnBlock(block)) continue;
    count += block.elementCount();
    values += block.elementCount() * static_cast<std::size_t>(block.kind.nodes * block.kind.components);
  }
  records.tags.reserve(count);
  records.firstValue.reserve(count);
  records.nodeCount.reserve(count);
  records.values.resize(values);
  std::size_t element = 0, next = 0;
  for (const PosElementBlock& block : view.blocks) {
    if (!drawnBlock(block)) {
      element += block.elementCount();
      continue;
    }
    const int nodes = block.kind.nodes;
    const auto components = static_cast<std::size_t>(block.kind.components);
    const std::size_t perElement = static_cast<std::size_t>(nodes) * components;
    for (std::size_t e = 0; e < block.elementCount(); ++e, ++element) {
      if (elements.tag[element] == 0) continue;
      records.tags.push_back(elements.tag[element]);
      records.firstValue.push_back(next);
      records.nodeCount.push_back(static_cast<std::uint32_t>(nodes));
      const float* from = view.elementValues(block, e, step);
      float* to = records.values.data() + next;
      const std::uint32_t at =
          elements.orderAt.empty() ? PosElementTags::kSameOrder : elements.orderAt[element];
      if (at == PosElementTags::kSameOrder) {
        std::copy_n(from, perElement, to);
      } else {
        for (int j = 0; j < nodes; ++j)
          std::copy_n(from + static_cast<std::size_t>(j) * components, components,
                      to + elements.order[at + static_cast<std::size_t>(j)] * components);
      }
      next += perElement;
    }
  }
  records.values.resize(next);
  return records;
}

// The records of one step read where the view holds them, when they need no copy: one drawn
// block, its elements tagged one after another, each keeping its own node order (a view made into
// the mesh of its elements); else nullopt.
std::optional<UniformElementNodeRecords> uniformRecords(const PosView& view, int step,
                                                        const PosElementTags& elements) {
  const PosElementBlock* drawn = nullptr;
  std::size_t first = 0, element = 0;
  for (const PosElementBlock& block : view.blocks) {
    if (drawnBlock(block)) {
      if (drawn) return std::nullopt;
      drawn = &block;
      first = element;
    }
    element += block.elementCount();
  }
  if (!drawn || drawn->elementCount() == 0 || !elements.orderAt.empty() || elements.tag[first] == 0)
    return std::nullopt;
  for (std::size_t e = 0; e < drawn->elementCount(); ++e)
    if (elements.tag[first + e] != elements.tag[first] + e) return std::nullopt;
  const std::size_t perStep = static_cast<std::size_t>(drawn->kind.nodes * drawn->kind.components);
  return UniformElementNodeRecords{elements.tag[first], drawn->elementCount(),
                                   static_cast<std::uint32_t>(drawn->kind.nodes),
                                   drawn->values.data() + static_cast<std::size_t>(step) * perStep,
                                   perStep * static_cast<std::size_t>(view.stepCount)};
}

}  // namespace

bool sameElements(const PosView& a, const PosView& b) {
  if (a.blocks.size() != b.blocks.size()) return false;
  for (std::size_t i = 0; i < a.blocks.size(); ++i)
    if (a.blocks[i].kind.gmshType != b.blocks[i].kind.gmshType || a.blocks[i].coords != b.blocks[i].coords)
      return false;
  return true;
}

int drawnComponents(const PosView& view, const std::string& file) {
  int components = 0;
  const PosElementBlock* first = nullptr;
  for (const PosElementBlock& block : view.blocks) {
    if (!drawnBlock(block)) continue;
    if (first && block.kind.components != components)
      throw InputError(
          SourceLocation{file, view.line},
          fmt::format("view \"{}\" holds {} elements ({} at line {}) and {} elements ({} at line {}): lancer "
                      "makes one field of a view, of one kind; write them as two views",
                      view.name, componentsName(components), first->kind.code(), first->lines.front(),
                      componentsName(block.kind.components), block.kind.code(), block.lines.front()));
    if (!first) first = &block, components = block.kind.components;
  }
  return components;
}

void addPosViewSteps(Mesh& mesh, const PosView& view, int components, const PosElementTags& elements,
                     const std::vector<std::uint64_t>& faceElement,
                     const std::vector<MshCornerNodes>& faceCornerNode, const MshCoveredElements& covered) {
  const int firstStep = nextStepIndex(mesh.fields, view.name);
  for (int k = 0; k < view.stepCount; ++k) {
    MeshField field;
    field.name = view.name;
    field.at = FieldAt::kCorner;
    field.components = components;
    field.step = firstStep + k;
    field.time = view.timesGiven ? view.times[static_cast<std::size_t>(k)] : field.step;
    if (const auto inPlace = uniformRecords(view, k, elements)) {
      field.values = mapElementNodeValues(*inPlace, components, faceElement, faceCornerNode, covered);
    } else {
      field.values = mapElementNodeValues(stepRecords(view, k, elements), components, faceElement,
                                          faceCornerNode, {}, covered);
    }
    field.ranges = componentRanges(field.values, components);
    mesh.fields.push_back(std::move(field));
  }
}

}  // namespace lancer
