// OptionTable<Settings>: the options of one integrator or filter, each bound to a field of its
// settings struct. The table is the single definition of an option: its name, type, range or
// choices, help and paper section, and where its value goes. Defaults are read from a
// default-constructed Settings, so they cannot drift from the struct.
//
//   OptionTable<SppmSettings> t;
//   t.number("sppm-alpha", &SppmSettings::alpha, 1e-3, 1.0, "Knaus-Zwicker radius reduction", "PCLT eq. 1");
//   t.apply(given, &settings);  // only the names this table knows; throws OptionError on bad values
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "pathspace/options/option_parse.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/options/option_values.h"

namespace pathspace {

template <typename Settings>
class OptionTable {
 public:
  // Cross-option rules on the finished settings (e.g. two options that exclude each other).
  using Check = std::function<void(const Settings&)>;

  // An integer or real option. `field` is a data member pointer or a callable Settings& -> T&
  // (values() reads through it with a const_cast; it never writes there).
  template <typename Field>
  OptionTable& number(std::string name, Field field, double min, double max, std::string help, std::string paper = {}) {
    using T = std::remove_reference_t<std::invoke_result_t<Field, Settings&>>;
    static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, "number() needs an arithmetic field");
    OptionSpec spec = make_spec(name, std::is_integral_v<T> ? OptionType::integer : OptionType::real, help, paper);
    spec.min = min;
    spec.max = max;
    spec.default_text = number_text(widen(std::invoke(field, defaults_)));
    add(std::move(spec), [field](const Settings& s) { return number_text(widen(std::invoke(field, const_cast<Settings&>(s)))); },
        [field, name, min, max](Settings& s, const std::string& text) {
      T& target = std::invoke(field, s);
      if constexpr (std::is_integral_v<T>)
        target = T(parse_integer_option(name, text, min, max));
      else if constexpr (std::is_same_v<T, float>)
        target = parse_float_option(name, text, min, max);
      else
        target = T(parse_double_option(name, text, min, max));
    });
    return *this;
  }

  // A flag: giving it stores `value_when_given` (e.g. --no-nee stores nee = false).
  template <typename Field>
  OptionTable& flag(std::string name, Field field, bool value_when_given, std::string help, std::string paper = {}) {
    OptionSpec spec = make_spec(name, OptionType::flag, help, paper);
    spec.default_text = "off";
    add(std::move(spec),
        [field, value_when_given](const Settings& s) {
          return std::string(std::invoke(field, const_cast<Settings&>(s)) == value_when_given ? "on" : "off");
        },
        [field, value_when_given](Settings& s, const std::string&) { std::invoke(field, s) = value_when_given; });
    return *this;
  }

  // One of named values (an enum, or anything comparable).
  template <typename Field, typename Value>
  OptionTable& choice(std::string name, Field field, std::vector<std::pair<std::string, Value>> choices, std::string help,
                      std::string paper = {}) {
    OptionSpec spec = make_spec(name, OptionType::choice, help, paper);
    for (const auto& [text, value] : choices) {
      spec.choices.push_back(text);
      if (value == std::invoke(field, defaults_)) spec.default_text = text;
    }
    add(std::move(spec),
        [field, choices](const Settings& s) {
          for (const auto& [t, value] : choices)
            if (value == std::invoke(field, const_cast<Settings&>(s))) return t;
          return std::string("?");
        },
        [field, name, choices](Settings& s, const std::string& text) {
      for (const auto& [t, value] : choices)
        if (t == text) {
          std::invoke(field, s) = value;
          return;
        }
      std::string list;
      for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c.first;
      throw OptionError(option_message(name, text, "expects one of " + list));
    });
    return *this;
  }

  // How the default of the option added last is shown when its value is a sentinel ("the scene's").
  OptionTable& shows_default(std::string text) {
    entries_.back().spec.default_text = std::move(text);
    return *this;
  }

  OptionTable& check(Check rule) {
    checks_.push_back(std::move(rule));
    return *this;
  }

  std::vector<OptionSpec> specs() const {
    std::vector<OptionSpec> out;
    for (const Entry& e : entries_) out.push_back(e.spec);
    return out;
  }

  bool has(const std::string& name) const {
    for (const Entry& e : entries_)
      if (e.spec.name == name) return true;
    return false;
  }

  // Every option's current value as the user would write it, by name, in table order (the settings'
  // fingerprint, SettingsSchema::describe, and the options a checkpoint stores).
  std::vector<std::pair<std::string, std::string>> values(const Settings& settings) const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const Entry& e : entries_) out.emplace_back(e.spec.name, e.text(settings));
    return out;
  }

  // Stores every given option that this table knows into *settings (others are left to the caller),
  // then applies the cross-option checks.
  void apply(const OptionValues& given, Settings* settings) const {
    for (const auto& [name, text] : given.items())
      for (const Entry& e : entries_)
        if (e.spec.name == name) e.set(*settings, text);
    for (const Check& rule : checks_) rule(*settings);
  }

 private:
  struct Entry {
    OptionSpec spec;
    std::function<std::string(const Settings&)> text;
    std::function<void(Settings&, const std::string&)> set;
  };

  static OptionSpec make_spec(const std::string& name, OptionType type, const std::string& help, const std::string& paper) {
    OptionSpec spec;
    spec.name = name;
    spec.type = type;
    spec.help = help;
    spec.paper = paper;
    return spec;
  }
  template <typename T>
  static auto widen(T v) {
    if constexpr (std::is_integral_v<T>)
      return int64_t(v);
    else
      return v;
  }
  void add(OptionSpec spec, std::function<std::string(const Settings&)> text, std::function<void(Settings&, const std::string&)> set) {
    if (has(spec.name)) throw OptionError("option --" + spec.name + " is defined twice in one table");
    entries_.push_back({std::move(spec), std::move(text), std::move(set)});
  }

  Settings defaults_{};
  std::vector<Entry> entries_;
  std::vector<Check> checks_;
};

}  // namespace pathspace
