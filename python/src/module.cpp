// The _lancer extension module: the C++ library's reader, scenes and renderer for lancer/__init__.py.
#include "bindings.hpp"

PYBIND11_MODULE(_lancer, module) {
  module.doc() = "lancer's C++ core; use the lancer package, which wraps it";
  module.attr("__version__") = LANCER_VERSION;  // project(VERSION), as `lancer --version` prints
  lancer::python::bindErrors(module);
  lancer::python::bindMesh(module);
  lancer::python::bindScene(module);
  lancer::python::bindRender(module);
  lancer::python::bindAnimate(module);
  lancer::python::bindImage(module);
  lancer::python::bindVolume(module);
  lancer::python::bindListViews(module);
  lancer::python::bindMemory(module);
}
