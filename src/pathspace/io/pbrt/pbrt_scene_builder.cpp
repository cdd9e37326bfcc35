// pbrt-v4 graphics state and scene construction (see pbrt_scene_builder.h). Shapes are transformed
// to world space on the way in; triangle winding is flipped where pbrt's surface normal (from the
// per-vertex normals N, else ReverseOrientation xor a handedness-swapping transform) disagrees with
// pathspace's winding normal, so one-sided area lights emit to the same side as in pbrt.
#include "pathspace/io/pbrt/pbrt_scene_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>
#include <set>

#include "pathspace/io/environment_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_environment.h"
#include "pathspace/io/pbrt/pbrt_materials.h"
#include "pathspace/io/spectrum/white_balance.h"
#include "pathspace/io/pbrt/pbrt_missing_files.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/pbrt/pbrt_tessellated_shapes.h"
#include "pathspace/io/pbrt/pbrt_parser.h"
#include "pathspace/io/pbrt/pbrt_paths.h"
#include "pathspace/io/pbrt/pbrt_transform.h"
#include "pathspace/io/ply_reader.h"

namespace pathspace::pbrt {

namespace {

constexpr int kInterfaceMaterial = -2;  // "interface": a medium boundary, not a visible surface

struct GraphicsState {
  Mat4 ctm;      // at the start time of TransformTimes
  Mat4 ctm_end;  // at its end time (ActiveTransform EndTime / All); equal to ctm when nothing moves
  bool reverse_orientation = false;
  int material = -1;  // index into the scene's materials; -1: the default material
  bool area_light = false;
  Rgb area_radiance;
  bool area_two_sided = false;
  float area_power = 0.f;  // pbrt-v4's "power" (> 0): each shape emits this much (pbrt_scene_builder.cpp, light_power)
};

// pbrt-v4's optional "power" of a light: > 0 rescales the emission so that the light emits it (0:
// not given; pbrt-v4 ignores values <= 0 as well). Must be finite.
float light_power_param(const Statement& st) {
  const double power = st.get_float("power", 0.0);
  if (!std::isfinite(power)) throw Error(st.find("power")->loc, "\"power\" must be finite");
  return power > 0.0 ? float(power) : 0.f;
}

Vec3 vec_at(const std::vector<double>& v, size_t i) { return Vec3(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2])); }

class Builder {
 public:
  Builder(const SceneLoadOptions& o, LoadWarnings* w, std::string main_folder)
      : options_(o), warnings_(w), main_folder_(std::move(main_folder)) {
    textures_.scene = &scene_;  // image textures are read into the scene
    textures_.main_folder = main_folder_;
  }

  void handle(const Statement& st) {
    // What this statement added is reported at its location by scene validation.
    const auto before = SceneSizes::of(scene_);
    dispatch(st);
    before.mark_since(&scene_, st.loc);
    for (const Param& p : st.params)
      if (!p.used) warn(p.loc, st.title() + ": parameter \"" + p.type + " " + p.name + "\" is not supported; ignored");
  }

  Scene finish(SceneFileSettings* settings) {
    if (!missing_.empty())
      missing_.fail(missing_images_ ? "missing images can be replaced by neutral stand-ins with --substitute-missing-textures" : "");
    if (!stack_.empty()) warn(FileLoc{}, "AttributeBegin without AttributeEnd at the end of the scene");
    const int w = options_.width > 0 ? options_.width : film_width_;
    const int h = options_.height > 0 ? options_.height : film_height_;
    if (!has_camera_) warn(FileLoc{}, "no Camera statement; using pbrt's default camera at the origin looking along +z");
    Mat4 open, close;
    at_shutter(camera_from_world_, camera_from_world_end_, camera_time_start_, camera_time_end_, camera_loc_, &open, &close);
    scene_.camera = file_camera_at(open, w, h);
    set_thin_lens(&scene_.camera, lens_radius_, focal_distance_);  // validated in camera()
    if (!(open == close)) {  // motion blur of the camera (scene/motion.h)
      scene_.camera_moves = true;
      scene_.camera_end = file_camera_at(close, w, h).pose();
      const double degrees = rotation_between_degrees(open, close);
      if (degrees > kMaxLinearRotationDegrees)
        warn(camera_loc_, fmt::format("the camera turns {:.0f} degrees while the shutter is open; its view direction is blended "
                                      "linearly between shutter open and close, not turned on pbrt-v4's arc",
                                      degrees));
    }
    apply_camera_options(options_, false, w, h, &scene_);
    if (has_camera_) scene_.sources.set_camera(camera_loc_);
    scene_.max_path_segments = max_depth_ + 1;
    const Bounds3 b = scene_.geometry_bounds();
    if (!b.empty()) scene_.ray_epsilon = std::max(1e-4f, 5e-5f * length(b.hi - b.lo));
    if (settings) {
      settings->spp = spp_;
      settings->image_name = image_name_;
    }
    apply_imaging_ratio();
    scene_.finalize();
    return std::move(scene_);
  }

 private:
  void warn(const FileLoc& loc, const std::string& m) { warnings_->add(loc, m); }
  // The file's camera for one camera-from-world transform.
  PerspectiveCamera file_camera_at(const Mat4& camera_from_world, int w, int h) const {
    Mat4 world_from_camera;
    if (!camera_from_world.inverse(&world_from_camera)) throw Error(camera_loc_, "camera transform is singular");
    return make_file_camera(world_from_camera.point(Vec3()), world_from_camera.vector(Vec3(0, 0, 1)),
                            world_from_camera.vector(Vec3(1, 0, 0)), world_from_camera.vector(Vec3(0, 1, 0)), fov_, w, h);
  }
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
  void at_shutter(const Mat4& start, const Mat4& end, double t0, double t1, const FileLoc& loc, Mat4* open, Mat4* close) const {
    if (start == end) {
      *open = *close = start;
      return;
    }
    if (!animated_transform_at(start, end, t0, t1, shutter_open_, open) || !animated_transform_at(start, end, t0, t1, shutter_close_, close))
      throw Error(loc, "the animated transform cannot be interpolated (a singular start or end transform)");
  }

  // The shape transform at shutter open and close (pbrt-v4's animated transform at the camera's
  // shutteropen and shutterclose, clamped to TransformTimes). True when the two differ: the shape
  // moves while the shutter is open (motion blur, scene/motion.h).
  bool shutter_transforms(const FileLoc& loc, Mat4* open, Mat4* close) {
    at_shutter(gs_.ctm, gs_.ctm_end, transform_start_time_, transform_end_time_, loc, open, close);
    if (*open == *close) return false;  // the motion lies outside the shutter interval
    const double degrees = rotation_between_degrees(*open, *close);
    if (degrees > kMaxLinearRotationDegrees)
      warn(loc, fmt::format("the shape turns {:.0f} degrees while the shutter is open; its vertices move on straight lines "
                            "between shutter open and close (Embree's linear motion), not on pbrt-v4's arcs",
                            degrees));
    return true;
  }
  // Relative file names resolve against the folder of the file that names them.
  std::string folder_of(const Statement& st) const {
    const std::string f = std::filesystem::path(st.loc.file).parent_path().string();
    return f.empty() ? main_folder_ : f;
  }

  void dispatch(const Statement& st) {
    const std::string& d = st.directive;
    const auto& n = st.numbers;
    if (d == "WorldBegin") {
      in_world_ = true;
      gs_.ctm = gs_.ctm_end = Mat4();
      coord_systems_["world"] = {Mat4(), Mat4()};
    } else if (d == "WorldEnd") {
    } else if (d == "AttributeBegin" || d == "TransformBegin") {
      stack_.push_back({gs_, d == "TransformBegin"});
    } else if (d == "AttributeEnd" || d == "TransformEnd") {
      if (stack_.empty() || stack_.back().second != (d == "TransformEnd"))
        throw Error(st.loc, d + " without a matching " + (d == "AttributeEnd" ? "AttributeBegin" : "TransformBegin"));
      if (stack_.back().second) gs_.ctm = stack_.back().first.ctm, gs_.ctm_end = stack_.back().first.ctm_end;
      else gs_ = stack_.back().first;
      stack_.pop_back();
    } else if (d == "Identity") {
      set_transform(Mat4());
    } else if (d == "Translate") {
      transform(Mat4::translate(n[0], n[1], n[2]));
    } else if (d == "Scale") {
      transform(Mat4::scale(n[0], n[1], n[2]));
    } else if (d == "Rotate") {
      transform(Mat4::rotate(n[0], n[1], n[2], n[3]));
    } else if (d == "LookAt") {
      Mat4 m;
      if (!look_at(Vec3(float(n[0]), float(n[1]), float(n[2])), Vec3(float(n[3]), float(n[4]), float(n[5])),
                   Vec3(float(n[6]), float(n[7]), float(n[8])), &m))
        throw Error(st.loc, "LookAt: the up vector is parallel to the view direction (or eye == target)");
      transform(m);
    } else if (d == "Transform") {
      set_transform(Mat4::from_columns(n.data()));
    } else if (d == "ConcatTransform") {
      transform(Mat4::from_columns(n.data()));
    } else if (d == "CoordinateSystem") {
      coord_systems_[st.strings[0]] = {gs_.ctm, gs_.ctm_end};
    } else if (d == "CoordSysTransform") {
      const auto it = coord_systems_.find(st.strings[0]);
      if (it == coord_systems_.end()) warn(st.loc, "unknown coordinate system '" + st.strings[0] + "'; ignored");
      else gs_.ctm = it->second.first, gs_.ctm_end = it->second.second;
    } else if (d == "ReverseOrientation") {
      gs_.reverse_orientation = !gs_.reverse_orientation;
    } else if (d == "ActiveTransform") {
      active_ = st.strings[0] == "StartTime" ? ActiveTransform::start
                : st.strings[0] == "EndTime"  ? ActiveTransform::end
                                              : ActiveTransform::all;
    } else if (d == "TransformTimes") {
      if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && n[0] <= n[1]))
        throw Error(st.loc, "TransformTimes needs two finite times, the start not after the end");
      transform_start_time_ = n[0];
      transform_end_time_ = n[1];
    } else if (d == "ColorSpace") {
      if (st.strings[0] != "srgb") warn(st.loc, "ColorSpace \"" + st.strings[0] + "\" ignored: pathspace renders in linear sRGB");
    } else if (d == "Option" || d == "Attribute" || d == "MakeNamedMedium" || d == "MediumInterface") {
      warn(st.loc, d + " is not supported; ignored");
      mark_all(st);
    } else if (d == "Camera") {
      camera(st);
    } else if (d == "Film") {
      if (st.strings[0] != "rgb") warn(st.loc, "Film \"" + st.strings[0] + "\" treated as \"rgb\"");
      film_width_ = st.get_int("xresolution", 1280);
      film_height_ = st.get_int("yresolution", 720);
      if (film_width_ < 1 || film_height_ < 1 || film_width_ > 16384 || film_height_ > 16384)
        throw Error(st.loc, "Film resolution must be between 1 and 16384");
      image_name_ = st.get_string("filename", "");
      st.ignore({"savefp16"});
      film_sensor(st);
    } else if (d == "Sampler") {
      spp_ = st.get_int("pixelsamples", 16);
      if (spp_ < 1) throw Error(st.loc, "pixelsamples must be at least 1");
      mark_all(st);  // sampler kind, seed, randomisation: they change the noise, not the expectation
    } else if (d == "Integrator") {
      max_depth_ = st.get_int("maxdepth", 5);
      if (max_depth_ < 0 || max_depth_ > 1023) throw Error(st.loc, "maxdepth must be between 0 and 1023");
      if (st.strings[0] != "path" && st.strings[0] != "volpath")
        warn(st.loc, "Integrator \"" + st.strings[0] + "\": pathspace renders with the --integrator option (default pt); only maxdepth is used");
      st.ignore({"lightsampler"});
      if (st.strings[0] != "path" && st.strings[0] != "volpath") mark_all(st);
    } else if (d == "PixelFilter") {
      if (st.strings[0] != "box") warn(st.loc, "PixelFilter \"" + st.strings[0] + "\" not supported: pathspace uses a box filter of one pixel");
      mark_all(st);
    } else if (d == "Accelerator") {
      mark_all(st);
    } else if (d == "Texture") {
      if (!missing_image_texture(st)) add_texture(st, folder_of(st), &textures_, warnings_);
    } else if (d == "MakeNamedMaterial") {
      const std::string type = st.get_string("type", "");
      if (type.empty()) throw Error(st.loc, "MakeNamedMaterial \"" + st.strings[0] + "\" has no \"string type\"");
      if (named_materials_.count(st.strings[0])) warn(st.loc, "material \"" + st.strings[0] + "\" redefined");
      named_materials_[st.strings[0]] = material_index(type, st);
    } else if (d == "NamedMaterial") {
      const auto it = named_materials_.find(st.strings[0]);
      if (it == named_materials_.end()) throw Error(st.loc, "named material \"" + st.strings[0] + "\" is not defined");
      gs_.material = it->second;
    } else if (d == "Material") {
      gs_.material = material_index(st.strings[0], st);
    } else if (d == "LightSource") {
      light(st);
    } else if (d == "AreaLightSource") {
      if (st.strings[0] != "diffuse") throw Error(st.loc, "AreaLightSource \"" + st.strings[0] + "\" is not supported (only \"diffuse\")");
      gs_.area_light = true;
      gs_.area_radiance =
          spectrum_param(st, "L", Rgb(1.f), textures_, warnings_, SpectrumUse::illuminant) * float(st.get_float("scale", 1.0));
      gs_.area_two_sided = st.get_bool("twosided", false);
      gs_.area_power = light_power_param(st);
    } else if (d == "Shape") {
      shape(st);
    } else if (d == "ObjectBegin") {
      if (object_depth_ > 0) throw Error(st.loc, "ObjectBegin inside object \"" + current_object_ + "\"");
      if (objects_.count(st.strings[0])) warn(st.loc, "object \"" + st.strings[0] + "\" redefined");
      current_object_ = st.strings[0];
      objects_[current_object_].clear();
      stack_.push_back({gs_, false});
      ++object_depth_;
    } else if (d == "ObjectEnd") {
      if (object_depth_ == 0 || stack_.empty()) throw Error(st.loc, "ObjectEnd without ObjectBegin");
      --object_depth_;
      gs_ = stack_.back().first;
      stack_.pop_back();
    } else if (d == "ObjectInstance") {
      instance(st);
    }
  }

  // An image file named by `p` (relative to the statement's file) that does not exist: recorded for the
  // end-of-scene error, or with substitute_missing_textures a warning (the caller substitutes).
  bool image_missing(const Statement& st, const Param& p, const char* what, const std::string& stand_in) {
    const std::string name = p.strings.size() == 1 ? p.strings[0] : "";
    std::filesystem::path path(name);
    if (path.is_relative()) path = std::filesystem::path(folder_of(st)) / path;
    std::error_code ec;
    if (name.empty() || std::filesystem::is_regular_file(path, ec)) return false;
    if (options_.substitute_missing_textures) {
      warn(p.loc, std::string(what) + " '" + name + "' not found (looked for " + path.string() + "); substituted by " + stand_in);
    } else {
      missing_.add(p.loc, what, name);
      missing_images_ = true;
    }
    return true;
  }

  // An imagemap Texture whose file is missing gets a constant mid grey (a placeholder while the
  // scene is still parsed for more missing files, or the stand-in when substituting).
  bool missing_image_texture(const Statement& st) {
    if (st.strings[2] != "imagemap") return false;
    const Param* file = st.find("filename");
    if (!file || !image_missing(st, *file, "texture file", "a constant mid grey (0.5)")) return false;
    textures_.values[st.strings[0]] = Rgb(kMissingTextureValue);
    mark_all(st);
    return true;
  }

  int material_index(const std::string& type, const Statement& st) {
    if (type == "interface") return kInterfaceMaterial;
    if (type == "" || type == "none") {
      warn(st.loc, "material \"" + type + "\": shapes are rendered with grey diffuse 0.5");
      return -1;
    }
    return int(scene_.add_material(make_material(type, st, textures_, warnings_)));
  }

  // pbrt-v4's RGB film with the default "cie1931" sensor scales the image by the imaging ratio
  // exposure time x iso / 100 (PixelSensor) and, with "whitebalance" T, adapts D_T's white to D65.
  void film_sensor(const Statement& st) {
    iso_ = float(st.get_float("iso", 100.0));
    if (!(iso_ > 0.f && std::isfinite(iso_))) throw Error(st.loc, "Film iso must be positive and finite");
    const std::string sensor = st.get_string("sensor", "cie1931");
    if (sensor != "cie1931") warn(st.find("sensor")->loc, "Film sensor \"" + sensor + "\" treated as \"cie1931\" (no sensor response curves)");
    const double kelvin = st.get_float("whitebalance", 0.0);
    if (kelvin != 0.0) {
      try {
        scene_.output_color_matrix = white_balance_matrix(kelvin);
      } catch (const Error& e) {
        throw Error(st.find("whitebalance")->loc, e.what());
      }
    }
  }

  // The imaging ratio scales every emitter: the image is linear in emission, so this equals scaling
  // the image, for every integrator alike.
  void apply_imaging_ratio() {
    const float ratio = exposure_time_ * iso_ / 100.f;
    if (ratio == 1.f) return;
    for (Light& l : scene_.lights) l.value = l.value * ratio;
  }

  void camera(const Statement& st) {
    if (st.strings[0] != "perspective") throw Error(st.loc, "Camera \"" + st.strings[0] + "\" is not supported (only \"perspective\")");
    fov_ = float(st.get_float("fov", 90.0));
    if (!(fov_ > 0.f && fov_ < 180.f)) throw Error(st.loc, "fov must be between 0 and 180 degrees");
    // pbrt-v4's thin lens (defaults: lensradius 0 = pinhole, focaldistance 1e6), in scene units.
    lens_radius_ = float(st.get_float("lensradius", 0.0));
    focal_distance_ = float(st.get_float("focaldistance", 1e6));
    if (!(lens_radius_ >= 0.f && std::isfinite(lens_radius_))) throw Error(st.loc, "lensradius must be finite and >= 0");
    if (!(focal_distance_ > 0.f && std::isfinite(focal_distance_))) throw Error(st.loc, "focaldistance must be finite and positive");
    // pbrt-v4's exposure time (the film's imaging ratio) and the interval moving shapes are blurred over.
    exposure_time_ = float(st.get_float("shutterclose", 1.0) - st.get_float("shutteropen", 0.0));
    if (!(exposure_time_ > 0.f && std::isfinite(exposure_time_)))
      throw Error(st.loc, "shutterclose - shutteropen must be positive and finite (the shutter never opens)");
    shutter_open_ = st.get_float("shutteropen", 0.0);
    shutter_close_ = st.get_float("shutterclose", 1.0);
    // pbrt-v4's CameraTransform: the CTM at start and end time, interpolated at the shutter (finish()).
    camera_from_world_ = gs_.ctm;
    camera_from_world_end_ = gs_.ctm_end;
    camera_time_start_ = transform_start_time_;
    camera_time_end_ = transform_end_time_;
    has_camera_ = true;
    camera_loc_ = st.loc;
    Mat4 inv;
    if (camera_from_world_.inverse(&inv)) coord_systems_["camera"] = {inv, inv};
  }

  void light(const Statement& st) {
    const std::string& type = st.strings[0];
    const size_t before = scene_.lights.size();
    add_light(st);
    if (gs_.ctm == gs_.ctm_end) return;
    const bool point_like = type == "point" || type == "spot" || type == "projection";
    if (!point_like || scene_.lights.size() != before + 1) {
      warn(st.loc, "LightSource \"" + type + "\" under an animated transform: only area lights (shapes) and point, spot "
                   "and projection lights move; this one keeps its transform at the start time");
      return;
    }
    move_point_light(st.loc, &scene_.lights.back());
  }

  // A point-like light under an animated transform: its position at shutter open and close, the
  // transforms interpolated as for shapes; it keeps its orientation at the start time (warning if it turns).
  void move_point_light(const FileLoc& loc, Light* l) {
    Mat4 open, close, inv_start;
    at_shutter(gs_.ctm, gs_.ctm_end, transform_start_time_, transform_end_time_, loc, &open, &close);
    if (!gs_.ctm.inverse(&inv_start)) throw Error(loc, "the light's transform is singular");
    const Vec3 local = inv_start.point(l->position);  // placed with the start transform
    l->position = open.point(local);
    l->position_end = close.point(local);
    l->moves = !(l->position == l->position_end);
    if (rotation_between_degrees(open, close) > kLightTurnWarningDegrees)
      warn(loc, "the light turns while the shutter is open; it moves but keeps its orientation at the start time");
  }

  void add_light(const Statement& st) {
    const std::string& type = st.strings[0];
    const float scale = float(st.get_float("scale", 1.0));
    const float power = light_power_param(st);
    if (type == "point") {
      // pbrt-v4: "power" over the sphere of directions.
      const Rgb i = spectrum_param(st, "I", Rgb(1.f), textures_, warnings_, SpectrumUse::illuminant) * scale *
                    (power > 0.f ? power / float(4.0 * M_PI) : 1.f);
      const std::vector<double> from = st.get_numbers("from");
      scene_.add_point_light(gs_.ctm.point(from.size() == 3 ? vec_at(from, 0) : Vec3()), i);
    } else if (type == "spot") {
      // pbrt-v4: the cone around from -> to; full intensity inside coneangle - conedelta, smoothstep
      // falloff (in the cosine) out to coneangle.
      const Rgb i = spectrum_param(st, "I", Rgb(1.f), textures_, warnings_, SpectrumUse::illuminant) * scale;
      const std::vector<double> from = st.get_numbers("from"), to = st.get_numbers("to");
      const Vec3 f = from.size() == 3 ? vec_at(from, 0) : Vec3(), t = to.size() == 3 ? vec_at(to, 0) : Vec3(0, 0, 1);
      const Vec3 axis = gs_.ctm.vector(t - f);
      if (!(length(axis) > 0.f)) throw Error(st.loc, "spot light: 'from' equals 'to'");
      const double cone = st.get_float("coneangle", 30.0), delta = st.get_float("conedelta", 5.0);
      if (!(cone > 0.0 && cone <= 180.0) || !(delta >= 0.0)) throw Error(st.loc, "spot light: need 0 < coneangle <= 180 and conedelta >= 0");
      const float cos_total = float(std::cos(cone * M_PI / 180.0));
      const float cos_falloff = float(std::cos(std::max(0.0, cone - delta) * M_PI / 180.0));
      // pbrt-v4: "power" over the cone, the smoothstep's ramp counted at half.
      const float cone_solid_angle = float(2.0 * M_PI) * ((1.f - cos_falloff) + 0.5f * (cos_falloff - cos_total));
      scene_.add_spot_light(gs_.ctm.point(f), axis, i * (power > 0.f ? power / cone_solid_angle : 1.f), cos_total, cos_falloff);
    } else if (type == "projection") {
      projection_light(st, scale, power);
    } else if (type == "distant") {
      // pbrt-v4: "illuminance" (> 0) is the irradiance on a surface facing the light.
      const double illuminance = st.get_float("illuminance", -1.0);
      const Rgb l = spectrum_param(st, "L", Rgb(1.f), textures_, warnings_, SpectrumUse::illuminant) * scale *
                    (illuminance > 0.0 ? float(illuminance) : 1.f);
      const std::vector<double> from = st.get_numbers("from"), to = st.get_numbers("to");
      const Vec3 f = from.size() == 3 ? vec_at(from, 0) : Vec3(), t = to.size() == 3 ? vec_at(to, 0) : Vec3(0, 0, 1);
      const Vec3 dir = gs_.ctm.vector(t - f);
      if (!(length(dir) > 0.f)) throw Error(st.loc, "distant light: 'from' equals 'to'");
      scene_.add_directional_light(dir, l);
    } else if (type == "infinite") {
      if (const Param* f = st.find("filename")) {
        if (image_missing(st, *f, "environment map", "a constant white environment (radiance 1 x scale)")) {
          mark_all(st);
          if (options_.substitute_missing_textures) add_environment(Rgb(kMissingEnvironmentRadiance) * scale, st.loc);
          return;
        }
        image_environment(st, *f, scale);
        return;
      }
      // pbrt-v4: "illuminance" (> 0) is the irradiance on an upward-facing patch, pi L.
      const double illuminance = st.get_float("illuminance", -1.0);
      add_environment(spectrum_param(st, "L", Rgb(1.f), textures_, warnings_, SpectrumUse::illuminant) * scale *
                          (illuminance > 0.0 ? float(illuminance / M_PI) : 1.f),
                      st.loc);
    } else {
      warn(st.loc, "LightSource \"" + type + "\" is not supported; skipped");
      mark_all(st);
    }
  }

  // pbrt-v4's projection light (scene/point_light_intensity.h): the image `filename` through a
  // perspective frustum along the light's +z, `fov` (default 90 degrees) across the image's shorter
  // axis, intensity scale * image (nearest texel, as pbrt-v4 looks it up); the image's top row lies
  // towards the light's -y, as pbrt-v4's screen space puts it. A missing image: no light (the
  // end-of-scene error, or a warning with --substitute-missing-textures).
  void projection_light(const Statement& st, float scale, float power) {
    const Param* file = st.find("filename");
    if (!file || file->strings.size() != 1) throw Error(st.loc, "projection light needs \"string filename\"");
    file->used = true;
    if (image_missing(st, *file, "projection image", "no light")) {
      mark_all(st);
      return;
    }
    std::filesystem::path path(file->strings[0]);
    if (path.is_relative()) path = std::filesystem::path(folder_of(st)) / path;
    const double fov = st.get_float("fov", 90.0);
    if (!(fov > 0.0 && fov < 180.0)) throw Error(st.find("fov")->loc, "projection light: fov must lie between 0 and 180 degrees");
    ImageTexture image;
    try {
      Image read = read_image(path.string());
      image.width = read.width;
      image.height = read.height;
      image.texels = std::move(read.pixels);
    } catch (const Error& e) {
      throw Error(file->loc, std::string("projection light: ") + e.what());
    }
    if (!all_finite(image.mean())) throw Error(file->loc, "projection light: the image holds NaN or infinite values");
    image.name = path.string();
    image.nearest = true;
    const double aspect = double(image.width) / image.height;
    const uint32_t texture = scene_.add_texture(std::move(image));
    const double t = std::tan(fov * M_PI / 360.0);
    const double tu = aspect > 1.0 ? t * aspect : t, tv = aspect > 1.0 ? t : t / aspect;
    Frame frame;
    if (!axes_frame(gs_.ctm, &frame)) throw Error(st.loc, "projection light: the transform is singular");
    scene_.add_projector_light(gs_.ctm.point(Vec3()), frame, Rgb(scale), int32_t(texture), float(0.5 / tu),
                               float(-0.5 / tv), false);
    if (power > 0.f) {  // pbrt-v4: scale * power / (the image's luminance power at scale 1)
      Light& l = scene_.lights.back();
      l.value = Rgb(1.f);
      const float unit_power = scene_.light_power(scene_.lights.size() - 1);
      if (!(unit_power > 0.f)) throw Error(st.loc, "projection light: \"power\" given for a black image");
      l.value = Rgb(scale * power / unit_power);
    }
  }

  // Constant environments add up exactly, so a second infinite light joins the first (a Scene holds one).
  void add_environment(const Rgb& radiance, const FileLoc& loc) {
    if (!scene_.environment_image.empty()) {
      warn(loc, "a second infinite light next to an image environment is not supported; skipped");
      return;
    }
    for (Light& l : scene_.lights)
      if (l.type == LightType::environment) {
        l.value += radiance;
        return;
      }
    scene_.add_environment_light(radiance);
  }

  // An image infinite light (io/pbrt/pbrt_environment.h); "illuminance" rescales as pbrt-v4 does.
  void image_environment(const Statement& st, const Param& file, float scale) {
    file.used = true;
    std::filesystem::path path(file.strings[0]);
    if (path.is_relative()) path = std::filesystem::path(folder_of(st)) / path;
    const float illuminance = float(st.get_float("illuminance", -1.0));
    bool has_environment = false;
    for (const Light& l : scene_.lights) has_environment = has_environment || l.type == LightType::environment;
    if (has_environment) {
      warn(st.loc, "a second infinite light next to another is not supported with an image; skipped");
      return;
    }
    EnvironmentImage image;
    try {
      image = read_pbrt_environment(path.string(), gs_.ctm, st.loc, warnings_);
    } catch (const Error& e) {
      throw Error(file.loc, std::string("environment map: ") + e.what());
    }
    if (illuminance > 0.f) {
      const double k = pbrt_map_illuminance(image);
      if (!(k > 0.0)) throw Error(st.loc, "\"illuminance\" given for an environment map that is black above the horizon");
      scale *= float(illuminance / k);
    }
    scene_.add_environment_map(std::move(image), Rgb(scale));
  }

  // pbrt-v4 instancing, flattened: the object's shapes are added again with the instance's transform
  // applied on top of the one each shape was defined with (Embree instances would save memory;
  // the scenes we read have few instances). Unsupported parameters are reported at the first use.
  void instance(const Statement& st) {
    if (object_depth_ > 0) throw Error(st.loc, "ObjectInstance inside ObjectBegin");
    const auto it = objects_.find(st.strings[0]);
    if (it == objects_.end()) throw Error(st.loc, "object \"" + st.strings[0] + "\" is not defined");
    const bool first_use = instanced_.insert(st.strings[0]).second;
    const GraphicsState saved = gs_;
    for (const auto& [shape_st, shape_gs] : it->second) {
      Statement copy = shape_st;
      for (const Param& p : copy.params) p.used = false;
      gs_ = shape_gs;
      gs_.ctm = saved.ctm * shape_gs.ctm;
      gs_.ctm_end = saved.ctm_end * shape_gs.ctm_end;
      shape(copy);
      if (first_use)
        for (const Param& p : copy.params)
          if (!p.used) warn(p.loc, copy.title() + ": parameter \"" + p.type + " " + p.name + "\" is not supported; ignored");
    }
    gs_ = saved;
  }

  void shape(const Statement& st) {
    const std::string& type = st.strings[0];
    if (object_depth_ > 0) {  // kept for ObjectInstance, with the graphics state it was defined in
      objects_[current_object_].push_back({st, gs_});
      mark_all(st);
      return;
    }
    if (gs_.material == kInterfaceMaterial) {
      warn(st.loc, "shape with material \"interface\" skipped (participating media are not supported)");
      mark_all(st);
      return;
    }
    st.ignore({"faceIndices"});
    if (type == "trianglemesh") {
      const std::vector<double> p = st.get_numbers("P");
      std::vector<double> idx = st.get_numbers("indices");
      const std::vector<double> nrm = st.get_numbers("N");
      const std::vector<double> uv = st.get_numbers(st.find("uv") ? "uv" : "st");
      if (p.empty() || p.size() % 3) throw Error(st.loc, "trianglemesh needs \"point3 P\" with a multiple of 3 values");
      if (idx.empty() && p.size() == 9) idx = {0, 1, 2};
      if (idx.empty() || idx.size() % 3) throw Error(st.loc, "trianglemesh needs \"integer indices\" with a multiple of 3 values");
      if (!nrm.empty() && nrm.size() != p.size()) throw Error(st.loc, "trianglemesh: N must have one normal per vertex");
      if (!uv.empty() && uv.size() != p.size() / 3 * 2) throw Error(st.loc, "trianglemesh: uv must have one point2 per vertex");
      std::vector<Vec3> pos(p.size() / 3), normals(nrm.size() / 3);
      std::vector<std::array<float, 2>> uvs(uv.size() / 2);
      for (size_t i = 0; i < uvs.size(); ++i) uvs[i] = {float(uv[2 * i]), float(uv[2 * i + 1])};
      for (size_t i = 0; i < pos.size(); ++i) pos[i] = vec_at(p, i);
      for (size_t i = 0; i < normals.size(); ++i) normals[i] = vec_at(nrm, i);
      std::vector<uint32_t> tri(idx.size());
      for (size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] < 0 || idx[i] >= double(pos.size()))
          throw Error(st.find("indices")->loc, "index " + std::to_string(int64_t(idx[i])) + " out of range (" + std::to_string(pos.size()) + " vertices)");
        tri[i] = uint32_t(idx[i]);
      }
      add_mesh(st, pos, normals, uvs, tri);
    } else if (type == "plymesh") {
      const std::string file = st.get_string("filename", "");
      const std::filesystem::path path = resolve_scene_file(file, folder_of(st), main_folder_);
      std::error_code ec;
      if (!file.empty() && !std::filesystem::exists(path, ec)) {  // listed with the other missing files at the end
        missing_.add(st.find("filename")->loc, "PLY mesh", file);
        return;
      }
      PlyMesh mesh;
      try {
        mesh = read_ply(path.string());
      } catch (const Error& e) {
        throw Error(st.loc, "plymesh \"" + file + "\": " + e.what());
      }
      add_mesh(st, mesh.positions, mesh.normals, mesh.uvs, mesh.indices);
    } else if (type == "sphere") {
      sphere(st);
    } else if (type == "disk" || type == "bilinearmesh" || type == "loopsubdiv") {
      const ObjectMesh m = type == "disk"           ? disk_mesh(st, warnings_)
                           : type == "bilinearmesh" ? bilinear_mesh(st, warnings_)
                                                    : loop_subdivision_mesh(st);
      // pbrt-v4 makes a disk one shape, a bilinear mesh one per patch, a subdivision surface one per
      // triangle: what "power" of an area light is emitted by (add_mesh).
      add_mesh(st, m.positions, m.normals, m.uvs, m.indices, type == "disk" ? 0 : type == "bilinearmesh" ? 2 : 1);
    } else {
      warn(st.loc, "Shape \"" + type + "\" is not supported; skipped");
      mark_all(st);
    }
  }

  // The shape's material; with pbrt-v4's shape "alpha" (a float, or a float imagemap texture) a copy
  // of it with that cutout opacity (scene/surface_opacity.h), one copy per material and alpha.
  uint32_t shape_material(const Statement& st) {
    if (gs_.material < 0 && default_material_ < 0)
      default_material_ = int(scene_.add_material(make_material("diffuse", Statement{}, textures_, warnings_)));
    const uint32_t material = uint32_t(gs_.material >= 0 ? gs_.material : default_material_);
    if (!st.find("alpha")) return material;
    int32_t texture = -1;
    const float alpha = float_texture_param(st, "alpha", 1.f, &textures_, warnings_, &texture);
    if (!(alpha >= 0.f && alpha <= 1.f)) throw Error(st.find("alpha")->loc, "\"alpha\" must lie in [0, 1]");
    if (alpha == 1.f && texture < 0) return material;
    const auto key = std::make_tuple(material, alpha, texture);
    const auto it = cutout_materials_.find(key);
    if (it != cutout_materials_.end()) return it->second;
    Material m = scene_.materials[material];
    m.opacity = alpha;
    m.opacity_texture = texture;
    const uint32_t copy = scene_.add_material(m);
    cutout_materials_.emplace(key, copy);
    return copy;
  }

  Rgb emission(const Statement& st, uint32_t material) {
    if (!gs_.area_light) return Rgb();
    const Material& m = scene_.materials[material];
    if (!is_black(m.diffuse) || !is_black(m.glossy) || !is_black(m.specular) || m.type != MaterialType::standard)
      warn(st.loc, "an emissive shape's material is ignored (pathspace emitters do not reflect light)");
    return gs_.area_radiance;
  }

  // The radiance of an area light whose pbrt shape has area `area`: with pbrt-v4's "power", the shape
  // emits that power, cosine-distributed from one side (two with twosided).
  Rgb shape_radiance(const Rgb& le, double area) const {
    if (!(gs_.area_power > 0.f) || is_black(le)) return le;
    return area > 0.0 ? le * float(gs_.area_power / ((gs_.area_two_sided ? 2.0 : 1.0) * M_PI * area)) : Rgb();
  }

  // Positions, shading normals (N, with ReverseOrientation applied as for the face orientation) and
  // uvs go to the scene's vertex arrays; N also orients the faces. `triangles_per_shape`: how many
  // consecutive triangles make one pbrt-v4 shape (1: triangle meshes, 2: bilinear patches, 0: all of
  // them), the area an area light's "power" is spread over.
  void add_mesh(const Statement& st, const std::vector<Vec3>& pos, const std::vector<Vec3>& normals,
                const std::vector<std::array<float, 2>>& uvs, const std::vector<uint32_t>& idx, int triangles_per_shape = 1) {
    const uint32_t material = shape_material(st);
    const Rgb le_shape = emission(st, material);
    Mat4 open, close;
    const bool moving = shutter_transforms(st.loc, &open, &close);
    Mat4 inv, inv_close;
    if (!open.inverse(&inv) || !close.inverse(&inv_close)) throw Error(st.loc, "shape transform is singular");
    const bool flip_default = gs_.reverse_orientation != (open.det3() < 0.0);
    const uint32_t base = uint32_t(scene_.positions.size());
    for (const Vec3& p : pos) scene_.positions.push_back(open.point(p));
    if (moving) {  // the vertices at shutter close; the static ones before them stand still
      for (size_t i = scene_.positions_end.size(); i < base; ++i) scene_.positions_end.push_back(scene_.positions[i]);
      for (const Vec3& p : pos) scene_.positions_end.push_back(close.point(p));
    }
    if (uvs.size() == pos.size()) {
      scene_.uvs.resize(base);
      for (const auto& t : uvs) scene_.uvs.push_back(Point2{t[0], t[1]});
    }
    // Each triangle's pbrt shape's area in world space (for "power").
    std::vector<double> shape_area(idx.size() / 3, 0.0);
    if (gs_.area_power > 0.f) {
      const size_t n = shape_area.size(), group = triangles_per_shape > 0 ? size_t(triangles_per_shape) : std::max<size_t>(n, 1);
      for (size_t first = 0; first < n; first += group) {
        double sum = 0.0;
        for (size_t t = first; t < std::min(n, first + group); ++t) {
          const Vec3 a = scene_.positions[base + idx[3 * t]], b = scene_.positions[base + idx[3 * t + 1]], c = scene_.positions[base + idx[3 * t + 2]];
          sum += 0.5 * double(length(cross(b - a, c - a)));
        }
        for (size_t t = first; t < std::min(n, first + group); ++t) shape_area[t] = sum;
      }
    }
    bool smooth = false;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
      const Rgb le = shape_radiance(le_shape, shape_area[t / 3]);
      uint32_t v[3] = {base + idx[t], base + idx[t + 1], base + idx[t + 2]};
      const Vec3 ng = cross(scene_.positions[v[1]] - scene_.positions[v[0]], scene_.positions[v[2]] - scene_.positions[v[0]]);
      const float area2 = length(ng);
      bool flip = flip_default;
      if (!normals.empty()) {
        Vec3 ns;
        for (int k = 0; k < 3; ++k) {
          const Vec3 nk = normalize(Mat4::normal(inv, normals[idx[t + size_t(k)]]));
          ns += gs_.reverse_orientation ? -nk : nk;
          if (area2 > 0.f && abs_dot(nk, ng / area2) < 0.999f) smooth = true;
        }
        flip = dot(ns, ng) < 0.f;
      }
      if (flip) std::swap(v[1], v[2]);
      if (!is_black(le) && !(area2 > 0.f)) continue;  // a zero-area emitter cannot be sampled
      Triangle tri{{v[0], v[1], v[2]}, material, kNoLight};
      if (!is_black(le)) {
        Light l;
        l.type = LightType::area_triangle;
        l.shape = uint32_t(scene_.triangles.size());
        l.value = le;
        l.two_sided = gs_.area_two_sided;
        tri.light = int32_t(scene_.lights.size());
        scene_.lights.push_back(l);
      }
      scene_.triangles.push_back(tri);
    }
    if (smooth && normals.size() == pos.size()) {  // flat meshes need no shading normals
      auto world_normal = [&](const Mat4& inverse, const Vec3& n) {
        const Vec3 w = Mat4::normal(inverse, n);
        const float len = length(w);
        return len > 0.f && all_finite(w) ? w * ((gs_.reverse_orientation ? -1.f : 1.f) / len) : Vec3();
      };
      scene_.normals.resize(base);
      for (const Vec3& n : normals) scene_.normals.push_back(world_normal(inv, n));
      if (moving) {
        for (size_t i = scene_.normals_end.size(); i < base; ++i) scene_.normals_end.push_back(scene_.normals[i]);
        for (const Vec3& n : normals) scene_.normals_end.push_back(world_normal(inv_close, n));
      }
    }
  }

  void sphere(const Statement& st) {
    const float radius = float(st.get_float("radius", 1.0));
    const double zmin = st.get_float("zmin", -radius), zmax = st.get_float("zmax", radius), phimax = st.get_float("phimax", 360.0);
    if (zmin > -radius || zmax < radius || phimax < 360.0) warn(st.loc, "partial sphere (zmin/zmax/phimax) rendered as a full sphere");
    Mat4 open, close;
    if (shutter_transforms(st.loc, &open, &close)) {
      // Spheres do not move (scene/motion.h): a moving one becomes a triangle mesh that does.
      if (!(radius > 0.f)) throw Error(st.loc, "sphere radius must be > 0");
      const ObjectMesh m = sphere_mesh(radius);
      warn(st.loc, fmt::format("a moving sphere is rendered as a mesh of {} triangles", m.indices.size() / 3));
      add_mesh(st, m.positions, m.normals, m.uvs, m.indices, 0);
      return;
    }
    // Only similarity transforms keep a sphere a sphere.
    const Vec3 c0 = gs_.ctm.vector(Vec3(1, 0, 0)), c1 = gs_.ctm.vector(Vec3(0, 1, 0)), c2 = gs_.ctm.vector(Vec3(0, 0, 1));
    const float s = length(c0);
    if (std::fabs(length(c1) - s) > 1e-4f * s || std::fabs(length(c2) - s) > 1e-4f * s || abs_dot(c0, c1) > 1e-4f * s * s ||
        abs_dot(c0, c2) > 1e-4f * s * s || abs_dot(c1, c2) > 1e-4f * s * s)
      throw Error(st.loc, "sphere under a non-uniform scale or shear is not supported");
    if (!(radius > 0.f)) throw Error(st.loc, "sphere radius must be > 0");
    const uint32_t material = shape_material(st);
    const double world_radius = double(radius) * double(s);
    const Rgb le = shape_radiance(emission(st, material), 4.0 * M_PI * world_radius * world_radius);
    if (!is_black(le) && gs_.area_two_sided) warn(st.loc, "two-sided emission of a sphere: only the outside emits");
    const bool inward = gs_.reverse_orientation != (gs_.ctm.det3() < 0.0);
    scene_.add_sphere(gs_.ctm.point(Vec3()), radius * s, material, le, inward);
  }

  const SceneLoadOptions& options_;
  LoadWarnings* warnings_;
  std::string main_folder_;
  Scene scene_;
  GraphicsState gs_;
  std::vector<std::pair<GraphicsState, bool>> stack_;  // bool: pushed by TransformBegin
  std::map<std::string, int> named_materials_;
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
  float exposure_time_ = 1.f, iso_ = 100.f;  // the film's imaging ratio (film_sensor)
  int film_width_ = 1280, film_height_ = 720, spp_ = 16, max_depth_ = 5;
  std::string image_name_;
};

}  // namespace

namespace {
// Every Error from a scene file names at least the file (checks deep in Scene have no location).
// A null `warnings` discards them.
template <typename F>
Scene located(const std::string& name, LoadWarnings* warnings, F&& load) {
  LoadWarnings discard(nullptr);
  try {
    return load(warnings ? warnings : &discard);
  } catch (const Error& e) {
    if (!e.location().file.empty()) throw;
    throw Error(FileLoc{name}, e.what());
  }
}
}  // namespace

Scene load_pbrt_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings, SceneFileSettings* settings) {
  return located(path, warnings, [&](LoadWarnings* w) {
    Builder b(options, w, std::filesystem::path(path).parent_path().string());
    parse_file(path, [&](const Statement& st) { b.handle(st); });
    return b.finish(settings);
  });
}

Scene load_pbrt_string(const std::string& text, const std::string& name, const std::string& folder, const SceneLoadOptions& options,
                       LoadWarnings* warnings, SceneFileSettings* settings) {
  return located(name, warnings, [&](LoadWarnings* w) {
    Builder b(options, w, folder);
    parse_string(text, name, folder, [&](const Statement& st) { b.handle(st); });
    return b.finish(settings);
  });
}

}  // namespace pathspace::pbrt
