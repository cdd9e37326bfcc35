// OptionValues: the options a caller gave, by name, as text (from a command line, a Python keyword
// argument or a study definition). Interpreting them is the job of an OptionTable.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pathspace {

class OptionValues {
 public:
  // Flags are given with an empty value.
  void set(std::string name, std::string value = {});  // replaces a value given before
  void erase(const std::string& name);
  bool has(const std::string& name) const { return find(name) != nullptr; }
  const std::string* find(const std::string& name) const;
  const std::vector<std::pair<std::string, std::string>>& items() const { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  std::vector<std::pair<std::string, std::string>> items_;  // in the order given; names unique
};

}  // namespace pathspace
