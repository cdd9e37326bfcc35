// The Mitsuba loader's tests: a scene from XML text, with the warnings the loader gave.
#pragma once

#include <string>
#include <vector>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"

namespace pathspace::testing {

struct LoadedMitsuba {
  Scene scene;
  std::vector<std::string> warnings;
};

// `text` as the file "scene.xml" in `folder` (where its relative paths resolve).
inline LoadedMitsuba load_mitsuba_text(const std::string& text, const std::string& folder = ".") {
  LoadedMitsuba r;
  LoadWarnings w(&r.warnings);
  r.scene = mitsuba::load_mitsuba_string(text, "scene.xml", folder, {}, &w, nullptr);
  return r;
}

}  // namespace pathspace::testing
