#include "pathspace/study/record.h"

#include "pathspace/base/error.h"

namespace pathspace::study {

Record& Record::put(std::string name, Value v) {
  for (Field& f : fields_)
    if (f.name == name) {
      f.value = std::move(v);
      return *this;
    }
  fields_.push_back({std::move(name), std::move(v)});
  return *this;
}

const Value* Record::find(std::string_view name) const {
  for (const Field& f : fields_)
    if (f.name == name) return &f.value;
  return nullptr;
}

double Record::number(std::string_view name) const {
  const Value* v = find(name);
  if (!v || !is_number(*v)) throw Error("study: no number '" + std::string(name) + "' in the record");
  return as_number(*v);
}

void Record::merge(const Record& other) {
  for (const Field& f : other.fields_) put(f.name, f.value);
}

bool is_number(const Value& v) { return std::holds_alternative<int64_t>(v) || std::holds_alternative<double>(v); }

double as_number(const Value& v) {
  if (const int64_t* i = std::get_if<int64_t>(&v)) return double(*i);
  if (const double* d = std::get_if<double>(&v)) return *d;
  return 0.0;
}

nlohmann::ordered_json to_json(const Value& v) {
  return std::visit(
      [](const auto& x) -> nlohmann::ordered_json {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::monostate>)
          return nullptr;
        else
          return x;
      },
      v);
}

nlohmann::ordered_json to_json(const Record& r) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const Field& f : r.fields()) j[f.name] = to_json(f.value);
  return j;
}

}  // namespace pathspace::study
