// femto.SceneError: every femto::Error (scene files, bad parameters, output
// paths) reaches Python as one exception type whose text is what the CLI
// prints after "error: ", with the file and line as attributes.
#include <femto/base/error.h>

#include "bindings.h"

namespace py = pybind11;

namespace femto::python {

void bindSceneError(py::module_& m) {
  // Leaked on purpose: the class lives as long as the interpreter.
  static py::handle sceneError = py::exception<Error>(m, "SceneError", PyExc_RuntimeError).release();
  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const Error& e) {
      py::object error = py::reinterpret_borrow<py::object>(sceneError)(e.what());
      const SourceLocation& where = e.where();
      error.attr("message") = py::str(e.what());
      error.attr("file") = where.known() ? py::object(py::str(where.file)) : py::none();
      error.attr("line") = where.known() && where.line > 0 ? py::object(py::int_(where.line)) : py::none();
      PyErr_SetObject(sceneError.ptr(), error.ptr());
    }
  });
}

}  // namespace femto::python
