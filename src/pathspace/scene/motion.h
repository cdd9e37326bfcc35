// Motion blur (pbrt-v4's ActiveTransform, Embree's motion blur geometry of two time steps): a scene
// that moves while the shutter is open holds its triangles' vertices (and normals) at shutter open,
// Scene::positions, and at shutter close, Scene::positions_end. At time t in [0, 1) a vertex is the
// linear blend of the two, as Embree interpolates them, so the hit points computed here lie on the
// triangles Embree intersected. Every path samples one time, uniform over the shutter
// (sample_time), and every ray and hit of the path carries it (Ray::time, SurfaceHit::time):
// shading, light sampling at moving emitters and shadow rays all see the scene at that instant.
// The camera moves too (camera_at): camera rays start from it, and light paths' camera connections
// project through it, at the path's time (the filters' level of detail keeps the shutter-open
// camera). Point, spot and projector lights move on straight lines (lights/light.h,
// light_position), keeping their orientation. Spheres do not move. Still scenes read no time
// dimension, so their images do not change.
#pragma once

#include <cstdint>

#include "pathspace/geometry/shapes.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

PS_INLINE bool scene_moves(const SceneView& s) { return s.positions_end != nullptr || s.camera_moves || s.lights_move; }

// The camera at time t: the shutter-open camera itself when it stands still.
PS_INLINE PerspectiveCamera camera_at(const SceneView& s, float time) {
  return s.camera_moves ? camera_towards(s.camera, s.camera_end, time) : s.camera;
}

// Vertex v at time t.
PS_INLINE Vec3 vertex_at(const SceneView& s, uint32_t v, float time) {
  if (!s.positions_end) return s.positions[v];
  return s.positions[v] * (1.f - time) + s.positions_end[v] * time;
}

struct TriangleVertices {
  Vec3 p0, p1, p2;
};

PS_INLINE TriangleVertices triangle_at(const SceneView& s, const Triangle& tri, float time) {
  return {vertex_at(s, tri.v[0], time), vertex_at(s, tri.v[1], time), vertex_at(s, tri.v[2], time)};
}

// The time of a path: uniform over the shutter (sampler dimension `dimension`) in a scene that
// moves, 0 without reading the sampler in a still one.
PS_INLINE float sample_time(const SceneView& s, const Sampler& sampler, uint32_t dimension) {
  return scene_moves(s) ? sampler.at(dimension) : 0.f;
}

}  // namespace pathspace
