// The pbrt-v4 scene builder (pbrt_scene_builder.h loads files with it): a graphics state (current
// transform at the start and end time, material, area light, attribute stack) against which the
// parser's statements are executed to fill a pathspace Scene. Its steps are in three files: the
// graphics state, camera, film and materials (pbrt_builder.cpp), lights (pbrt_builder_lights.cpp)
// and shapes (pbrt_builder_shapes.cpp); participating media are read by pbrt_media.h. Shapes are
// transformed to world space on the way in; triangle winding is flipped where pbrt's surface normal
// (from the per-vertex normals N, else ReverseOrientation xor a handedness-swapping transform)
// disagrees with pathspace's winding normal, so one-sided area lights emit to the same side as in
// pbrt. Internal to io/pbrt.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_materials.h"
#include "pathspace/io/pbrt/pbrt_media.h"
#include "pathspace/io/pbrt/pbrt_missing_files.h"
#include "pathspace/io/pbrt/pbrt_statement.h"
#include "pathspace/io/pbrt/pbrt_transform.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/scene.h"

namespace pathspace::pbrt {

struct GraphicsState {
  Mat4 ctm;      // at the start time of TransformTimes
  Mat4 ctm_end;  // at its end time (ActiveTransform EndTime / All); equal to ctm when nothing moves
  bool reverse_orientation = false;
  int material = -1;  // index into the scene's materials; -1: the default material
  bool area_light = false;
  Rgb area_radiance;
  bool area_two_sided = false;
  float area_power = 0.f;  // pbrt-v4's "power" (> 0): each shape emits this much (shape_radiance)
  int media = -1;          // the MediumInterface's id in PbrtMedia; -1: vacuum on both sides
};

// pbrt-v4's optional "power" of a light: > 0 rescales the emission so that the light emits it (0:
// not given; pbrt-v4 ignores values <= 0 as well). Must be finite.
float light_power_param(const Statement& st);

inline Vec3 vec_at(const std::vector<double>& v, size_t i) { return Vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2])); }

class SceneBuilder {
 public:
  SceneBuilder(const SceneLoadOptions& o, LoadWarnings* w, std::string main_folder)
      : options_(o), warnings_(w), main_folder_(std::move(main_folder)) {
    textures_.scene = &scene_;  // image textures are read into the scene
    textures_.main_folder = main_folder_;
  }
  void handle(const Statement& st);
  Scene finish(SceneFileSettings* settings);

 private:
  void warn(const FileLoc& loc, const std::string& m) { warnings_->add(loc, m); }
  // The file's camera for one camera-from-world transform.
  PerspectiveCamera file_camera_at(const Mat4& camera_from_world, int w, int h) const;
  void mark_all(const Statement& st) {
    for (const Param& p : st.params) p.used = true;
  }
  // pbrt-v4's ActiveTransform: transform directives change the start transform, the end one or both.
  void transform(const Mat4& t) {
    if (active_ != ActiveTransform::end) gs_.ctm = gs_.ctm * t;
    if (active_ != ActiveTransform::start) gs_.ctm_end = gs_.ctm_end * t;
  }
  void set_transform(const Mat4& m) {
    if (active_ != ActiveTransform::end) gs_.ctm = m;
    if (active_ != ActiveTransform::start) gs_.ctm_end = m;
  }
  // A transform that is `start` at time t0 and `end` at t1, at the camera's shutteropen and
  // shutterclose (pbrt-v4's AnimatedTransform, clamped to [t0, t1]); both `start` when still.
  void at_shutter(const Mat4& start, const Mat4& end, double t0, double t1, const FileLoc& loc, Mat4* open, Mat4* close) const;
  // The shape transform at shutter open and close (pbrt-v4's animated transform at the camera's
  // shutteropen and shutterclose, clamped to TransformTimes). True when the two differ: the shape
  // moves while the shutter is open (motion blur, scene/motion.h).
  bool shutter_transforms(const FileLoc& loc, Mat4* open, Mat4* close);
  // Relative file names resolve against the folder of the file that names them.
  std::string folder_of(const Statement& st) const;
  void dispatch(const Statement& st);
  // An image file named by `p` (relative to the statement's file) that does not exist: recorded for the
  // end-of-scene error, or with substitute_missing_textures a warning (the caller substitutes).
  bool image_missing(const Statement& st, const Param& p, const char* what, const std::string& stand_in);
  // An imagemap Texture whose file is missing gets a constant mid grey (a placeholder while the
  // scene is still parsed for more missing files, or the stand-in when substituting).
  bool missing_image_texture(const Statement& st);
  int material_index(const std::string& type, const Statement& st);
  // pbrt-v4's RGB film with the default "cie1931" sensor scales the image by the imaging ratio
  // exposure time x iso / 100 (PixelSensor) and, with "whitebalance" T, adapts D_T's white to D65.
  void film_sensor(const Statement& st);
  // The imaging ratio scales every emitter: the image is linear in emission, so this equals scaling
  // the image, for every integrator alike.
  void apply_imaging_ratio();
  void camera(const Statement& st);
  void pixel_filter(const Statement& st);
  void light(const Statement& st);
  // A point-like light under an animated transform: its position at shutter open and close, the
  // transforms interpolated as for shapes; it keeps its orientation at the start time (warning if it turns).
  void move_point_light(const FileLoc& loc, Light* l);
  void add_light(const Statement& st);
  // pbrt-v4's projection light (scene/point_light_intensity.h): the image `filename` through a
  // perspective frustum along the light's +z, `fov` (default 90 degrees) across the image's shorter
  // axis, intensity scale * image (nearest texel, as pbrt-v4 looks it up); the image's top row lies
  // towards the light's -y, as pbrt-v4's screen space puts it. A missing image: no light (the
  // end-of-scene error, or a warning with --substitute-missing-textures).
  void projection_light(const Statement& st, float scale, float power);
  // Constant environments add up exactly, so a second infinite light joins the first (a Scene holds one).
  void add_environment(const Rgb& radiance, const FileLoc& loc);
  // An image infinite light (io/pbrt/pbrt_environment.h); "illuminance" rescales as pbrt-v4 does.
  void image_environment(const Statement& st, const Param& file, float scale);
  // pbrt-v4 instancing, flattened: the object's shapes are added again with the instance's transform
  // applied on top of the one each shape was defined with (Embree instances would save memory;
  // the scenes we read have few instances). Unsupported parameters are reported at the first use.
  void instance(const Statement& st);
  // A Shape statement: its geometry (shape_geometry), bound to the graphics state's media.
  void shape(const Statement& st);
  void shape_geometry(const Statement& st);
  // The shape's material; with pbrt-v4's shape "alpha" (a float, or a float imagemap texture) a copy
  // of it with that cutout opacity (scene/surface_opacity.h), one copy per material and alpha.
  uint32_t shape_material(const Statement& st);
  Rgb emission(const Statement& st, uint32_t material);
  // The radiance of an area light whose pbrt shape has area `area`: with pbrt-v4's "power", the shape
  // emits that power, cosine-distributed from one side (two with twosided).
  Rgb shape_radiance(const Rgb& le, double area) const;
  // Positions, shading normals (N, with ReverseOrientation applied as for the face orientation) and
  // uvs go to the scene's vertex arrays; N also orients the faces. `triangles_per_shape`: how many
  // consecutive triangles make one pbrt-v4 shape (1: triangle meshes, 2: bilinear patches, 0: all of
  // them), the area an area light's "power" is spread over.
  void add_mesh(const Statement& st, const std::vector<Vec3>& pos, const std::vector<Vec3>& normals,
                const std::vector<std::array<float, 2>>& uvs, const std::vector<uint32_t>& idx, int triangles_per_shape = 1);
  void sphere(const Statement& st);

  const SceneLoadOptions& options_;
  LoadWarnings* warnings_;
  std::string main_folder_;
  Scene scene_;
  GraphicsState gs_;
  std::vector<std::pair<GraphicsState, bool>> stack_;  // bool: pushed by TransformBegin
  std::map<std::string, int> named_materials_;
  int interface_material_ = -1;  // pbrt-v4's "interface": one material of MaterialType::interface
  std::map<int, uint32_t> interior_media_;  // subsurface materials: material index -> its interior medium
  PbrtMedia media_;
  std::map<std::tuple<uint32_t, float, int32_t>, uint32_t> cutout_materials_;  // shape_material's copies
  std::map<std::string, std::pair<Mat4, Mat4>> coord_systems_;  // start and end transforms
  TextureTable textures_;
  MissingFiles missing_;
  bool missing_images_ = false;
  int default_material_ = -1;
  int object_depth_ = 0;
  std::string current_object_;
  std::map<std::string, std::vector<std::pair<Statement, GraphicsState>>> objects_;  // ObjectBegin .. ObjectEnd
  std::set<std::string> instanced_;
  bool in_world_ = false;
  enum class ActiveTransform { all, start, end } active_ = ActiveTransform::all;
  double transform_start_time_ = 0.0, transform_end_time_ = 1.0;  // TransformTimes
  double shutter_open_ = 0.0, shutter_close_ = 1.0;                // the camera's shutter
  bool has_camera_ = false;
  Mat4 camera_from_world_, camera_from_world_end_;             // at TransformTimes' start and end
  double camera_time_start_ = 0.0, camera_time_end_ = 1.0;
  FileLoc camera_loc_;
  float fov_ = 90.f;
  float lens_radius_ = 0.f, focal_distance_ = 1e6f;
  PixelFilter pixel_filter_;  // PixelFilter; pbrt-v4's default would be a gaussian, but a file without
                              // one keeps the unit box (the images of older pathspace versions)
  float exposure_time_ = 1.f, iso_ = 100.f;  // the film's imaging ratio (film_sensor)
  int film_width_ = 1280, film_height_ = 720, spp_ = 16, max_depth_ = 5;
  std::string image_name_;
};

}  // namespace pathspace::pbrt
