#include "pathspace/options/option_spec.h"

#include "pathspace/options/option_values.h"

namespace pathspace {

const char* option_type_name(OptionType type) {
  switch (type) {
    case OptionType::flag: return "flag";
    case OptionType::integer: return "integer";
    case OptionType::real: return "real";
    case OptionType::choice: return "choice";
    case OptionType::size: return "size";
  }
  return "?";
}

bool OptionSpec::same_contract(const OptionSpec& o) const {
  return name == o.name && type == o.type && default_text == o.default_text && min == o.min && max == o.max &&
         choices == o.choices;
}

void OptionValues::set(std::string name, std::string value) {
  for (auto& [n, v] : items_)
    if (n == name) {
      v = std::move(value);
      return;
    }
  items_.emplace_back(std::move(name), std::move(value));
}

void OptionValues::erase(const std::string& name) {
  std::erase_if(items_, [&](const auto& item) { return item.first == name; });
}

const std::string* OptionValues::find(const std::string& name) const {
  for (const auto& [n, v] : items_)
    if (n == name) return &v;
  return nullptr;
}

}  // namespace pathspace
