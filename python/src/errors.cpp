#include "errors.h"

#include "bindings.h"
#include "pathspace/options/option_spec.h"

namespace pathspace::python {

void bind_errors(py::module_& m) {
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  error.doc() = "A pathspace error: an unreadable image, a failed write, a scene the renderer cannot render.";
  static py::exception<SceneLoadError> scene_error(m, "SceneError", error.ptr());
  scene_error.doc() = "A scene that cannot be loaded; str() is the message with its file:line:column, "
                      "and .file, .line and .column hold the location (line and column 0: unknown).";
  // Translators registered later are tried first: the most specific type last.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneLoadError& e) {
      py::object exc = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      exc.attr("file") = e.file;
      exc.attr("line") = e.line;
      exc.attr("column") = e.column;
      PyErr_SetObject(scene_error.ptr(), exc.ptr());
    } catch (const OptionError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
}

}  // namespace pathspace::python
