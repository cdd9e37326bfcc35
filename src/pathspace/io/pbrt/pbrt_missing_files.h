// Files a pbrt scene references but that do not exist (image textures, environment maps, PLY meshes).
// The builder records every one and fails once at the end of the scene, so a user fixing a scene
// sees the whole list at once instead of one file per run. With
// SceneLoadOptions::substitute_missing_textures, images are replaced by neutral stand-ins instead.
#pragma once

#include <string>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace::pbrt {

// Stand-ins for missing images (substitute_missing_textures): a mid-grey texture and a white
// environment, values that keep a scene's light balance plausible without guessing colours.
inline constexpr float kMissingTextureValue = 0.5f;
inline constexpr float kMissingEnvironmentRadiance = 1.f;

class MissingFiles {
 public:
  // `what` names the kind ("texture file"), `name` is the file as written in the scene.
  void add(const FileLoc& loc, const std::string& what, const std::string& name) { missing_.push_back({loc, what + " '" + name + "'"}); }
  bool empty() const { return missing_.empty(); }

  // One Error (at the first reference) that lists each missing file with its referencing location.
  [[noreturn]] void fail(const std::string& hint) const {
    std::string m = std::to_string(missing_.size()) + (missing_.size() == 1 ? " referenced file is" : " referenced files are") + " missing: ";
    for (size_t i = 0; i < missing_.size(); ++i) m += (i ? "; " : "") + missing_[i].text + " at " + missing_[i].loc.to_string();
    throw Error(missing_.front().loc, m + (hint.empty() ? "" : " (" + hint + ")"));
  }

 private:
  struct Entry {
    FileLoc loc;
    std::string text;
  };
  std::vector<Entry> missing_;
};

}  // namespace pathspace::pbrt
