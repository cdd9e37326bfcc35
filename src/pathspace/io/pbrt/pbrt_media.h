// pbrt-v4 participating media for the scene builder (pbrt_builder.h): MakeNamedMedium's homogeneous,
// uniformgrid and rgbgrid media become SceneMedia records (scene/scene_media.h), and MediumInterface
// names which media the shapes, lights and camera created after it separate or sit in. Names are
// resolved when the scene is finished, as pbrt-v4 creates its media after parsing: a medium may be
// defined after the MediumInterface that names it, but it must be defined somewhere.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_materials.h"
#include "pathspace/io/pbrt/pbrt_statement.h"
#include "pathspace/io/pbrt/pbrt_transform.h"
#include "pathspace/scene/scene.h"

namespace pathspace::pbrt {

// The affine map from world space to the unit cube of a grid that spans the box [lo, hi] (per axis,
// either order) of the space `world_from_box` places in the world: the rows of
// Medium::world_to_grid. False when the box is flat or the transform singular. Shared with the
// Mitsuba loader (its volumes' to_world and bounding boxes).
bool world_to_unit_box(const Mat4& world_from_box, const double lo[3], const double hi[3], float out[12]);

// How many triangles, spheres and lights a scene holds: what a statement added lies between two counts.
struct SceneCounts {
  size_t triangles = 0, spheres = 0, lights = 0;
  static SceneCounts of(const Scene& s) { return {s.triangles.size(), s.spheres.size(), s.lights.size()}; }
};

// Binds what was added between `before` and `after` to interface m: the triangles and spheres
// separate its media when they differ (a shape with one medium on both sides is no boundary), the
// lights (area lights included) emit into m.outside. Shared with the Mitsuba loader.
void bind_added(const MediumInterface& m, const SceneCounts& before, const SceneCounts& after, SceneMedia* media);

class PbrtMedia {
 public:
  // MakeNamedMedium: the medium, placed by `ctm` (its CTM: medium space to world), is added to
  // *media. Errors (at the statement or parameter): a redefined name, an unknown type, negative or
  // non-finite coefficients, a grid whose value count does not match nx * ny * nz, |g| >= 1.
  void define(const Statement& st, const Mat4& ctm, const TextureTable& textures, LoadWarnings* w, SceneMedia* media);
  // MediumInterface "inside" "outside" (one name: both): the id the graphics state keeps; -1 when
  // both sides are vacuum ("").
  int interface_of(const Statement& st);
  // What was created between `before` and `after` under interface `id` (the graphics state's):
  // shapes separate its two media when they differ, lights emit into its outside medium.
  void bind(int id, const SceneCounts& before, const SceneCounts& after);
  // What was created between `before` and `after` with a material whose interior is medium
  // `interior` (pbrt-v4's subsurface): shapes separate it from the outside medium of interface `id`
  // (vacuum when -1); it overrides bind() for those shapes.
  void bind_interior(int id, uint32_t interior, const SceneCounts& before, const SceneCounts& after);
  // pbrt-v4's CameraMedium: the outside medium of the interface current at Camera.
  void bind_camera(int id) { camera_ = id; }
  // Resolves the names into *media's bindings; a name no MakeNamedMedium defines is an Error at the
  // MediumInterface that names it.
  void finish(SceneMedia* media) const;

 private:
  struct Interface {
    std::string inside, outside;
    FileLoc loc;
  };
  struct Binding {
    int id;
    SceneCounts before, after;
    int32_t interior = -1;  // >= 0: the shapes' inside medium (bind_interior)
  };
  int32_t resolve(const std::string& name, const FileLoc& loc) const;

  std::map<std::string, uint32_t> named_;
  std::vector<Interface> interfaces_;
  std::vector<Binding> bindings_;
  int camera_ = -1;
};

}  // namespace pathspace::pbrt
