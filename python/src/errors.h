// How C++ errors reach Python: a scene that cannot be loaded raises pathspace.SceneError (with the
// file:line:column message), a bad option value ValueError with the CLI's message, any other
// pathspace::Error pathspace.Error.
#pragma once

#include <string>

#include "pathspace/base/error.h"

namespace pathspace::python {

// Thrown by the bindings for errors of loading a scene: translated into pathspace.SceneError.
class SceneLoadError : public Error {
 public:
  explicit SceneLoadError(const Error& e) : Error(e.location(), message_of(e)), file(e.location().file), line(e.location().line), column(e.location().column) {}
  std::string file;
  int line = 0, column = 0;

 private:
  // The message without the location prefix Error's constructor adds again.
  static std::string message_of(const Error& e) {
    const std::string what = e.what(), prefix = e.location().to_string() + ": ";
    return !e.location().file.empty() && what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
  }
};

}  // namespace pathspace::python
