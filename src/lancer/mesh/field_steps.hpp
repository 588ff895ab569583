// The time steps of a gmsh view (the MeshField entries of a mesh that share a name) in time order,
// a view's values at any time between two steps (linear in time, as gmsh's own animation blends),
// and the scalar a colour map shows of a vector or a tensor (its magnitude, a component, von Mises).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// What scalar of a field's values is shown: `component = "magnitude" | 0..8 | "x" | "y" | "z" |
// "von_mises"`.
struct FieldComponent {
  enum class Kind { Magnitude, Index, VonMises };
  Kind kind = Kind::Magnitude;
  int index = 0;  // Kind::Index

  friend bool operator==(const FieldComponent&, const FieldComponent&) = default;
};

// "magnitude", "x", "y", "z", "von_mises" or the digits of an index; nullopt for anything else.
std::optional<FieldComponent> parseFieldComponent(std::string_view text);
std::string describeComponent(const FieldComponent& component);  // "magnitude", "x", "component 4", ...

// Empty when `component` exists for a field of `components` values, else what is wrong and what to use.
std::string componentProblem(const FieldComponent& component, int components);

// The scalar of one item's `components` values (NaN stays NaN). Von Mises of a 3x3 tensor in row order:
// sqrt(((sxx-syy)^2 + (syy-szz)^2 + (szz-sxx)^2 + 6 (sxy^2 + syz^2 + szx^2)) / 2), the shear terms
// averaged over the two off-diagonal halves.
float componentScalar(const float* values, int components, const FieldComponent& component);

// The least and greatest `component` scalar of a step's items, NaN ignored; empty (low > high) when
// there is none. The reader's fields answer from what it saw (MeshField::ranges).
std::pair<double, double> componentRange(const MeshField& field, const FieldComponent& component);

// The field's values without a copy: its own, or, when it is stored (mesh_field.hpp), those read
// back from its file, which `keep` holds for as long as they are used. Throws as loadedField does.
const std::vector<float>& fieldValues(const MeshField& field,
                                      std::shared_ptr<const std::vector<float>>& keep);

// The ranges a stored step keeps: each component's, the magnitude's, von Mises' for a tensor.
std::vector<std::pair<float, float>> componentRanges(const std::vector<float>& values, int components);

// The steps of view `name`, in time order (ties by step index). Their time is the file's real tag;
// a view whose times do not increase with its step index (gmsh writes time 0 for every step when the
// writer gives none) is timed by its step index instead: stepTime() says which.
std::vector<const MeshField*> viewSteps(const Mesh& mesh, std::string_view name);
double stepTime(const std::vector<const MeshField*>& steps, std::size_t i);
// Whether the steps' times increase with their step index, so that a time between two steps means
// something (GetDP's Newmark scheme writes t = 0 twice, its eigenmodes store their unsorted
// frequencies: their steps are ordered and blended by index, and keep their times for labels).
bool timedByTags(std::vector<const MeshField*> steps);

// The distinct names of the views a mesh carries, in file order.
std::vector<std::string> viewNames(const Mesh& mesh);

// "\"temperature\" (steps 0, 1), \"velocity\" (step 0)": what a file offers, for messages.
std::string describeViews(const Mesh& mesh);

// Which moment of the results a picture shows: one step by its index, or a time between steps.
struct StepSelection {
  std::optional<int> step;     // the step index (gmsh's integer tag); wins over time
  std::optional<double> time;  // linear in time between the two steps around it, clamped at the ends
  std::string where;           // "--step", or the scene file's key, for messages
};

// A view's values at one moment without a copy: one step's values, or two steps' and the weight of
// the second, blended item by item as viewAt blends them (to the bit).
struct ViewValues {
  const MeshField* field = nullptr;  // the step shown, or the earlier of the two (name, components)
  const std::vector<float>* a = nullptr;
  const std::vector<float>* b = nullptr;  // the later step of a blend; null for one step
  float weight = 0;
  std::shared_ptr<const std::vector<float>> keepA, keepB;  // the values of stored steps, read back
  std::size_t size() const { return a->size(); }
  float operator[](std::size_t i) const { return b ? (*a)[i] + weight * ((*b)[i] - (*a)[i]) : (*a)[i]; }
};

// What viewAt gives, as ViewValues: null and `problem` set when the step does not exist.
std::optional<ViewValues> viewValuesAt(const std::vector<const MeshField*>& steps, const StepSelection& when,
                                       std::string& problem);

// The view's values at `when` (the first step when neither is set). Null and `problem` set when the
// step does not exist. The result's step is the step's index, or -1 for a blend of two steps.
std::optional<MeshField> viewAt(const std::vector<const MeshField*>& steps, const StepSelection& when,
                                std::string& problem);

// An element-node view (FieldAt::kCorner) as one value per vertex of `mesh`: the mean of the values
// its faces give each vertex, NaN where none does. What moves nodes (a warp) and stands at them
// (arrows); the faces keep their own values for colours and isolines. Other views come back as given.
ViewValues vertexMeans(const Mesh& mesh, const ViewValues& view);
MeshField vertexMeans(const Mesh& mesh, const MeshField& field);

// The times of every step of the named views of a mesh, sorted and without repeats: the frames of an
// animation over steps.
std::vector<double> stepTimes(const Mesh& mesh, const std::vector<std::string>& names);

}  // namespace lancer
