// pbrt-v4 scene loading: the statement stream of pbrt_parser.h, executed by the scene builder
// (pbrt_builder.h) against a graphics state (current transform, material, area light, attribute
// stack), fills a pathspace Scene. Film, Camera, Sampler and Integrator set resolution, camera,
// default spp and path length (pbrt's maxdepth counts bounces; pathspace counts segments, so
// max_path_segments = maxdepth + 1).
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace::pbrt {

Scene load_pbrt_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings,
                     SceneFileSettings* settings);
// For tests: parse `text` as if it were a file named `name` in `folder`.
Scene load_pbrt_string(const std::string& text, const std::string& name, const std::string& folder,
                       const SceneLoadOptions& options, LoadWarnings* warnings, SceneFileSettings* settings);

}  // namespace pathspace::pbrt
