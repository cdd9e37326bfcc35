#include "json_values.h"

namespace pathspace::python {

py::object python_of(const nlohmann::ordered_json& j) {
  using Type = nlohmann::ordered_json::value_t;
  switch (j.type()) {
    case Type::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = python_of(value);
      return d;
    }
    case Type::array: {
      py::list l;
      for (const auto& value : j) l.append(python_of(value));
      return l;
    }
    case Type::string: return py::str(j.get<std::string>());
    case Type::boolean: return py::bool_(j.get<bool>());
    case Type::number_integer: return py::int_(j.get<int64_t>());
    case Type::number_unsigned: return py::int_(j.get<uint64_t>());
    case Type::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

}  // namespace pathspace::python
