// The parts of the extension module pathspace._core (docs/python.md), each added by one bind_*
// function in its own file. The package's Python files (python/pathspace/) wrap them into the
// public API: keyword arguments, progress bars and the exception classes users catch.
#pragma once

#include <pybind11/pybind11.h>

namespace pathspace::python {

namespace py = pybind11;

void bind_errors(py::module_& m);   // errors.cpp: pathspace.Error, SceneError; OptionError -> ValueError
void bind_options(py::module_& m);  // options.cpp: the registry's option catalog, integrators, filters
void bind_scene(py::module_& m);    // scene.cpp: Scene, Camera, builtin_scenes
void bind_images(py::module_& m);   // images.cpp: read_image, write_image, compare
void bind_render(py::module_& m);   // render.cpp: _render, _native_render_seconds

}  // namespace pathspace::python
