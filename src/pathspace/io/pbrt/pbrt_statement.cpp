// Parameter lookups for pbrt statements (see pbrt_statement.h).
#include "pathspace/io/pbrt/pbrt_statement.h"

namespace pathspace::pbrt {

namespace {
bool is_numeric_type(const std::string& t) {
  return t == "float" || t == "integer" || t == "point" || t == "point2" || t == "point3" || t == "vector" ||
         t == "vector2" || t == "vector3" || t == "normal" || t == "normal3" || t == "rgb" || t == "color" ||
         t == "spectrum" || t == "blackbody";
}
}  // namespace

const Param* Statement::find(const std::string& name) const {
  for (const Param& p : params)
    if (p.name == name) {
      p.used = true;
      return &p;
    }
  return nullptr;
}

std::vector<double> Statement::get_numbers(const std::string& name) const {
  const Param* p = find(name);
  if (!p) return {};
  if (!is_numeric_type(p->type) || !p->strings.empty()) throw Error(p->loc, "parameter '" + name + "' must be numeric");
  return p->numbers;
}

double Statement::get_float(const std::string& name, double fallback) const {
  const Param* p = find(name);
  if (!p) return fallback;
  if ((p->type != "float" && p->type != "integer") || p->numbers.size() != 1)
    throw Error(p->loc, "parameter '" + name + "' must be one float");
  return p->numbers[0];
}

int Statement::get_int(const std::string& name, int fallback) const {
  const Param* p = find(name);
  if (!p) return fallback;
  if (p->type != "integer" || p->numbers.size() != 1) throw Error(p->loc, "parameter '" + name + "' must be one integer");
  return int(p->numbers[0]);
}

bool Statement::get_bool(const std::string& name, bool fallback) const {
  const Param* p = find(name);
  if (!p) return fallback;
  if (p->type != "bool" || p->bools.size() != 1) throw Error(p->loc, "parameter '" + name + "' must be one bool");
  return p->bools[0];
}

std::string Statement::get_string(const std::string& name, const std::string& fallback) const {
  const Param* p = find(name);
  if (!p) return fallback;
  if (p->strings.size() != 1) throw Error(p->loc, "parameter '" + name + "' must be one string");
  return p->strings[0];
}

void Statement::ignore(std::initializer_list<const char*> names) const {
  for (const char* n : names)
    for (const Param& p : params)
      if (p.name == n) p.used = true;
}

std::string Statement::title() const {
  std::string s = directive;
  for (const std::string& a : strings) s += " \"" + a + "\"";
  return s;
}

}  // namespace pathspace::pbrt
