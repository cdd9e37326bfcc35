// Mitsuba shapes as pathspace geometry in world space: obj (tinyobjloader via obj_loader), ply
// (ply_reader), rectangle, cube, sphere (analytic under a similarity transform, else triangulated)
// and disk (triangulated, area-preserving). Winding follows Mitsuba's normals: the to_world normal
// of analytic shapes, the world-space winding of meshes; flip_normals reverses both.
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_object.h"
#include "pathspace/scene/scene.h"

namespace pathspace::mitsuba {

// The sensor's shutter interval, in the animations' time.
struct Shutter {
  double open = 0.0, close = 0.0;
};

// Where an <shape type="instance"> places the shapes of its shapegroup: its to_world at shutter
// open and close (identity for a shape that stands on its own).
struct InstanceTransform {
  Mat4 open, close;
};
InstanceTransform instance_transform(const Object& instance, const Shutter& shutter, LoadWarnings* w);

// Adds shape `o` with `material`; a non-black `radiance` makes it a one-sided area emitter (Mitsuba's
// area lights emit on the normal's side). Mesh files resolve against `folder`. A to_world animated
// over the shutter (<animation>) gives the shape its vertices at shutter open and close (motion
// blur, scene/motion.h); a moving sphere becomes a mesh. A shape of a shapegroup is added once per
// instance, under `instance` (instancing by copies: each instance's triangles are the scene's own).
void add_shape(const Object& o, uint32_t material, const Rgb& radiance, const std::string& folder, const Shutter& shutter,
               LoadWarnings* w, Scene* scene, const InstanceTransform& instance = {});

}  // namespace pathspace::mitsuba
