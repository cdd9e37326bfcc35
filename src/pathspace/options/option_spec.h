// OptionSpec: one user-settable option of an integrator or filter, described as data (name, type,
// default, range or choices, help, paper section). The CLI builds --help, validation and its error
// messages from these; `pathspace info --integrators --json` prints them for tools and bindings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace {

enum class OptionType : uint8_t {
  flag,     // given or not; giving it sets its field to a fixed value (e.g. --no-nee)
  integer,  // whole number within [min, max]
  real,     // finite number within [min, max]
  choice,   // one of `choices`
  size,     // "WxH": two whole numbers, each within [min, max] (an image size)
};

const char* option_type_name(OptionType type);

struct OptionSpec {
  std::string name;          // without dashes: "pclt-alpha" is --pclt-alpha
  OptionType type = OptionType::flag;
  std::string default_text;  // the default as the user would write it ("0.6666667", "box", "off")
  double min = 0.0, max = 0.0;       // integer and real options
  std::vector<std::string> choices;  // choice options
  std::string help;
  std::string paper;         // the paper section it implements ("PCLT paper eq. 1"); may be empty

  // Same meaning for the user (type, range, choices, default): options shared by several
  // integrators (--max-depth) must agree on these, help text may differ.
  bool same_contract(const OptionSpec& other) const;
};

// A mistake in the options a caller gave (unknown option, bad value, option of another integrator).
// The CLI reports it as a usage error (exit status 2).
class OptionError : public Error {
 public:
  explicit OptionError(const std::string& message) : Error(message) {}
};

}  // namespace pathspace
