// The registry's option catalog for Python: the package builds render()'s keyword arguments, their
// docstring and its signature from it (python/pathspace/_options.py), so no option is defined twice.
#include <pybind11/stl.h>

#include "bindings.h"
#include "json_values.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/device_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/session/option_catalog.h"

namespace pathspace::python {

namespace {

py::dict option_dict(const CatalogOption& o) {
  py::dict d = python_of(option_spec_json(o.spec));
  d["integrators"] = o.integrators;
  d["filters"] = o.filters;
  return d;
}

}  // namespace

void bind_options(py::module_& m) {
  m.def(
      "option_catalog",
      [] {
        py::list out;
        for (const CatalogOption& o : option_catalog()) out.append(option_dict(o));
        return out;
      },
      "Every integrator and filter option as a dict: name (the CLI's, with dashes), type, default (as the CLI "
      "writes it), min/max or choices, help, paper, and the integrators and filters it belongs to.");
  m.def("integrators", [] { return integrator_registry().names(); }, "The registered integrators' names.");
  m.def("filters", [] { return filter_registry().names(); }, "The registered path space filters' names (besides 'none').");
  m.def("devices", [] { return device_registry().names(); }, "Where passes can run ('cpu', and 'cuda' where built).");
}

}  // namespace pathspace::python
