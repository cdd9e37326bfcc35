// Scene: owns the flat arrays (vertices, triangles, spheres, materials, lights) and the camera.
// Builders (built-in scenes, file loaders) append through the add_* helpers, then call finalize(),
// which derives bounds and the light-selection distribution. Kernels see only view().
#pragma once

#include <array>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pathspace/math/frame.h"
#include "pathspace/scene/environment_image.h"
#include "pathspace/scene/image_texture.h"
#include "pathspace/scene/light_tree.h"
#include "pathspace/scene/scene_media.h"
#include "pathspace/scene/scene_sources.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

// How lights are picked (docs/conventions.md, "Light selection"). uniform and power serve every
// integrator alike; bvh starts light paths by power and picks the light for next event estimation
// at a shading point with the light tree (scene/light_tree.h).
enum class LightSelection { uniform, power, bvh };
inline constexpr LightSelection kDefaultLightSelection = LightSelection::bvh;
// The names the CLI and Python use for them ("uniform", "power", "bvh"), in that order.
const std::vector<std::string>& light_selection_names();
const std::string& light_selection_name(LightSelection s);
// false when `name` is none of light_selection_names().
bool parse_light_selection(const std::string& name, LightSelection* out);

class Scene {
 public:
  std::string name;
  std::vector<Vec3> positions;
  // Per-vertex texture coordinates and shading normals: each empty, or (after finalize) one per
  // position; finalize pads vertices added without them with uv (0, 0) and normal 0 (flat shading).
  std::vector<Point2> uvs;
  std::vector<Vec3> normals;
  // Motion blur (scene/motion.h): the vertices and normals at shutter close, empty in a still scene;
  // else positions_end has one per position (finalize pads it with the positions, so vertices added
  // without an end position stand still) and normals_end one per normal.
  std::vector<Vec3> positions_end;
  std::vector<Vec3> normals_end;
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<Material> materials;
  std::vector<ImageTexture> textures;  // referenced by Material::diffuse_texture etc.
  std::vector<Light> lights;
  EnvironmentImage environment_image;  // the environment light's image, or empty (constant)
  // Participating media and which shapes, lights and the camera they belong to (docs/media.md);
  // empty in a scene without media.
  SceneMedia media;
  PerspectiveCamera camera;
  // Motion blur of the camera (scene/motion.h, camera_at): camera is the camera at shutter open and
  // camera_end its pose at shutter close. Its lens and image do not change.
  bool camera_moves = false;
  CameraPose camera_end;
  // Animations (docs/animation.md): triangles and spheres from these indices on may move from frame
  // to frame; those before them are the same in every frame, so the acceleration structure of one
  // frame can reuse the previous frame's for them (accel/accel.h). kNothingMoves: all static.
  static constexpr uint32_t kNothingMoves = UINT32_MAX;
  uint32_t first_moving_triangle = kNothingMoves;
  uint32_t first_moving_sphere = kNothingMoves;
  float ray_epsilon = 1e-4f;
  int max_path_segments = 10;
  LightSelection light_selection = kDefaultLightSelection;
  // A colour matrix (row-major, linear sRGB to linear sRGB) for the images a render hands out
  // (RenderSession::snapshot): pbrt-v4's film white balance (io/spectrum/white_balance.h); identity
  // unless a scene file asks for one.
  std::array<float, 9> output_color_matrix{1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f};
  // When set, infinite lights use this bounding sphere instead of the geometry's.
  bool has_bounds_override = false;
  BoundingSphere bounds_override;
  SceneSources sources;  // where the elements came from (file:line:column), for messages

  uint32_t add_material(const Material& m);
  uint32_t add_texture(ImageTexture t);
  uint32_t add_vertex(const Vec3& p);
  // Adds triangle (p0, p1, p2); its geometric normal is normalize(cross(p1 - p0, p2 - p0)).
  // A non-black emission makes it an area light (radiance, front side unless two_sided).
  uint32_t add_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, uint32_t material,
                        const Rgb& emission = Rgb(), bool two_sided_emission = false);
  // Quad p0 p1 p2 p3 (counter-clockwise around its normal) as triangles (p0,p1,p2), (p2,p3,p0).
  void add_quad(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, uint32_t material,
                const Rgb& emission = Rgb(), bool two_sided_emission = false);
  uint32_t add_sphere(const Vec3& center, float radius, uint32_t material, const Rgb& emission = Rgb(),
                      bool inward_normals = false);
  void add_point_light(const Vec3& position, const Rgb& intensity);
  // pbrt-v4 spot light: intensity I on the axis, smoothstep falloff from cos_falloff to cos_total.
  void add_spot_light(const Vec3& position, const Vec3& axis, const Rgb& intensity, float cos_total, float cos_falloff);
  // A projector at `position` looking along frame.n, its image plane spanned by frame.s (u) and
  // frame.t (v): lights/light.h and scene/point_light_intensity.h say what the arguments mean.
  void add_projector_light(const Vec3& position, const Frame& frame, const Rgb& value, int32_t texture, float uv_scale_u,
                           float uv_scale_v, bool irradiance_plane);
  void add_directional_light(const Vec3& propagation_direction, const Rgb& irradiance);
  void add_environment_light(const Rgb& radiance);
  // An image environment: radiance = scale * image (lights/environment_map.h for the mappings).
  void add_environment_map(EnvironmentImage image, const Rgb& scale);

  // Validates indices and derives bounds and the light distribution. Throws pathspace::Error.
  void finalize();

  Bounds3 geometry_bounds() const;
  BoundingSphere bounds() const { return bounds_; }
  const DiscreteDistribution& light_distribution() const { return light_distribution_; }
  // Total emitted power of light i (luminance), the weight of power-proportional selection.
  float light_power(size_t i) const;
  // Light i's bounds for the light tree, or nullopt for an infinite light (valid after finalize()).
  std::optional<LightBounds> light_bounds(size_t i) const;
  // The light tree (empty unless light_selection is bvh).
  const LightTree& light_tree() const { return light_tree_; }
  // Whether some non-emitting triangle's material has cutout opacity (scene/surface_opacity.h):
  // only then do the ray casters test opacity. Scans the triangles (finalize keeps the answer).
  bool any_cutout_triangle() const;
  SceneView view() const;

 private:
  BoundingSphere bounds_;
  DiscreteDistribution light_distribution_;
  std::vector<float> emission_cells_;  // mapped area triangles' sampling cells (Light::emission_cells)
  LightTree light_tree_;
  int32_t environment_light_ = -1;
  bool has_cutouts_ = false;
  // What SceneView::textures points to; rebuilt by view() when stale (a copied Scene's views would
  // still point into the original's texels).
  mutable std::vector<TextureView> texture_views_;
  bool finalized_ = false;
};

// The sizes of a scene's arrays before a loader step; mark_since() then records every element the
// step added as coming from the step's statement (scene_sources.h).
struct SceneSizes {
  size_t vertices = 0, spheres = 0, materials = 0, lights = 0, textures = 0;

  static SceneSizes of(const Scene& s);
  void mark_since(Scene* s, const FileLoc& at) const;
};

}  // namespace pathspace
