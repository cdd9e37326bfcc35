// Record: named values in the order they were set, one row of a results table (a run's settings,
// its metrics, a CSV row). Values are typed (integer, number, flag, text) so that CSV, JSON and HTML
// print each as it is: a byte count stays an integer, a ratio a number.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace pathspace::study {

using Value = std::variant<std::monostate, bool, int64_t, double, std::string>;

struct Field {
  std::string name;
  Value value;
};

class Record {
 public:
  // Sets `name` (in place when it is already there, else appended): integers (any width) become
  // int64, floating-point numbers double, strings text.
  template <typename T>
  Record& set(std::string name, const T& v) {
    if constexpr (std::is_same_v<T, bool>)
      return put(std::move(name), Value(v));
    else if constexpr (std::is_integral_v<T>)
      return put(std::move(name), Value(int64_t(v)));
    else if constexpr (std::is_floating_point_v<T>)
      return put(std::move(name), Value(double(v)));
    else if constexpr (std::is_same_v<T, Value>)
      return put(std::move(name), v);
    else
      return put(std::move(name), Value(std::string(v)));
  }

  // Null when `name` was not set.
  const Value* find(std::string_view name) const;
  bool has(std::string_view name) const { return find(name) != nullptr; }
  // The value of an integer or number field; throws pathspace::Error when missing or not numeric.
  double number(std::string_view name) const;
  // Appends (or replaces) every field of `other`.
  void merge(const Record& other);

  const std::vector<Field>& fields() const { return fields_; }
  bool empty() const { return fields_.empty(); }

 private:
  Record& put(std::string name, Value v);
  std::vector<Field> fields_;
};

// True for int64 and double.
bool is_number(const Value& v);
// Integer or number as double (0 for anything else).
double as_number(const Value& v);

nlohmann::ordered_json to_json(const Value& v);
nlohmann::ordered_json to_json(const Record& r);

}  // namespace pathspace::study
