#include "pathspace/options/resolution_option.h"

#include "pathspace/options/option_parse.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/options/usage_error.h"

namespace pathspace {

Resolution parse_resolution_option(const std::string& option, const std::string& text, int max_side) {
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos || x == 0 || x + 1 == text.size())
    throw UsageError("--" + option + " expects WxH, e.g. 512x512, not '" + text + "'");
  try {
    Resolution r;
    r.width = int(parse_integer_option(option, text.substr(0, x), 1, max_side));
    r.height = int(parse_integer_option(option, text.substr(x + 1), 1, max_side));
    return r;
  } catch (const OptionError&) {
    throw UsageError("--" + option + " '" + text + "': width and height must be whole numbers between 1 and " +
                     std::to_string(max_side));
  }
}

}  // namespace pathspace
