// lancer.Mesh from numpy arrays (checked here, at the boundary: shapes, dtypes, index ranges, finite
// coordinates) or from a .msh file (read_msh), and its arrays back as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

#include "bindings.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/mesh_from_elements.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::python {
namespace {

using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Bad arrays are an InputError (a ValueError) at "lancer.Mesh", as the checks of lancer/_arrays.py.
[[noreturn]] void valueError(const std::string& message) {
  throw InputError(SourceLocation{"lancer.Mesh"}, message);
}

// lancer.Mesh's second constructor: from element blocks and fields, the form lancer/_arrays.py puts
// meshio-style cells, point_data and cell_data in (a marker first, so that no array call matches it).
struct ElementBlocksMarker {};

// The first i in [0, count) for which bad(i) holds, or count: checked in parallel chunks (a 1M-face
// array is a few milliseconds a pass), the lowest failing index reported whatever the threads.
template <typename Bad>
std::size_t firstBad(std::size_t count, int threads, Bad&& bad) {
  const ChunkPlan plan(count, 1 << 16);
  std::vector<std::size_t> firstInChunk(plan.chunks, count);
  parallelChunks(plan, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (bad(i)) {
        firstInChunk[k] = i;
        return;
      }
  });
  return *std::min_element(firstInChunk.begin(), firstInChunk.end());
}

char dtypeKind(const py::array& array) { return array.dtype().kind(); }

std::string shapeOf(const py::array& array) {
  std::string shape = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) shape += fmt::format("{}{}", i ? ", " : "", array.shape(i));
  return shape + (array.ndim() == 1 ? ",)" : ")");
}

// (N, 3) real numbers, every coordinate finite, as one contiguous float64 array (a view when it is one).
PointArray checkedPoints(const py::array& points, int threads) {
  if (points.ndim() != 2 || points.shape(1) != 3)
    valueError(fmt::format("points must be an (N, 3) array of coordinates; got shape {}{}", shapeOf(points),
                           points.ndim() == 2 && points.shape(1) == 2
                               ? "; add a zero z column to 2-D points: np.c_[points, np.zeros(len(points))]"
                               : ""));
  const char kind = dtypeKind(points);
  if (kind != 'f' && kind != 'i' && kind != 'u')
    valueError(fmt::format("points must hold real numbers (float64); got dtype {}",
                           py::str(points.dtype()).cast<std::string>()));
  PointArray contiguous = PointArray::ensure(points);
  const double* xyz = contiguous.data();
  const auto count = static_cast<std::size_t>(contiguous.shape(0));
  if (const std::size_t i = firstBad(count, threads,
                                     [&](std::size_t p) {
                                       return !std::isfinite(xyz[3 * p]) || !std::isfinite(xyz[3 * p + 1]) ||
                                              !std::isfinite(xyz[3 * p + 2]);
                                     });
      i < count)
    valueError(fmt::format("points[{}] is ({}, {}, {}): every coordinate must be finite", i, xyz[3 * i],
                           xyz[3 * i + 1], xyz[3 * i + 2]));
  return contiguous;
}

// An integer array of the given number of dimensions (1 or 2), named for messages.
IndexArray checkedIntegers(const py::array& array, const char* name) {
  const char kind = dtypeKind(array);
  if (kind != 'i' && kind != 'u')
    valueError(
        fmt::format("{} must hold integers; got dtype {}", name, py::str(array.dtype()).cast<std::string>()));
  return IndexArray::ensure(array);
}

// Per-face physical tags or entity tags: (M,) non-negative integers that fit gmsh's int tags.
std::vector<std::int32_t> checkedTags(const py::object& tags, py::ssize_t faceCount, const char* name) {
  std::vector<std::int32_t> result(static_cast<std::size_t>(faceCount), 0);
  if (tags.is_none()) return result;
  const py::array array = py::array::ensure(tags);
  if (!array) valueError(fmt::format("{} must be an array of one integer per face", name));
  if (array.ndim() != 1 || array.shape(0) != faceCount)
    valueError(fmt::format("{} must be an ({},) array, one tag per cell; got shape {}", name, faceCount,
                           shapeOf(array)));
  const IndexArray values = checkedIntegers(array, name);
  for (py::ssize_t f = 0; f < faceCount; ++f) {
    const std::int64_t tag = values.data()[f];
    if (tag < 0 || tag > std::numeric_limits<std::int32_t>::max())
      valueError(fmt::format("{}[{}] is {}: tags are 0 (none) or positive 32-bit integers", name, f, tag));
    result[static_cast<std::size_t>(f)] = static_cast<std::int32_t>(tag);
  }
  return result;
}

std::vector<PhysicalGroup> checkedGroupNames(const py::object& names, int dimension) {
  std::vector<PhysicalGroup> groups;
  if (names.is_none()) return groups;
  if (!py::isinstance<py::dict>(names)) valueError("group_names must be a dict {tag: name}");
  for (const auto& [key, value] : names.cast<py::dict>()) {
    if (!py::isinstance<py::int_>(key) || !py::isinstance<py::str>(value))
      valueError(fmt::format("group_names must map integer tags to strings; got {}: {}",
                             py::repr(key).cast<std::string>(), py::repr(value).cast<std::string>()));
    const auto tag = key.cast<long long>();
    if (tag <= 0 || tag > std::numeric_limits<std::int32_t>::max())
      valueError(fmt::format("group_names has tag {}: physical tags are positive 32-bit integers", tag));
    groups.push_back({dimension, static_cast<int>(tag), value.cast<std::string>()});
  }
  return groups;
}

// Mesh(points, faces, groups=None, group_names=None, entities=None, name="<arrays>")
std::shared_ptr<Mesh> meshFromArrays(const py::array& pointsIn, const py::array& facesIn,
                                     const py::object& groupsIn, const py::object& groupNames,
                                     const py::object& entitiesIn, const std::string& name, int threads) {
  requireThreads(threads);
  const PointArray points = checkedPoints(pointsIn, threads);
  if (facesIn.ndim() != 2 || (facesIn.shape(1) != 3 && facesIn.shape(1) != 4))
    valueError(fmt::format("cells must be an (M, 3) or (M, 4) array of 0-based point indices; got shape {}",
                           shapeOf(facesIn)));
  const IndexArray faces = checkedIntegers(facesIn, "cells");
  const py::ssize_t faceCount = faces.shape(0);
  const auto corners = static_cast<int>(faces.shape(1));
  std::vector<std::int32_t> groups = checkedTags(groupsIn, faceCount, "groups");
  std::vector<std::int32_t> entities =
      entitiesIn.is_none() ? groups : checkedTags(entitiesIn, faceCount, "entities");
  const std::int64_t pointCount = points.shape(0);
  if (pointCount > std::numeric_limits<std::int32_t>::max())
    valueError(fmt::format("{} points are more than lancer's 32-bit indices allow", pointCount));

  // One pass checks the corners and writes the faces (the only copy of the indices).
  SurfaceFacesInput input;
  input.faces.resize(static_cast<std::size_t>(faceCount));
  adviseHugePages(input.faces);
  const std::int64_t* index = faces.data();
  const auto badFace = [&](std::size_t f) {
    const std::int64_t* corner = index + f * static_cast<std::size_t>(corners);
    const int used = corners == 3 || corner[3] == -1 ? 3 : 4;
    for (int c = 0; c < used; ++c) {
      if (corner[c] < 0 || corner[c] >= pointCount) return true;
      input.faces[f].vertex[c] = static_cast<std::uint32_t>(corner[c]);
    }
    return false;
  };
  if (const std::size_t f = firstBad(input.faces.size(), threads, badFace); f < input.faces.size()) {
    const std::int64_t* corner = index + f * static_cast<std::size_t>(corners);
    const int c = static_cast<int>(
        std::find_if(corner, corner + corners, [&](std::int64_t v) { return v < 0 || v >= pointCount; }) -
        corner);
    valueError(fmt::format("cells[{}] uses point {}, but points has {} rows (indices are 0-based{})", f,
                           corner[c], pointCount, corners == 4 ? "; -1 last makes a triangle" : ""));
  }
  input.physical = std::move(groups);
  input.entity = std::move(entities);
  std::vector<PhysicalGroup> named = checkedGroupNames(groupNames, 2);
  static_assert(sizeof(Vec3d) == 3 * sizeof(double));
  const std::span<const Vec3d> xyz(reinterpret_cast<const Vec3d*>(points.data()),
                                   static_cast<std::size_t>(pointCount));
  std::shared_ptr<Mesh> mesh;
  {
    py::gil_scoped_release release;
    mesh = std::make_shared<Mesh>(meshFromFaces(xyz, std::move(input), std::move(named), name, threads));
  }
  warnUser(mesh->source.warnings, 2);
  return mesh;
}

// Non-negative element tags (gmsh's size_t tags) as uint64, named for messages.
std::vector<std::uint64_t> checkedElementTags(const py::array& array, const char* name) {
  const IndexArray values = checkedIntegers(array, name);
  std::vector<std::uint64_t> tags(static_cast<std::size_t>(values.size()));
  for (py::ssize_t i = 0; i < values.size(); ++i) {
    if (values.data()[i] < 0)
      valueError(fmt::format("{} holds {}: element tags are >= 0", name, values.data()[i]));
    tags[static_cast<std::size_t>(i)] = static_cast<std::uint64_t>(values.data()[i]);
  }
  return tags;
}

// Field values: NaN is "no value here" (grey in color_by); an infinity has no colour: an error.
// tags name the records of an element field; a node field's records are the nodes, in order.
void rejectInfinite(const PointArray& values, int components, const std::string& field,
                    std::span<const std::uint64_t> tags) {
  for (py::ssize_t i = 0; i < values.size(); ++i) {
    if (!std::isinf(values.data()[i])) continue;
    const auto record = static_cast<std::size_t>(i / components);
    valueError(tags.empty() ? fmt::format("node field '{}' has an infinite value at node index {}: give "
                                          "finite values, or NaN for none",
                                          field, record)
                            : fmt::format("element field '{}' has an infinite value for element {}: give "
                                          "finite values, or NaN for none",
                                          field, tags[record]));
  }
}

// _mesh_from_elements(points, blocks, group_names, name, node_fields, element_fields): for
// lancer.from_gmsh (keepVolume: also the volume elements, as mesh.volume; lancer.Mesh from arrays). blocks:
// [(type, dimension, physical, entity, nodes, tags)], nodes 0-based, nodeCount per element, tags one per
// element (or None); group_names: {(dimension, tag): name}; node_fields: [(name, components, values (N *
// components,)[, step, time])]; element_fields: [(name, components, tags (R,), values (R * components,)[,
// step, time])], tags naming the blocks' elements; element_node_fields: [(name, components, tags (R,),
// node_counts (R,), values (sum(node_counts) * components,)[, step, time])], each record's values in its
// element's node order.
std::shared_ptr<Mesh> meshFromElementBlocks(const py::array& pointsIn, const py::list& blockList,
                                            const py::dict& groupNames, const std::string& name,
                                            const py::list& fieldList, const py::list& elementFieldList,
                                            const py::list& elementNodeFieldList, bool keepVolume = false) {
  const PointArray points = checkedPoints(pointsIn, 0);
  const std::int64_t pointCount = points.shape(0);
  std::vector<std::vector<std::uint32_t>> indices;  // the converted arrays the blocks' spans point into
  std::vector<std::vector<std::uint64_t>> elementTags;
  std::vector<ElementBlock> blocks;
  for (const py::handle item : blockList) {
    const auto [type, dimension, physical, entity, nodeArray, tagArray] =
        item.cast<std::tuple<int, int, std::int32_t, std::int32_t, py::array, py::object>>();
    const int nodeCount = elementNodeCount(type);
    if (nodeCount == 0) valueError(fmt::format("gmsh element type {} is not one lancer knows", type));
    const IndexArray values = checkedIntegers(nodeArray, "element nodes");
    if (values.size() % nodeCount != 0)
      valueError(fmt::format("{} node indices are no whole number of type-{} elements ({} nodes each)",
                             values.size(), type, nodeCount));
    std::vector<std::uint32_t>& block = indices.emplace_back(static_cast<std::size_t>(values.size()));
    for (py::ssize_t i = 0; i < values.size(); ++i) {
      if (values.data()[i] < 0 || values.data()[i] >= pointCount)
        valueError(
            fmt::format("an element uses node index {}, outside the {} nodes", values.data()[i], pointCount));
      block[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(values.data()[i]);
    }
    std::vector<std::uint64_t>& tags = elementTags.emplace_back();
    if (!tagArray.is_none()) {
      tags = checkedElementTags(py::array::ensure(tagArray), "element tags");
      if (tags.size() * static_cast<std::size_t>(nodeCount) != block.size())
        valueError(fmt::format("{} element tags for {} type-{} elements", tags.size(),
                               block.size() / static_cast<std::size_t>(nodeCount), type));
    }
  }
  std::size_t b = 0;
  for (const py::handle item : blockList) {
    const auto [type, dimension, physical, entity] =
        item.cast<py::tuple>()[py::slice(0, 4, 1)].cast<std::tuple<int, int, std::int32_t, std::int32_t>>();
    blocks.push_back({type, dimension, physical, entity, indices[b], elementTags[b]});
    ++b;
  }
  std::vector<PhysicalGroup> named;
  for (const auto& [key, value] : groupNames) {
    const auto [dimension, tag] = key.cast<std::pair<int, int>>();
    named.push_back({dimension, tag, value.cast<std::string>()});
  }
  std::vector<PointArray> fieldValues;  // the converted values the fields' spans point into
  std::vector<NodeFieldInput> fields;
  for (const py::handle item : fieldList) {
    const auto tuple = item.cast<py::tuple>();
    const auto [fieldName, components, values] =
        tuple[py::slice(0, 3, 1)].cast<std::tuple<std::string, int, py::array>>();
    const auto [step, time] = py::len(tuple) >= 5 ? tuple[py::slice(3, 5, 1)].cast<std::pair<int, double>>()
                                                  : std::pair<int, double>{0, 0.0};
    auto& array = fieldValues.emplace_back(PointArray::ensure(values));
    if (components <= 0 || array.size() != pointCount * components)
      valueError(fmt::format("field '{}' has {} values for {} nodes of {} components", fieldName,
                             array.size(), pointCount, components));
    rejectInfinite(array, components, fieldName, {});
    fields.push_back({fieldName, components,
                      std::span<const double>(array.data(), static_cast<std::size_t>(array.size())), step,
                      time});
  }
  std::vector<std::vector<std::uint64_t>> recordTags;
  std::vector<ElementFieldInput> elementFields;
  for (const py::handle item : elementFieldList) {
    const auto tuple = item.cast<py::tuple>();
    const auto [fieldName, components, tagArray, values] =
        tuple[py::slice(0, 4, 1)].cast<std::tuple<std::string, int, py::array, py::array>>();
    const auto [step, time] = py::len(tuple) >= 6 ? tuple[py::slice(4, 6, 1)].cast<std::pair<int, double>>()
                                                  : std::pair<int, double>{0, 0.0};
    const std::vector<std::uint64_t>& tags =
        recordTags.emplace_back(checkedElementTags(tagArray, "element field tags"));
    auto& array = fieldValues.emplace_back(PointArray::ensure(values));
    if (components <= 0 ||
        static_cast<std::size_t>(array.size()) != tags.size() * static_cast<std::size_t>(components))
      valueError(fmt::format("element field '{}' has {} values for {} elements of {} components", fieldName,
                             array.size(), tags.size(), components));
    rejectInfinite(array, components, fieldName, tags);
    elementFields.push_back({fieldName, components, tags,
                             std::span<const double>(array.data(), static_cast<std::size_t>(array.size())),
                             step, time});
  }
  std::vector<std::vector<std::uint32_t>> recordNodeCounts;
  std::vector<ElementNodeFieldInput> elementNodeFields;
  for (const py::handle item : elementNodeFieldList) {
    const auto tuple = item.cast<py::tuple>();
    const auto [fieldName, components, tagArray, countArray, values] =
        tuple[py::slice(0, 5, 1)].cast<std::tuple<std::string, int, py::array, py::array, py::array>>();
    const auto [step, time] = py::len(tuple) >= 7 ? tuple[py::slice(5, 7, 1)].cast<std::pair<int, double>>()
                                                  : std::pair<int, double>{0, 0.0};
    const std::vector<std::uint64_t>& tags =
        recordTags.emplace_back(checkedElementTags(tagArray, "element-node field tags"));
    const IndexArray counts = checkedIntegers(countArray, "element-node field node counts");
    std::vector<std::uint32_t>& nodeCounts = recordNodeCounts.emplace_back();
    std::size_t total = 0;
    for (py::ssize_t i = 0; i < counts.size(); ++i) {
      if (counts.data()[i] < 1 || counts.data()[i] > 1000)
        valueError(fmt::format("element-node field '{}' gives {} nodes for an element: 1 to 1000", fieldName,
                               counts.data()[i]));
      nodeCounts.push_back(static_cast<std::uint32_t>(counts.data()[i]));
      total += nodeCounts.back();
    }
    auto& array = fieldValues.emplace_back(PointArray::ensure(values));
    if (components <= 0 || nodeCounts.size() != tags.size() ||
        static_cast<std::size_t>(array.size()) != total * static_cast<std::size_t>(components))
      valueError(
          fmt::format("element-node field '{}' has {} values for {} elements of {} nodes in all and {} "
                      "components",
                      fieldName, array.size(), tags.size(), total, components));
    rejectInfinite(array, components, fieldName, {});
    elementNodeFields.push_back(
        {fieldName, components, tags, nodeCounts,
         std::span<const double>(array.data(), static_cast<std::size_t>(array.size())), step, time});
  }
  const std::span<const Vec3d> xyz(reinterpret_cast<const Vec3d*>(points.data()),
                                   static_cast<std::size_t>(pointCount));
  std::shared_ptr<Mesh> mesh;
  {
    py::gil_scoped_release release;
    mesh = std::make_shared<Mesh>(meshFromElements(xyz, blocks, std::move(named), name, fields, elementFields,
                                                   elementNodeFields, keepVolume));
  }
  warnUser(mesh->source.warnings, 2);
  return mesh;
}

py::array_t<double> pointsOf(const Mesh& mesh) {
  py::array_t<double> points({static_cast<py::ssize_t>(mesh.positions.size()), py::ssize_t{3}});
  double* out = points.mutable_data();
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(static_cast<std::uint32_t>(v));
    out[3 * v] = p.x, out[3 * v + 1] = p.y, out[3 * v + 2] = p.z;
  }
  return points;
}

// (M, 3) when every face is a triangle, else (M, 4) with -1 last for the triangles.
py::array_t<std::int64_t> facesOf(const Mesh& mesh) {
  bool quads = false;
  for (const MeshFace& face : mesh.faces) quads = quads || face.isQuad();
  const py::ssize_t corners = quads ? 4 : 3;
  py::array_t<std::int64_t> faces({static_cast<py::ssize_t>(mesh.faces.size()), corners});
  std::int64_t* out = faces.mutable_data();
  for (const MeshFace& face : mesh.faces)
    for (int c = 0; c < corners; ++c)
      *out++ = face.vertex[c] == kNoVertex ? std::int64_t{-1} : std::int64_t{face.vertex[c]};
  return faces;
}

py::array_t<std::int32_t> tagsOf(const std::vector<std::int32_t>& tags) {
  return py::array_t<std::int32_t>(static_cast<py::ssize_t>(tags.size()), tags.data());
}

// One field's values: (points, C) for node data, (faces, C) for element data, (faces, 4, C) for
// element-node data (in the order of each face's corners, as `faces` lists them); NaN where none.
py::array_t<float> fieldOf(const Mesh& mesh, const std::string& name, const std::optional<int>& step) {
  std::string names;
  for (const MeshField& stepField : mesh.fields) {
    if (stepField.name == name && step && stepField.step != *step) continue;
    if (stepField.name == name) {
      const MeshField field = loadedField(stepField);  // a step left in its file is read back
      const auto components = static_cast<py::ssize_t>(field.components);
      if (field.at != FieldAt::kCorner) {
        py::array_t<float> values({static_cast<py::ssize_t>(field.itemCount()), components});
        std::copy(field.values.begin(), field.values.end(), values.mutable_data());
        return values;
      }
      const auto slots = static_cast<py::ssize_t>(kCornerSlots);
      py::array_t<float> values({static_cast<py::ssize_t>(mesh.faces.size()), slots, components});
      float* out = values.mutable_data();
      std::fill_n(out, values.size(), std::numeric_limits<float>::quiet_NaN());
      const auto perCorner = static_cast<std::size_t>(components);
      for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int c = 0; c < mesh.faces[f].cornerCount(); ++c)
          std::copy_n(field.values.begin() +
                          static_cast<std::ptrdiff_t>(
                              (f * kCornerSlots + static_cast<std::size_t>(cornerSlot(mesh.faces[f], c))) *
                              perCorner),
                      perCorner, out + (f * kCornerSlots + static_cast<std::size_t>(c)) * perCorner);
      return values;
    }
    names += fmt::format("{}'{}'", names.empty() ? "" : ", ", stepField.name);
  }
  if (step && !viewSteps(mesh, name).empty())
    throw py::key_error(
        fmt::format("the field '{}' has no step {}; the mesh has {}", name, *step, describeViews(mesh)));
  throw py::key_error(
      fmt::format("the mesh has no field '{}'; its fields: {}", name, names.empty() ? "none" : names));
}

py::dict groupNamesOf(const Mesh& mesh) {
  py::dict names;
  for (const PhysicalGroup& group : mesh.physicalGroups)
    if (!group.name.empty() && !names.contains(py::int_(group.tag))) names[py::int_(group.tag)] = group.name;
  return names;
}

}  // namespace

void bindMesh(py::module_& module) {
  py::class_<ElementBlocksMarker>(module, "_ElementBlocks").def(py::init<>());
  py::class_<Mesh, std::shared_ptr<Mesh>>(module, "Mesh",
                                          "A surface mesh: points, triangle and quad faces, physical groups")
      .def(py::init([](const ElementBlocksMarker&, const py::array& points, const py::list& blocks,
                       const py::dict& groupNames, const std::string& name, const py::list& nodeFields,
                       const py::list& elementFields) {
             // Arrays with volume cells keep them: the mesh can be sliced and probed inside.
             return meshFromElementBlocks(points, blocks, groupNames, name, nodeFields, elementFields,
                                          py::list(), true);
           }),
           py::arg("marker"), py::arg("points"), py::arg("blocks"), py::arg("group_names"), py::arg("name"),
           py::arg("node_fields"), py::arg("element_fields"))
      .def(py::init(&meshFromArrays), py::arg("points"), py::arg("faces"), py::arg("groups") = py::none(),
           py::arg("group_names") = py::none(), py::arg("entities") = py::none(),
           py::arg("name") = "<arrays>", py::arg("threads") = 0,
           "points (N, 3) float64; faces (M, 3) or (M, 4) int, 0-based (a (M, 4) row with -1 last is a "
           "triangle); groups (M,) physical tags (0: none); group_names {tag: name}; entities (M,) gmsh "
           "elementary tags (default: the groups). Points no face uses are dropped, as are zero-area faces. "
           "threads: for the checks and the assembly (0: every core); the mesh is the same for any count.")
      .def_property_readonly("points", &pointsOf, "(N, 3) float64 world coordinates of the vertices")
      .def_property_readonly("faces", &facesOf, "(M, 3) int64, or (M, 4) with -1 last for triangles")
      .def_property_readonly(
          "groups", [](const Mesh& mesh) { return tagsOf(mesh.facePhysicalTag); },
          "(M,) int32 physical tag of each face (0: none)")
      .def_property_readonly(
          "entities", [](const Mesh& mesh) { return tagsOf(mesh.faceEntityTag); },
          "(M,) int32 gmsh elementary entity of each face")
      .def_property_readonly("group_names", &groupNamesOf, "{tag: name} of the named physical groups")
      .def_property_readonly(
          "fields", [](const Mesh& mesh) { return viewNames(mesh); },
          "names of the fields (gmsh views: node, element and element-node data) color_by and warp can use, "
          "once each")
      .def(
          "steps",
          [](const Mesh& mesh, const std::string& name) {
            std::vector<std::pair<int, double>> steps;
            const std::vector<const MeshField*> fields = viewSteps(mesh, name);
            for (std::size_t k = 0; k < fields.size(); ++k)
              steps.emplace_back(fields[k]->step, stepTime(fields, k));
            return steps;
          },
          py::arg("name"), "the (step, time) of each step of a field, in time order")
      .def("field", &fieldOf, py::arg("name"), py::arg("step") = py::none(),
           "values of one of `fields` at a step (default: its first in the file): (len(points), C) float32 "
           "for node data, (len(faces), C) for element data, (len(faces), 4, C) for element-node data (each "
           "face's corners in the order of `faces`), NaN where the data gives none")
      .def_property_readonly("name", [](const Mesh& mesh) { return mesh.source.path; })
      .def_property_readonly("warnings", [](const Mesh& mesh) { return mesh.source.warnings; })
      .def_property_readonly("load_seconds", [](const Mesh& mesh) { return mesh.source.loadSeconds; })
      .def("__repr__", [](const Mesh& mesh) {
        return fmt::format("<lancer.Mesh '{}': {} points, {} faces, {} physical groups>", mesh.source.path,
                           mesh.positions.size(), mesh.faces.size(), mesh.physicalGroups.size());
      });
  module.def(
      "read_msh",
      [](const std::string& path, int threads, const std::vector<std::string>& views) {
        requireThreads(threads);
        std::shared_ptr<Mesh> mesh;
        {
          py::gil_scoped_release release;
          mesh = std::make_shared<Mesh>(readMeshFile(path, threads));
          addViewFiles(*mesh, views);
        }
        warnUser(mesh->source.warnings);
        return mesh;
      },
      py::arg("path"), py::arg("threads") = 0, py::arg("views") = std::vector<std::string>{},
      "Reads a mesh file as the lancer command does: a gmsh .msh (MSH 2.2, 4.0, 4.1), a list-based .pos "
      "view, or an STL, OBJ or PLY surface (told apart by content) "
      "(threads: for the assembly after the parse, 0: every core; the mesh is the same for any count); "
      "views: list-based .pos files put on the mesh by their elements' coordinates, each step of each "
      "view an element-node field");
  module.def("_mesh_from_elements", &meshFromElementBlocks, py::arg("points"), py::arg("blocks"),
             py::arg("group_names"), py::arg("name"), py::arg("node_fields"), py::arg("element_fields"),
             py::arg("element_node_fields") = py::list(), py::arg("keep_volume") = false);
}

}  // namespace lancer::python
