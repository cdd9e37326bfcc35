#include "pathspace/scene/scene_sources.h"

#include <algorithm>

#include "pathspace/scene/scene.h"

namespace pathspace {

void SceneSources::mark(Kind kind, size_t begin, size_t end, const FileLoc& at) {
  if (begin >= end || at.file.empty()) return;
  std::vector<Range>& r = ranges_[kind];
  // Elements are only appended, so a range never starts before the last one's end.
  if (!r.empty() && begin < r.back().end) return;
  r.push_back({begin, end, at});
}

const FileLoc* SceneSources::find(Kind kind, size_t i) const {
  const std::vector<Range>& r = ranges_[kind];
  // The last range that begins at or before i.
  auto it = std::upper_bound(r.begin(), r.end(), i, [](size_t v, const Range& x) { return v < x.begin; });
  if (it == r.begin()) return fallback();
  --it;
  return i < it->end ? &it->at : fallback();
}

const FileLoc* SceneSources::camera() const { return camera_.file.empty() ? fallback() : &camera_; }

SceneSizes SceneSizes::of(const Scene& s) {
  return {s.positions.size(), s.spheres.size(), s.materials.size(), s.lights.size(), s.textures.size()};
}

void SceneSizes::mark_since(Scene* s, const FileLoc& at) const {
  s->sources.mark(SceneSources::kVertex, vertices, s->positions.size(), at);
  s->sources.mark(SceneSources::kSphere, spheres, s->spheres.size(), at);
  s->sources.mark(SceneSources::kMaterial, materials, s->materials.size(), at);
  s->sources.mark(SceneSources::kLight, lights, s->lights.size(), at);
  s->sources.mark(SceneSources::kTexture, textures, s->textures.size(), at);
}

bool SceneSources::empty() const {
  return camera_.file.empty() && fallback_.file.empty() && std::all_of(ranges_.begin(), ranges_.end(), [](const auto& r) { return r.empty(); });
}

}  // namespace pathspace
