// SceneView: the device-safe, read-only view of a Scene (raw pointers and counts into the owning
// Scene's flat arrays). Kernels and PS_HD code take a SceneView, never a Scene.
#pragma once

#include <cstdint>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/geometry/shapes.h"
#include "pathspace/lights/environment_map.h"
#include "pathspace/lights/light.h"
#include "pathspace/lights/light_tree_view.h"
#include "pathspace/materials/material.h"
#include "pathspace/media/media_view.h"
#include "pathspace/math/bbox.h"
#include "pathspace/sampling/discrete.h"
#include "pathspace/scene/texture.h"

namespace pathspace {

struct SceneView {
  const Vec3* positions = nullptr;
  const Point2* uvs = nullptr;      // per vertex, or nullptr when no mesh has texture coordinates
  const Vec3* normals = nullptr;    // per vertex (zero = flat), or nullptr when no mesh has normals
  // At shutter close, when the scene moves (scene/motion.h); nullptr in still scenes.
  const Vec3* positions_end = nullptr;
  const Vec3* normals_end = nullptr;  // set when positions_end and normals are
  const Triangle* triangles = nullptr;
  uint32_t num_triangles = 0;
  const Sphere* spheres = nullptr;
  uint32_t num_spheres = 0;
  const Material* materials = nullptr;
  uint32_t num_materials = 0;
  const TextureView* textures = nullptr;  // indexed by Material::*_texture
  uint32_t num_textures = 0;
  const Light* lights = nullptr;
  uint32_t num_lights = 0;
  const float* emission_cells = nullptr;  // mapped area triangles' sampling cells (lights/emission_cells.h)
  uint32_t num_emission_cells = 0;        // floats
  DiscreteView light_selection;     // probability of choosing each light (light paths; NEE unless the tree is active)
  LightTreeView light_tree;         // NEE at a shading point when active (scene/light_sampling.h)
  int32_t environment_light = -1;   // index of the environment light, or -1
  EnvironmentMapView environment_map;  // its image (texels null: constant radiance)
  MediaView media;                  // participating media (count 0: none)
  PerspectiveCamera camera;         // at shutter open
  bool camera_moves = false;        // motion blur: the camera reaches camera_end at shutter close (camera_at)
  CameraPose camera_end;
  bool lights_move = false;         // some point, spot or projector moves (Light::moves)
  BoundingSphere bounds;            // of the geometry; used by infinite lights
  float ray_epsilon = 1e-4f;        // ray offset (scene scale)
  int max_path_segments = 10;       // the scene's path length limit (camera ray = segment 1)
  bool has_cutouts = false;         // some non-emitting triangle's material has opacity (scene/surface_opacity.h)
};

}  // namespace pathspace
