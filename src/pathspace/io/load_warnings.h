// Warnings collected while loading a scene file: each names the file:line:column of the statement or
// parameter that pathspace does not support (or only approximates). The CLI prints them; tests read
// them. Repeated identical warnings are kept once.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace {

class LoadWarnings {
 public:
  explicit LoadWarnings(std::vector<std::string>* out) : out_(out) {}
  void add(const FileLoc& loc, const std::string& message) {
    const std::string text = (loc.file.empty() ? std::string() : loc.to_string() + ": ") + "warning: " + message;
    if (out_ && seen_.insert(text).second) out_->push_back(text);
  }

 private:
  std::vector<std::string>* out_;
  std::set<std::string> seen_;
};

}  // namespace pathspace
