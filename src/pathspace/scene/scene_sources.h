// Where a scene's elements came from: the file, line and column of the statement that made each
// vertex, sphere, material, light and texture, and the camera, as far as the loader knows them
// (pbrt and Mitsuba files: the statement or element; glTF, OBJ, PLY: the file). Scene validation
// (scene_validation.h) puts it in front of its messages, so that a bad value in a scene file is
// reported at file:line:column like a syntax error. Built-in scenes have none.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace {

class SceneSources {
 public:
  enum Kind { kVertex, kSphere, kMaterial, kLight, kTexture, kKinds };

  // Elements [begin, end) of `kind` came from `at`. Ranges are recorded in increasing order of
  // begin (as loaders add elements); an empty range or an unknown location records nothing.
  void mark(Kind kind, size_t begin, size_t end, const FileLoc& at);
  // Where element i of `kind` came from: its range's location, else the fallback; nullptr when
  // neither is known.
  const FileLoc* find(Kind kind, size_t i) const;

  void set_camera(const FileLoc& at) { camera_ = at; }
  const FileLoc* camera() const;
  // For elements no range covers (formats without line numbers, elements a loader adds at the end):
  // the scene file itself.
  void set_fallback(const FileLoc& at) { fallback_ = at; }

  bool empty() const;

 private:
  struct Range {
    size_t begin, end;
    FileLoc at;
  };
  const FileLoc* fallback() const { return fallback_.file.empty() ? nullptr : &fallback_; }

  std::array<std::vector<Range>, kKinds> ranges_;
  FileLoc camera_, fallback_;
};

}  // namespace pathspace
