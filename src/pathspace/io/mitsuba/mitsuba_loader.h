// Mitsuba scene files (.xml, versions 0.6 and 2/3) through pugixml: sensor, film, sampler and
// integrator settings, BSDFs, shapes and emitters (see docs/scene-files.md for the subset). As with
// pbrt files, what pathspace does not support is a warning with file:line:column and malformed input
// (XML syntax included) is a pathspace::Error with its location.
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace::mitsuba {

Scene load_mitsuba_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings,
                        SceneFileSettings* settings);
// Parses `text` as if it were the file `name`; relative mesh and texture paths resolve against `folder`.
Scene load_mitsuba_string(const std::string& text, const std::string& name, const std::string& folder,
                          const SceneLoadOptions& options, LoadWarnings* warnings, SceneFileSettings* settings);

}  // namespace pathspace::mitsuba
