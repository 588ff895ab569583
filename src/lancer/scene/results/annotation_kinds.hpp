// The kinds of annotation that are meshes of their own (annotation_spec.hpp), one row each: the
// [[mesh]] key that asks for it, its reader and its builder. The loader, the scene builder and the
// front ends' overrides go through this table; it is used once per mesh when a scene is built,
// never per ray or per triangle.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/annotation_spec.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// What a kind builds its mesh from.
struct AnnotationSite {
  const MeshInstance& owner;         // the [[mesh]] it annotates
  const Mesh& mesh;                  // the owner's mesh, with every step of its fields
  const VolumeMesh* volume;          // the owner's volume elements when they were read, else null
  const StepSelection& when;         // the step or time the scene shows
  std::vector<Material>& materials;  // the scene's, for a kind that adds one
};

struct AnnotationKind {
  std::string_view key;  // the [[mesh]] key; also how messages and the built instance name it
  // The key's spec when the mesh table has it (file: the scene file's path, for messages).
  std::optional<AnnotationSpec> (*read)(const std::string& file, const TomlTableReader& mesh);
  // The annotation's mesh, in the owner's coordinates (same origin). `instance` arrives as the
  // owner's placement, material and clips, Phong shaded, without annotations of its own; the kind
  // gives it its colours or a material. Throws InputError at the spec's `where`.
  Mesh (*build)(const AnnotationSpec& spec, const AnnotationSite& site, MeshInstance& instance);
  // Whether the spec samples the owner's volume elements (they are then read with the mesh, and one
  // volume gives the annotation once, however many of its slices and caps carry the spec).
  bool (*samplesVolume)(const AnnotationSpec& spec);
};

// Every kind, in the order of AnnotationSpec's alternatives.
std::span<const AnnotationKind> annotationKinds();
const AnnotationKind& annotationKind(const AnnotationSpec& spec);

// The mesh table's annotation keys, in the table's order.
std::vector<AnnotationSpec> readAnnotations(const std::string& file, const TomlTableReader& mesh);

// Puts `spec` on the instance in place of one of its kind.
void setAnnotation(MeshInstance& instance, const AnnotationSpec& spec);

// Whether one of the instance's annotations samples its volume elements.
bool annotationsSampleVolume(const MeshInstance& instance);

}  // namespace lancer
