// pathspace::Error: the one exception type for bad user input (scene files, CLI, images).
// It carries an optional file:line:column location so messages point at the culprit.
#pragma once

#include <stdexcept>
#include <string>

namespace pathspace {

struct FileLoc {
  std::string file;
  int line = 0;    // 1-based; 0 = unknown
  int column = 0;  // 1-based; 0 = unknown

  std::string to_string() const {
    if (file.empty()) return {};
    // Appended piecewise: `s += ":" + std::to_string(n)` trips GCC 12's false -Wrestrict (PR 105329).
    std::string s = file;
    if (line > 0) s.append(1, ':').append(std::to_string(line));
    if (line > 0 && column > 0) s.append(1, ':').append(std::to_string(column));
    return s;
  }
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  Error(const FileLoc& loc, const std::string& message)
      : std::runtime_error(loc.file.empty() ? message : loc.to_string() + ": " + message), loc_(loc) {}
  const FileLoc& location() const { return loc_; }

 private:
  FileLoc loc_;
};

}  // namespace pathspace
