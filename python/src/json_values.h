// JSON values (the statistics, the option catalog: what the CLI prints as JSON) as Python objects,
// converted value by value: dict, list, str, int, float, bool, None.
#pragma once

#include <nlohmann/json.hpp>

#include "bindings.h"

namespace pathspace::python {

py::object python_of(const nlohmann::ordered_json& value);

}  // namespace pathspace::python
