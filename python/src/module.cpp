// pathspace._core: the compiled half of the `pathspace` Python package (docs/python.md).
#include "bindings.h"

#include "pathspace/session/render.h"

PYBIND11_MODULE(_core, m) {
  using namespace pathspace::python;
  m.doc() = "The compiled core of the pathspace package; use `import pathspace`.";
  m.attr("build_type") = pathspace::build_type();
  bind_errors(m);
  bind_options(m);
  bind_scene(m);
  bind_images(m);
  bind_render(m);
}
