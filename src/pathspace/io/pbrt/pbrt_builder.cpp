// The pbrt-v4 scene builder (pbrt_builder.h): statements, the graphics state and its transforms, the
// camera, film, materials and the finished scene.
#include "pathspace/io/pbrt/pbrt_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/scene_pixel_filter.h"
#include "pathspace/io/spectrum/white_balance.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace::pbrt {

float light_power_param(const Statement& st) {
  const double power = st.get_float("power", 0.0);
  if (!std::isfinite(power)) throw Error(st.find("power")->loc, "\"power\" must be finite");
  return power > 0.0 ? float(power) : 0.f;
}

void SceneBuilder::handle(const Statement& st) {
  // What this statement added is reported at its location by scene validation.
  const auto before = SceneSizes::of(scene_);
  dispatch(st);
  before.mark_since(&scene_, st.loc);
  for (const Param& p : st.params)
    if (!p.used) warn(p.loc, st.title() + ": parameter \"" + p.type + " " + p.name + "\" is not supported; ignored");
}

Scene SceneBuilder::finish(SceneFileSettings* settings) {
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
  scene_.camera.filter = pixel_filter_;
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
  media_.finish(&scene_.media);
  scene_.finalize();
  return std::move(scene_);
}

PerspectiveCamera SceneBuilder::file_camera_at(const Mat4& camera_from_world, int w, int h) const {
  Mat4 world_from_camera;
  if (!camera_from_world.inverse(&world_from_camera)) throw Error(camera_loc_, "camera transform is singular");
  return make_file_camera(world_from_camera.point(Vec3()), world_from_camera.vector(Vec3(0, 0, 1)),
                          world_from_camera.vector(Vec3(1, 0, 0)), world_from_camera.vector(Vec3(0, 1, 0)), fov_, w, h);
}

void SceneBuilder::at_shutter(const Mat4& start, const Mat4& end, double t0, double t1, const FileLoc& loc, Mat4* open, Mat4* close) const {
  if (start == end) {
    *open = *close = start;
    return;
  }
  if (!animated_transform_at(start, end, t0, t1, shutter_open_, open) || !animated_transform_at(start, end, t0, t1, shutter_close_, close))
    throw Error(loc, "the animated transform cannot be interpolated (a singular start or end transform)");
}

bool SceneBuilder::shutter_transforms(const FileLoc& loc, Mat4* open, Mat4* close) {
  at_shutter(gs_.ctm, gs_.ctm_end, transform_start_time_, transform_end_time_, loc, open, close);
  if (*open == *close) return false;  // the motion lies outside the shutter interval
  const double degrees = rotation_between_degrees(*open, *close);
  if (degrees > kMaxLinearRotationDegrees)
    warn(loc, fmt::format("the shape turns {:.0f} degrees while the shutter is open; its vertices move on straight lines "
                          "between shutter open and close (Embree's linear motion), not on pbrt-v4's arcs",
                          degrees));
  return true;
}

std::string SceneBuilder::folder_of(const Statement& st) const {
  const std::string f = std::filesystem::path(st.loc.file).parent_path().string();
  return f.empty() ? main_folder_ : f;
}

void SceneBuilder::dispatch(const Statement& st) {
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
    const std::optional<Mat4> r = Mat4::rotate(n[0], n[1], n[2], n[3]);
    if (!r) throw Error(st.loc, "Rotate needs an axis of nonzero length");
    transform(*r);
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
  } else if (d == "MakeNamedMedium") {
    media_.define(st, gs_.ctm, textures_, warnings_, &scene_.media);
  } else if (d == "MediumInterface") {
    gs_.media = media_.interface_of(st);
  } else if (d == "Option" || d == "Attribute") {
    warn(st.loc, d + " is not supported; ignored");
    mark_all(st);
  } else if (d == "Camera") {
    camera(st);
  } else if (d == "Film") {
    if (st.strings[0] != "rgb") warn(st.loc, "Film \"" + st.strings[0] + "\" treated as \"rgb\"");
    film_width_ = st.get_int("xresolution", 1280);
    film_height_ = st.get_int("yresolution", 720);
    if (film_width_ < 1 || film_height_ < 1 || film_width_ > kMaxImageSide || film_height_ > kMaxImageSide)
      throw Error(st.loc, "Film resolution must be between 1 and " + std::to_string(kMaxImageSide));
    image_name_ = st.get_string("filename", "");
    st.ignore({"savefp16"});
    film_sensor(st);
  } else if (d == "Sampler") {
    spp_ = st.get_int("pixelsamples", 16);
    if (spp_ < 1 || spp_ > kMaxSamplesPerPixel)
      throw Error(st.loc, "pixelsamples must be between 1 and " + std::to_string(kMaxSamplesPerPixel) + " (--spp's range)");
    mark_all(st);  // sampler kind, seed, randomisation: they change the noise, not the expectation
  } else if (d == "Integrator") {
    max_depth_ = st.get_int("maxdepth", 5);
    if (max_depth_ < 0 || max_depth_ > 1023) throw Error(st.loc, "maxdepth must be between 0 and 1023");
    if (st.strings[0] != "path" && st.strings[0] != "volpath")
      warn(st.loc, "Integrator \"" + st.strings[0] + "\": pathspace renders with the --integrator option (default pt); only maxdepth is used");
    st.ignore({"lightsampler"});
    if (st.strings[0] != "path" && st.strings[0] != "volpath") mark_all(st);
  } else if (d == "PixelFilter") {
    pixel_filter(st);
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
    const SceneCounts before = SceneCounts::of(scene_);
    light(st);
    media_.bind(gs_.media, before, SceneCounts::of(scene_));
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

bool SceneBuilder::image_missing(const Statement& st, const Param& p, const char* what, const std::string& stand_in) {
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

bool SceneBuilder::missing_image_texture(const Statement& st) {
  if (st.strings[2] != "imagemap") return false;
  const Param* file = st.find("filename");
  if (!file || !image_missing(st, *file, "texture file", "a constant mid grey (0.5)")) return false;
  textures_.values[st.strings[0]] = Rgb(kMissingTextureValue);
  mark_all(st);
  return true;
}

int SceneBuilder::material_index(const std::string& type, const Statement& st) {
  if (type == "interface") {  // a surface that only bounds media: paths pass it unchanged
    if (interface_material_ < 0) {
      Material m;
      m.type = MaterialType::interface;
      interface_material_ = int(scene_.add_material(m));
    }
    return interface_material_;
  }
  if (type == "" || type == "none") {
    warn(st.loc, "material \"" + type + "\": shapes are rendered with grey diffuse 0.5");
    return -1;
  }
  if (type == "subsurface") {  // a dielectric around its own medium (docs/media.md)
    const SubsurfaceMaterial sub = make_subsurface(st, textures_, warnings_);
    const int index = int(scene_.add_material(sub.boundary));
    try {
      interior_media_[index] = scene_.media.add_homogeneous(sub.sigma_a, sub.sigma_s, sub.g);
    } catch (const Error& e) {
      throw Error(st.loc, e.what());
    }
    return index;
  }
  return int(scene_.add_material(make_material(type, st, textures_, warnings_)));
}

void SceneBuilder::film_sensor(const Statement& st) {
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

void SceneBuilder::apply_imaging_ratio() {
  const float ratio = exposure_time_ * iso_ / 100.f;
  if (ratio == 1.f) return;
  for (Light& l : scene_.lights) l.value = l.value * ratio;
}

// PixelFilter: box, triangle (pathspace's tent), gaussian and mitchell with pbrt-v4's parameters and
// defaults; one radius for both axes.
void SceneBuilder::pixel_filter(const Statement& st) {
  const std::string& name = st.strings[0];
  const std::optional<PixelFilterKind> kind = name == "triangle" ? PixelFilterKind::tent : parse_pixel_filter_kind(name);
  if (!kind || name == "tent") {
    warn(st.loc, "PixelFilter \"" + name + "\" not supported: pathspace uses a box filter of one pixel");
    mark_all(st);
    return;
  }
  const double fallback = default_pixel_filter_radius(*kind);
  const double xradius = st.get_float("xradius", fallback), yradius = st.get_float("yradius", fallback);
  if (xradius != yradius) warn(st.loc, fmt::format("PixelFilter: xradius {} and yradius {} differ; pathspace uses xradius on both axes", xradius, yradius));
  const double sigma = *kind == PixelFilterKind::gaussian ? st.get_float("sigma", 0.5) : 0.5;
  const double b = *kind == PixelFilterKind::mitchell ? st.get_float("B", 1.0 / 3.0) : 1.0 / 3.0;
  const double c = *kind == PixelFilterKind::mitchell ? st.get_float("C", 1.0 / 3.0) : 1.0 / 3.0;
  pixel_filter_ = scene_pixel_filter(*kind, xradius, sigma, b, c, st.loc, warnings_);
}

void SceneBuilder::camera(const Statement& st) {
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
  media_.bind_camera(gs_.media);  // pbrt-v4's CameraMedium: the outside medium current here
  Mat4 inv;
  if (camera_from_world_.inverse(&inv)) coord_systems_["camera"] = {inv, inv};
}

}  // namespace pathspace::pbrt
