// UsageError: a mistake in how a command was called (bad value, unknown name), by the CLI or by a
// study's options. The CLI's main() prints it as one line with a hint (by default: see --help) and
// exits with status 2; other errors exit with 1.
#pragma once

#include <string>

#include "pathspace/base/error.h"

namespace pathspace {

class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message, std::string hint = {}) : Error(message), hint_(std::move(hint)) {}
  // Empty: main() points at the command's --help.
  const std::string& hint() const { return hint_; }

 private:
  std::string hint_;
};

}  // namespace pathspace
