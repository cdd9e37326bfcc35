// An image size given as an option, "WxH", parsed by the checked parsers of option_parse.h: the
// CLI's --resolution and the studies' (studies/common/study_setup.h) share it.
#pragma once

#include <string>

namespace pathspace {

struct Resolution {
  int width = 0, height = 0;
};

// "WxH" (or "WXH"), each side a whole number 1 ... max_side; throws UsageError naming --option.
Resolution parse_resolution_option(const std::string& option, const std::string& text, int max_side);

}  // namespace pathspace
