// lancer.from_gmsh's list-based views (a merged .pos): the arrays gmsh.view.getListData gives, per
// view and element code, made into the parsed views of the .pos reader (mesh/pos/pos_reader.hpp) and
// put on the mesh by their elements' coordinates exactly as `lancer render m.msh a.pos` puts a file's.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "lancer/mesh/pos/pos_on_mesh.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"

namespace lancer::python {
namespace {

// One element code's elements: gmsh's list layout per element, the x of every node, then the y's, the
// z's, then the values (per step, per node, per component). Returns the step count it holds.
int appendBlock(PosView& view, const std::string& where, const std::string& code, std::size_t elements,
                const py::array_t<double, py::array::c_style | py::array::forcecast>& data) {
  const std::optional<PosElementKind> kind = posElementKind(code);
  if (!kind)
    throw InputError(
        SourceLocation{where},
        fmt::format("element code '{}' is not a list-based view's: use {}", code, posElementCodeHelp()));
  const auto size = static_cast<std::size_t>(data.size());
  const auto nodes = static_cast<std::size_t>(kind->nodes);
  const std::size_t perStepPerElement = nodes * static_cast<std::size_t>(kind->components);
  if (elements == 0 || size % elements != 0 || size / elements < 3 * nodes ||
      (size / elements - 3 * nodes) % perStepPerElement != 0 || size / elements == 3 * nodes)
    throw InputError(
        SourceLocation{where},
        fmt::format("{} {} elements hold {} numbers: each needs 3 x {} coordinates, then {} values "
                    "per time step",
                    elements, code, size, nodes, perStepPerElement));
  const std::size_t stride = size / elements;
  const int steps = static_cast<int>((stride - 3 * nodes) / perStepPerElement);
  PosElementBlock block;
  block.kind = *kind;
  block.coords.reserve(elements * 3 * nodes);
  block.values.reserve(elements * (stride - 3 * nodes));
  const double* in = data.data();
  for (std::size_t e = 0; e < elements; ++e, in += stride) {
    for (std::size_t n = 0; n < nodes; ++n)
      for (std::size_t axis = 0; axis < 3; ++axis) block.coords.push_back(in[axis * nodes + n]);
    for (std::size_t v = 3 * nodes; v < stride; ++v) {
      if (!std::isfinite(in[v]) || std::abs(in[v]) > 3.4e38)
        throw InputError(
            SourceLocation{where},
            fmt::format("{} element {} has the value {:g}: values must be finite floats", code, e, in[v]));
      block.values.push_back(static_cast<float>(in[v]));
    }
    block.lines.push_back(0);
  }
  view.blocks.push_back(std::move(block));
  return steps;
}

}  // namespace

void bindListViews(py::module_& module) {
  module.def(
      "_add_list_views",
      [](Mesh& mesh, const py::list& views, const std::string& source) {
        PosFile pos;
        pos.file = source;
        for (const py::handle item : views) {
          const auto [name, blocks] = item.cast<std::pair<std::string, py::list>>();
          PosView view;
          view.name = name;
          const std::string where = fmt::format("{}: view \"{}\"", source, name);
          for (const py::handle block : blocks) {
            const auto [code, elements, data] =
                block.cast<std::tuple<std::string, std::size_t,
                                      py::array_t<double, py::array::c_style | py::array::forcecast>>>();
            if (elements == 0) continue;
            const int steps = appendBlock(view, where, code, elements, data);
            if (view.stepCount != 0 && steps != view.stepCount)
              throw InputError(SourceLocation{where},
                               fmt::format("its {} elements have {} time steps, its others {}: every element "
                                           "of a view has the same steps",
                                           code, steps, view.stepCount));
            view.stepCount = steps;
          }
          // gmsh's API gives no list view's times: its steps are timed 0, 1, 2, ... (gmsh's default).
          for (int step = 0; step < view.stepCount; ++step) view.times.push_back(step);
          pos.views.push_back(std::move(view));
        }
        const py::gil_scoped_release release;
        addPosViews(mesh, pos);
      },
      py::arg("mesh"), py::arg("views"), py::arg("source"),
      "Puts list-based views ((name, [(code, element count, data), ...]) as gmsh.view.getListData gives "
      "them) on the mesh by their elements' coordinates, each step an element-node field");
}

}  // namespace lancer::python
