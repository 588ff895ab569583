#include "lancer/scene/results/annotation_kinds.hpp"

#include <algorithm>
#include <array>
#include <variant>

#include "lancer/scene/results/arrows.hpp"

namespace lancer {
namespace {

// One row per kind, in the order of AnnotationSpec's alternatives.
constexpr std::array<AnnotationKind, 1> kAnnotationKinds = {{
    {"arrows", readArrowAnnotation, buildArrowAnnotation, arrowsSampleVolume},
}};
static_assert(kAnnotationKinds.size() == std::variant_size_v<AnnotationSpec>,
              "kAnnotationKinds has one row per alternative of AnnotationSpec");

}  // namespace

std::span<const AnnotationKind> annotationKinds() { return kAnnotationKinds; }

const AnnotationKind& annotationKind(const AnnotationSpec& spec) { return kAnnotationKinds[spec.index()]; }

std::vector<AnnotationSpec> readAnnotations(const std::string& file, const TomlTableReader& mesh) {
  std::vector<AnnotationSpec> specs;
  for (const AnnotationKind& kind : kAnnotationKinds)
    if (std::optional<AnnotationSpec> spec = kind.read(file, mesh)) specs.push_back(std::move(*spec));
  return specs;
}

void setAnnotation(MeshInstance& instance, const AnnotationSpec& spec) {
  const auto same = std::find_if(instance.annotations.begin(), instance.annotations.end(),
                                 [&](const AnnotationSpec& other) { return other.index() == spec.index(); });
  if (same != instance.annotations.end())
    *same = spec;
  else
    instance.annotations.push_back(spec);
}

bool annotationsSampleVolume(const MeshInstance& instance) {
  return std::any_of(instance.annotations.begin(), instance.annotations.end(),
                     [](const AnnotationSpec& spec) { return annotationKind(spec).samplesVolume(spec); });
}

}  // namespace lancer
