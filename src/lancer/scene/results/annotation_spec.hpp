// What a [[mesh]] asks of the annotations that are meshes of their own (built from the mesh's fields
// at the step shown, drawn after it): one spec per kind, in one list. A new kind adds its spec here
// and its row in annotation_kinds.cpp (its key, reader and builder); the scene description, the
// loader, the builder, animations and the front ends' overrides take it from there.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "lancer/scene/results/arrow_spec.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Every kind's spec holds `field` (the view it draws), `step` (pinned, else the scene's) and `where`
// (its value in the scene file, for messages).
using AnnotationSpec = std::variant<ArrowSpec>;

inline const std::string& annotationField(const AnnotationSpec& spec) {
  return std::visit([](const auto& kind) -> const std::string& { return kind.field; }, spec);
}
inline std::optional<int> annotationStep(const AnnotationSpec& spec) {
  return std::visit([](const auto& kind) { return kind.step; }, spec);
}
inline const SourceLocation& annotationWhere(const AnnotationSpec& spec) {
  return std::visit([](const auto& kind) -> const SourceLocation& { return kind.where; }, spec);
}

}  // namespace lancer
