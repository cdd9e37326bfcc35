// SettingsSchema: an OptionTable with its settings type erased, so that one registry can hold the
// integrators and filters, each with its own settings struct. Settings travel as std::any holding
// exactly that struct (empty = the defaults).
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include "pathspace/options/option_table.h"

namespace pathspace {

struct SettingsSchema {
  std::vector<OptionSpec> options;
  std::function<std::any()> defaults;
  // Stores the given options that belong to this schema into *settings (defaults first when empty).
  std::function<void(const OptionValues&, std::any*)> apply;
  // The options' values in `settings` (the defaults when empty) as (name, value) pairs,
  // OptionTable::values.
  std::function<std::vector<std::pair<std::string, std::string>>(const std::any&)> values;

  template <typename Settings>
  static SettingsSchema of(OptionTable<Settings> table) {
    auto shared = std::make_shared<OptionTable<Settings>>(std::move(table));
    SettingsSchema schema;
    schema.options = shared->specs();
    schema.defaults = [] { return std::any(Settings{}); };
    schema.apply = [shared](const OptionValues& given, std::any* settings) {
      if (!settings->has_value()) *settings = Settings{};
      shared->apply(given, std::any_cast<Settings>(settings));
    };
    schema.values = [shared](const std::any& settings) {
      return shared->values(settings.has_value() ? std::any_cast<const Settings&>(settings) : Settings{});
    };
    return schema;
  }

  // "name=value name=value ...": a fingerprint of the settings (a restored render must continue with
  // the options it was made with).
  std::string describe(const std::any& settings) const {
    std::string out;
    for (const auto& [name, value] : values(settings)) out += (out.empty() ? "" : " ") + name + "=" + value;
    return out;
  }

  const OptionSpec* find(const std::string& name) const {
    for (const OptionSpec& o : options)
      if (o.name == name) return &o;
    return nullptr;
  }
};

// The settings struct inside `settings` (the defaults when it is empty). Throws pathspace::Error
// when it holds another type: a caller paired the wrong settings with `owner`.
template <typename Settings>
Settings settings_cast(const std::any& settings, const std::string& owner) {
  if (!settings.has_value()) return Settings{};
  if (const Settings* s = std::any_cast<Settings>(&settings)) return *s;
  throw Error("settings for '" + owner + "' have the wrong type (" + settings.type().name() + ")");
}

}  // namespace pathspace
