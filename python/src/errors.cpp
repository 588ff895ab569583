// lancer.InputError: the library's InputError as a Python exception (a ValueError) carrying the
// location in the user's file, with the CLI's one-line message as str(); and lancer.LancerWarning
// (a UserWarning), what the readers and the scene builder warn about, through Python's warnings.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::python {
namespace {

// Created once and kept for the interpreter's life, as pybind11's own exception types are.
py::handle lancerWarningType() {
  static py::handle type = PyErr_NewExceptionWithDoc(
      "lancer.LancerWarning",
      "What lancer read and accepted but the user should hear about (a reader's \"file:line: warning: "
      "...\" line, as the lancer command prints it on stderr)",
      PyExc_UserWarning, nullptr);
  return type;
}

}  // namespace

void warnUser(const std::string& message, int stackLevel) {
  if (PyErr_WarnEx(lancerWarningType().ptr(), message.c_str(), stackLevel) != 0)
    throw py::error_already_set();
}

void warnUser(const std::vector<std::string>& messages, int stackLevel) {
  for (const std::string& message : messages) warnUser(message, stackLevel);
}

void bindErrors(py::module_& module) {
  module.attr("LancerWarning") = lancerWarningType();
  // Created once and kept for the interpreter's life, as pybind11's own exception types are.
  static py::handle inputError =
      PyErr_NewExceptionWithDoc("lancer.InputError",
                                "Bad input: a mesh or scene file, or a value given to lancer. str() is the "
                                "message the lancer command prints; .file, .line, .column (0 when unknown) "
                                "and .byte_offset (-1 unless a binary file) locate it.",
                                PyExc_ValueError, nullptr);
  module.attr("InputError") = inputError;
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& error) {
      const SourceLocation& where = error.location();
      py::object exception = py::reinterpret_borrow<py::object>(inputError)(error.what());
      exception.attr("file") = where.file;
      exception.attr("line") = where.line;
      exception.attr("column") = where.column;
      exception.attr("byte_offset") = where.byteOffset;
      exception.attr("message") = error.message();
      PyErr_SetObject(inputError.ptr(), exception.ptr());
    }
  });
}

}  // namespace lancer::python
