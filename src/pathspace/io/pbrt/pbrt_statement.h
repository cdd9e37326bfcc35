// One parsed pbrt-v4 statement: directive, positional arguments and its typed parameter list
// ("float radius" [ 1 ]). Parameters remember whether the scene builder read them, so every
// parameter that pathspace does not support becomes a warning with its file:line:column.
#pragma once

#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace::pbrt {

struct Param {
  std::string type, name;         // "float", "radius"
  std::vector<double> numbers;
  std::vector<std::string> strings;
  std::vector<bool> bools;
  FileLoc loc;
  mutable bool used = false;
};

struct Statement {
  std::string directive;             // "Shape", "Translate", ...
  FileLoc loc;
  std::vector<std::string> strings;  // leading string arguments: Shape "sphere" -> {"sphere"}
  std::vector<double> numbers;       // numeric arguments: Translate 1 2 3
  std::vector<Param> params;

  // Lookups mark the parameter used. A parameter of the wrong type is an Error at its location.
  const Param* find(const std::string& name) const;
  double get_float(const std::string& name, double fallback) const;
  int get_int(const std::string& name, int fallback) const;
  bool get_bool(const std::string& name, bool fallback) const;
  std::string get_string(const std::string& name, const std::string& fallback) const;
  std::vector<double> get_numbers(const std::string& name) const;  // any numeric type
  // Marks parameters as used without reading them (harmless ones: they do not change the image).
  void ignore(std::initializer_list<const char*> names) const;
  // "Shape \"sphere\"" for messages.
  std::string title() const;
};

}  // namespace pathspace::pbrt
