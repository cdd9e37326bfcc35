// Mitsuba scene construction (see mitsuba_loader.h): walks the top-level elements in file order.
// Mitsuba's max_depth counts path segments ("1 renders only directly visible emitters, 2 direct
// illumination"), which is pathspace's max_path_segments; -1 (unbounded) becomes 1024, the pbrt
// loader's bound. The camera's image x runs along camera-space -x, as in Mitsuba's perspective sensor.
#include "pathspace/io/mitsuba/mitsuba_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/environment_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/mitsuba/mitsuba_materials.h"
#include "pathspace/io/mitsuba/mitsuba_media.h"
#include "pathspace/io/mitsuba/mitsuba_object.h"
#include "pathspace/io/mitsuba/mitsuba_shapes.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/scene_pixel_filter.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace::mitsuba {

namespace {

constexpr int kUnboundedSegments = 1024;

class Builder {
 public:
  Builder(const Document& doc, const SceneLoadOptions& o, LoadWarnings* w, std::string folder)
      : doc_(doc), options_(o), w_(w), folder_(std::move(folder)) {}

  Scene run(SceneFileSettings* settings) {
    const std::string version = doc_.attr(doc_.scene(), "version");
    if (version.empty()) w_->add(doc_.loc(doc_.scene()), "<scene> has no version attribute; read as Mitsuba 3");
    read_shutter();
    for (const pugi::xml_node& n : doc_.scene().children()) {
      if (n.type() != pugi::node_element) continue;
      const std::string tag = n.name();
      if (tag == "default") continue;  // read by Document
      if (tag == "texture" && !doc_.attr(n, "id").empty()) continue;  // found by Document for <ref>
      // What this element added is reported at its location by scene validation.
      const auto before = SceneSizes::of(scene_);
      if (tag == "integrator") integrator(Object(doc_, n));
      else if (tag == "sensor") sensor(Object(doc_, n));
      else if (tag == "bsdf") define_bsdf(n);
      else if (tag == "shape") shape(Object(doc_, n));
      else if (tag == "emitter") emitter(Object(doc_, n));
      else if (tag == "medium") media_.define(n);
      else if (tag == "path") {}  // read by Document (file resolution)
      else w_->add(doc_.loc(n), "<" + tag + "> is not supported; ignored");
      before.mark_since(&scene_, doc_.loc(n));
    }
    return finish(settings);
  }

 private:
  // The first sensor's shutter (Mitsuba 3's shutter_open and shutter_close, default 0 and 0: no
  // blur), read before the shapes that move during it, wherever the sensor stands in the file.
  void read_shutter() {
    for (const pugi::xml_node& n : doc_.scene().children("sensor")) {
      const Object o(doc_, n);
      shutter_.open = o.get_float("shutter_open", 0.0);
      shutter_.close = o.get_float("shutter_close", 0.0);
      if (!(std::isfinite(shutter_.open) && std::isfinite(shutter_.close) && shutter_.close >= shutter_.open))
        throw Error(o.loc(), "shutter_close must not be before shutter_open (both finite)");
      return;
    }
  }

  // The to_world of a directional or environment emitter, which does not move: an <animation> keeps
  // its first key.
  Mat4 still_transform(const Object& o) {
    bool animated = false;
    const Mat4 m = o.get_transform("to_world", &animated);
    if (animated)
      w_->add(o.loc(), o.title() + ": an animated to_world moves shapes, the sensor and point, spot and projector emitters "
                                   "only; this one keeps its first key");
    return m;
  }

  // The to_world of a point, spot or projector emitter at shutter open, and at shutter close in *close.
  Mat4 point_emitter_transform(const Object& o, Mat4* close) {
    const Object::TransformKeys keys = o.get_transform_keys("to_world");
    *close = keys.at(shutter_.close, o.loc());
    return keys.at(shutter_.open, o.loc());
  }

  // The emitter just added, placed at local point `local` by `open`, moves to where `close` puts it
  // (motion blur, scene/motion.h); it keeps its orientation at shutter open.
  void move_last_light(const Object& o, const Mat4& open, const Mat4& close, const Vec3& local) {
    if (open == close) return;
    Light& l = scene_.lights.back();
    l.position_end = close.point(local);
    l.moves = !(l.position == l.position_end);
    if (pbrt::rotation_between_degrees(open, close) > pbrt::kLightTurnWarningDegrees)
      w_->add(o.loc(), o.title() + ": the emitter turns while the shutter is open; it moves but keeps its orientation at shutter open");
  }

  Scene finish(SceneFileSettings* settings) {
    const int w = options_.width > 0 ? options_.width : film_width_;
    const int h = options_.height > 0 ? options_.height : film_height_;
    if (!has_sensor_) w_->add(doc_.loc(doc_.scene()), "no <sensor>; using a camera at the origin looking along +z");
    // Mitsuba's fov spans fov_axis; pathspace's file camera takes the shorter image axis.
    const HalfTangents t = half_tangents(fov_, w, h);
    const float fov_short = float(2.0 * std::atan(std::min(t.x, t.y)) * 180.0 / M_PI);
    if (!(fov_short > 0.f && fov_short < 180.f)) throw Error(sensor_loc_, "field of view must be between 0 and 180 degrees");
    auto camera_for = [&](const Mat4& m) {
      const Vec3 forward = m.vector(Vec3(0, 0, 1)), up = m.vector(Vec3(0, 1, 0)), right = -m.vector(Vec3(1, 0, 0));
      if (!(length(forward) > 0.f && length(up) > 0.f && length(right) > 0.f) || !all_finite(m.point(Vec3())))
        throw Error(sensor_loc_, "sensor to_world is singular");
      return make_file_camera(m.point(Vec3()), forward, right, up, fov_short, w, h);
    };
    scene_.camera = camera_for(camera_to_world_);
    set_thin_lens(&scene_.camera, aperture_radius_, focus_distance_);  // validated in sensor()
    scene_.camera.filter = pixel_filter_;
    if (!(camera_to_world_ == camera_to_world_end_)) {  // an animated sensor: motion blur (scene/motion.h)
      scene_.camera_moves = true;
      scene_.camera_end = camera_for(camera_to_world_end_).pose();
    }
    apply_camera_options(options_, false, w, h, &scene_);
    if (has_sensor_) scene_.sources.set_camera(sensor_loc_);
    scene_.max_path_segments = max_segments_;
    const Bounds3 b = scene_.geometry_bounds();
    if (!b.empty()) scene_.ray_epsilon = std::max(1e-4f, 5e-5f * length(b.hi - b.lo));
    if (settings) settings->spp = spp_;
    scene_.finalize();
    return std::move(scene_);
  }

  // Mitsuba's field of view (sensors and the projector): `fov` in degrees along `fov_axis` (x, y,
  // diagonal, smaller, larger; default x), or `focal_length` (default 50mm) on a 35 mm film's
  // diagonal.
  struct FieldOfView {
    double degrees = 45.0;
    std::string axis = "x";
  };
  FieldOfView read_fov(const Object& o) const {
    FieldOfView f;
    f.axis = o.get_string("fov_axis", "x");
    if (f.axis != "x" && f.axis != "y" && f.axis != "diagonal" && f.axis != "smaller" && f.axis != "larger")
      throw Error(o.find("fov_axis") ? doc_.loc(o.find("fov_axis")->node) : o.loc(), "fov_axis must be x, y, diagonal, smaller or larger");
    if (o.has("fov")) {
      f.degrees = o.get_float("fov", 45.0);
    } else {  // Mitsuba: a 35 mm film's diagonal (43.27 mm) seen through focal_length (default 50mm)
      const std::string text = o.get_string("focal_length", "50mm");
      const std::string digits = text.size() > 2 && text.substr(text.size() - 2) == "mm" ? text.substr(0, text.size() - 2) : text;
      const double mm = parse_number(digits, o.loc());
      if (!(mm > 0.0)) throw Error(o.loc(), "focal_length must be positive");
      f.degrees = 2.0 * std::atan(std::hypot(36.0, 24.0) / (2.0 * mm)) * 180.0 / M_PI;
      f.axis = "diagonal";
    }
    return f;
  }

  // Tangents of the half angles along x and y of a w x h image seen with field of view f.
  struct HalfTangents {
    double x = 1.0, y = 1.0;
  };
  static HalfTangents half_tangents(const FieldOfView& f, double w, double h) {
    const double t = std::tan(f.degrees * M_PI / 360.0), diag = std::hypot(w, h);
    if (f.axis == "y" || (f.axis == "smaller" && h <= w) || (f.axis == "larger" && h >= w)) return {t * w / h, t};
    if (f.axis == "diagonal") return {t * w / diag, t * h / diag};
    return {t, t * h / w};
  }

  void integrator(const Object& o) {
    if (o.type() == "direct") {  // direct illumination: what PT computes with 2 segments (emission and one bounce)
      max_segments_ = 2;
      if (o.get_bool("hide_emitters", false)) w_->add(doc_.loc(o.find("hide_emitters")->node), "hide_emitters is not supported; emitters stay visible");
      o.ignore({"emitter_samples", "bsdf_samples", "shading_samples"});  // sample counts: the noise, not the expectation
      o.warn_unused(w_);
      return;
    }
    if (o.type() != "path" && o.type() != "volpath") {
      w_->add(o.loc(), "integrator '" + o.type() + "': pathspace renders with the --integrator option (default pt); only max_depth is used");
      for (const pugi::xml_node& inner : o.children("integrator")) return integrator(Object(doc_, inner));  // aov, moment: the wrapped one
    }
    const int depth = o.get_int("max_depth", -1);
    if (depth != -1 && (depth < 1 || depth > kUnboundedSegments))
      throw Error(o.loc(), "max_depth must be -1 (unbounded) or between 1 and " + std::to_string(kUnboundedSegments));
    max_segments_ = depth == -1 ? kUnboundedSegments : depth;
    if (o.get_bool("hide_emitters", false)) w_->add(doc_.loc(o.find("hide_emitters")->node), "hide_emitters is not supported; emitters stay visible");
    o.ignore({"rr_depth"});
    if (o.type() != "path" && o.type() != "volpath") o.ignore_all();
    o.warn_unused(w_);
  }

  void sensor(const Object& o) {
    if (o.type() != "perspective" && o.type() != "thinlens")
      throw Error(o.loc(), "sensor type '" + o.type() + "' is not supported (only perspective)");
    if (o.type() == "thinlens") {  // both parameters required, as in Mitsuba 0.6 (Mitsuba 3's focus_distance 0 is degenerate)
      for (const char* name : {"aperture_radius", "focus_distance"})
        if (!o.has(name)) throw Error(o.loc(), std::string("thinlens sensor needs ") + name + " (0.6: apertureRadius, focusDistance)");
      aperture_radius_ = float(o.get_float("aperture_radius", 0.0));
      focus_distance_ = float(o.get_float("focus_distance", 0.0));
      if (!(aperture_radius_ >= 0.f && std::isfinite(aperture_radius_)))
        throw Error(doc_.loc(o.find("aperture_radius")->node), "aperture_radius must be finite and >= 0");
      if (!(focus_distance_ > 0.f && std::isfinite(focus_distance_)))
        throw Error(doc_.loc(o.find("focus_distance")->node), "focus_distance must be finite and positive");
    }
    has_sensor_ = true;
    sensor_loc_ = o.loc();
    fov_ = read_fov(o);
    // An animated to_world moves the camera over the shutter, as an animated shape moves.
    const Object::TransformKeys keys = o.get_transform_keys("to_world");
    camera_to_world_ = keys.at(shutter_.open, o.loc());
    camera_to_world_end_ = keys.at(shutter_.close, o.loc());
    const double degrees = pbrt::rotation_between_degrees(camera_to_world_, camera_to_world_end_);
    if (degrees > pbrt::kMaxLinearRotationDegrees)
      w_->add(o.loc(), o.title() + ": the camera turns " + std::to_string(int(std::lround(degrees))) +
                           " degrees while the shutter is open; its view direction is blended linearly, not turned on an arc");
    o.ignore({"near_clip", "far_clip", "shutter_open", "shutter_close", "principal_point_offset_x", "principal_point_offset_y"});
    for (const pugi::xml_node& n : o.children("film")) film(Object(doc_, n));
    for (const pugi::xml_node& n : o.children("sampler")) sampler(Object(doc_, n));
    scene_.media.camera_medium = media_.endpoint_medium(o);
    o.warn_unused(w_);
  }

  void film(const Object& o) {
    if (o.type() != "hdrfilm" && o.type() != "ldrfilm") w_->add(o.loc(), "film '" + o.type() + "' treated as hdrfilm");
    film_width_ = o.get_int("width", 768);
    film_height_ = o.get_int("height", 576);
    if (film_width_ < 1 || film_height_ < 1 || film_width_ > kMaxImageSide || film_height_ > kMaxImageSide)
      throw Error(o.loc(), "film width and height must be between 1 and " + std::to_string(kMaxImageSide));
    for (const pugi::xml_node& n : o.children("rfilter")) rfilter(Object(doc_, n));
    o.ignore({"file_format", "pixel_format", "component_format", "banner", "high_quality_edges", "tonemap_method", "gamma", "exposure"});
    o.warn_unused(w_);
  }

  // Mitsuba 3's filters with their parameters: box (radius 0.5), tent (radius), gaussian (stddev,
  // radius 4 stddev), mitchell (B, C; radius 2) and catmullrom (mitchell with B 0, C 0.5).
  void rfilter(const Object& f) {
    const std::string& type = f.type();
    PixelFilterKind kind = PixelFilterKind::box;
    double radius = 0.5, sigma = 0.5, b = 1.0 / 3.0, c = 1.0 / 3.0;
    if (type == "tent") {
      kind = PixelFilterKind::tent;
      radius = f.get_float("radius", 1.0);
    } else if (type == "gaussian") {
      kind = PixelFilterKind::gaussian;
      sigma = f.get_float("stddev", 0.5);
      radius = 4.0 * sigma;
    } else if (type == "mitchell" || type == "catmullrom") {
      kind = PixelFilterKind::mitchell;
      radius = 2.0;
      if (type == "catmullrom") {
        b = 0.0;
        c = 0.5;
      } else {
        b = f.get_float("B", b);
        c = f.get_float("C", c);
      }
    } else if (type != "box") {
      w_->add(f.loc(), "reconstruction filter '" + type + "' not supported: pathspace uses a box filter of one pixel");
      f.ignore_all();
      return;
    }
    pixel_filter_ = scene_pixel_filter(kind, radius, sigma, b, c, f.loc(), w_);
    f.warn_unused(w_);
  }

  void sampler(const Object& o) {
    spp_ = o.get_int("sample_count", 4);
    if (spp_ < 1 || spp_ > kMaxSamplesPerPixel)
      throw Error(o.loc(), "sample_count must be between 1 and " + std::to_string(kMaxSamplesPerPixel) + " (--spp's range)");
    o.ignore_all();  // sampler kind, seed, jitter: they change the noise, not the expectation
  }

  void define_bsdf(const pugi::xml_node& n) {
    const std::string id = doc_.attr(n, "id");
    if (id.empty()) w_->add(doc_.loc(n), "top-level <bsdf> without an id is never used; ignored");
    if (named_.count(id)) w_->add(doc_.loc(n), "bsdf id '" + id + "' redefined");
    named_[id] = make_bsdf(doc_, n, named_, folder_, w_, &textures_);
    material_index_.erase(id);
  }

  uint32_t shape_material(const Object& o) {
    std::vector<pugi::xml_node> b = o.children("bsdf");
    for (const pugi::xml_node& r : o.children("ref"))
      if (!media_.is_medium_ref(r)) b.push_back(r);  // media refs: shape_media
    if (b.size() > 1) w_->add(o.loc(), o.title() + " has more than one BSDF; the first is used");
    if (b.empty()) {
      if (default_material_ < 0) default_material_ = int(scene_.add_material(default_bsdf()));
      return uint32_t(default_material_);
    }
    if (std::string(b[0].name()) == "ref") {  // one material per id, however many shapes use it
      const std::string id = doc_.attr(b[0], "id");
      const auto it = material_index_.find(id);
      if (it != material_index_.end()) return it->second;
      return material_index_[id] = scene_.add_material(make_bsdf(doc_, b[0], named_, folder_, w_, &textures_));
    }
    return scene_.add_material(make_bsdf(doc_, b[0], named_, folder_, w_, &textures_));
  }

  // <shape type="shapegroup" id="..."> holds shapes that only <shape type="instance"> places; an
  // instance names its group with <ref id="..."/> (Mitsuba 3's instancing, flattened into copies).
  void shape(const Object& o, const InstanceTransform& instance = {}) {
    if (o.type() == "shapegroup") return shape_group(o);
    if (o.type() == "instance") return place_instance(o);
    const pbrt::SceneCounts before = pbrt::SceneCounts::of(scene_);
    const MediumInterface media = media_.shape_media(o);
    const uint32_t material = shape_material(o);
    Rgb radiance;
    for (const pugi::xml_node& n : o.children("emitter")) {
      const Object e(doc_, n);
      if (e.type() != "area") {
        w_->add(e.loc(), "emitter '" + e.type() + "' inside a shape is not supported; skipped");
        e.ignore_all();
      } else {
        radiance = e.get_rgb("radiance", Rgb(1.f), folder_, w_, SpectrumUse::unbounded);
      }
      e.warn_unused(w_);
    }
    const Material& m = scene_.materials[material];
    if (!is_black(radiance) && (!is_black(m.diffuse) || !is_black(m.glossy) || !is_black(m.specular) || m.type != MaterialType::standard))
      w_->add(o.loc(), "an emissive shape's BSDF is ignored (pathspace emitters do not reflect light)");
    add_shape(o, material, radiance, folder_, shutter_, w_, &scene_, instance);
    pbrt::bind_added(media, before, pbrt::SceneCounts::of(scene_), &scene_.media);
    o.warn_unused(w_);
  }

  void shape_group(const Object& o) {
    const std::string id = doc_.attr(o.node(), "id");
    if (id.empty()) throw Error(o.loc(), "a shapegroup needs an id (instances name it)");
    if (!groups_.emplace(id, o.node()).second) throw Error(o.loc(), "a second shapegroup with id '" + id + "'");
    for (const pugi::xml_node& n : o.node().children()) {
      if (n.type() != pugi::node_element) continue;
      if (std::string(n.name()) != "shape") throw Error(doc_.loc(n), "a shapegroup holds <shape> elements only, not <" + std::string(n.name()) + ">");
      const std::string inner = doc_.attr(n, "type");
      if (inner == "shapegroup" || inner == "instance") throw Error(doc_.loc(n), "a shapegroup cannot hold a shapegroup or an instance (nor can Mitsuba 3's)");
    }
    o.ignore_all();
  }

  void place_instance(const Object& o) {
    const pugi::xml_node ref = o.node().child("ref");
    const std::string id = ref ? doc_.attr(ref, "id") : std::string();
    const auto group = groups_.find(id);
    if (group == groups_.end())
      throw Error(o.loc(), id.empty() ? std::string("an instance needs <ref id=\"...\"/> naming a shapegroup")
                                      : "the instance names no shapegroup '" + id + "' defined before it");
    const InstanceTransform placed = instance_transform(o, shutter_, w_);
    for (const pugi::xml_node& n : group->second.children("shape")) shape(Object(doc_, n), placed);
    o.ignore_all();
    o.warn_unused(w_);
  }

  // An emitter with a medium (nested or <ref>) emits into it.
  void emitter(const Object& o) {
    const pbrt::SceneCounts before = pbrt::SceneCounts::of(scene_);
    const int32_t medium = media_.endpoint_medium(o);
    placed_emitter(o);
    pbrt::bind_added(make_medium_interface(medium, medium), before, pbrt::SceneCounts::of(scene_), &scene_.media);
  }

  void placed_emitter(const Object& o) {
    const std::string& t = o.type();
    if (t == "point") {
      Mat4 close;
      const Mat4 m = point_emitter_transform(o, &close);
      const Vec3 position = o.get_vector("position", Vec3());
      scene_.add_point_light(m.point(position), o.get_rgb("intensity", Rgb(1.f), folder_, w_, SpectrumUse::unbounded));
      move_last_light(o, m, close, position);
    } else if (t == "directional") {
      const Mat4 m = still_transform(o);
      const Vec3 dir = m.vector(o.get_vector("direction", Vec3(0, 0, 1)));
      if (!(length(dir) > 0.f) || !all_finite(dir)) throw Error(o.loc(), "directional emitter: direction must be non-zero");
      scene_.add_directional_light(dir, o.get_rgb("irradiance", Rgb(1.f), folder_, w_, SpectrumUse::unbounded));
    } else if (t == "constant") {
      if (has_environment_) throw Error(o.loc(), "a scene can hold at most one environment emitter");
      has_environment_ = true;
      scene_.add_environment_light(o.get_rgb("radiance", Rgb(1.f), folder_, w_, SpectrumUse::unbounded));
    } else if (t == "envmap") {
      if (has_environment_) throw Error(o.loc(), "a scene can hold at most one environment emitter");
      has_environment_ = true;
      envmap(o);
    } else if (t == "spot") {
      spot(o);
    } else if (t == "projector") {
      projector(o);
    } else {
      w_->add(o.loc(), "emitter type '" + t + "' is not supported at the top level; skipped");
      o.ignore_all();
    }
    o.warn_unused(w_);
  }

  // The orthonormal frame of an emitter's to_world (x, y: an image's axes; z: where it points).
  // Mitsuba maps directions through the inverse of to_world; with a non-uniform scale or a shear
  // that differs from this frame (warning).
  Frame emitter_frame(const Object& o, const Mat4& m) {
    Frame frame;
    if (!pbrt::axes_frame(m, &frame) || !all_finite(m.point(Vec3()))) throw Error(o.loc(), o.title() + ": to_world is singular");
    const Vec3 x = m.vector(Vec3(1, 0, 0)), y = m.vector(Vec3(0, 1, 0)), z = m.vector(Vec3(0, 0, 1));
    const float lx = length(x), ly = length(y), lz = length(z);
    if (std::fabs(dot(x, z)) > 1e-4f * lx * lz || std::fabs(dot(y, z)) > 1e-4f * ly * lz || std::fabs(dot(x, y)) > 1e-4f * lx * ly ||
        std::fabs(lx - ly) > 1e-4f * lx)
      w_->add(o.loc(), o.title() + ": to_world with a shear or non-uniform scale: its image is projected as if it were orthonormal");
    return frame;
  }

  // Mitsuba's spot: at the to_world origin, along its +z; full intensity inside beam_width (default
  // 3/4 of cutoff_angle, degrees), fading linearly in the angle to nothing at cutoff_angle; a bitmap
  // `texture` over the cone at uv = 0.5 + 0.5 (x, y) / (z tan cutoff), as Mitsuba 3's spot.
  void spot(const Object& o) {
    Mat4 close;
    const Mat4 m = point_emitter_transform(o, &close);
    const double cutoff = o.get_float("cutoff_angle", 20.0);
    const double beam = o.get_float("beam_width", cutoff * 0.75);
    if (!(cutoff > 0.0 && cutoff <= 180.0) || !(beam >= 0.0)) throw Error(o.loc(), "spot emitter: need 0 < cutoff_angle <= 180 and beam_width >= 0");
    const double inner = std::min(beam, cutoff);
    const Frame f = emitter_frame(o, m);
    scene_.add_spot_light(m.point(Vec3()), f.n, o.get_rgb("intensity", Rgb(1.f), folder_, w_, SpectrumUse::unbounded),
                          float(std::cos(cutoff * M_PI / 180.0)), float(std::cos(inner * M_PI / 180.0)));
    move_last_light(o, m, close, Vec3());
    Light& l = scene_.lights.back();
    l.falloff = SpotFalloff::linear_angle;
    if (!o.has("texture")) return;
    int32_t texture = -1;
    const Rgb scale = textured_rgb(o, "texture", Rgb(1.f), folder_, &textures_, w_, &texture);
    if (texture < 0) throw Error(o.loc(), "spot emitter: texture must be a bitmap (as in Mitsuba 3)");
    if (!(cutoff < 89.0)) throw Error(o.loc(), "spot emitter: a texture needs cutoff_angle below 89 degrees");
    const float k = float(0.5 / std::tan(cutoff * M_PI / 180.0));
    l.value *= scale;
    l.texture = texture;
    l.axis_u = f.s;
    l.axis_v = f.t;
    l.uv_scale_u = k;
    l.uv_scale_v = -k;  // Mitsuba's v = 0 is the image's top row, pathspace's the bottom
  }

  // Mitsuba 3's projector: `irradiance` (a bitmap, or a constant) on the plane at distance 1 along
  // to_world's +z, over the perspective sensor's field of view (fov, fov_axis, focal_length) for the
  // image's aspect ratio, times `scale`: intensity pi scale irradiance / cos^3 (Mitsuba 3's
  // projector.cpp), u running against to_world's x (Mitsuba's camera x axis points left).
  void projector(const Object& o) {
    if (!o.has("irradiance")) throw Error(o.loc(), "projector emitter needs irradiance");
    Mat4 close;
    const Mat4 m = point_emitter_transform(o, &close);
    const Frame f = emitter_frame(o, m);
    const Property* p = o.find("irradiance");
    int32_t texture = -1;
    const Rgb irradiance = p->tag == "texture" || p->tag == "ref"
                               ? textured_rgb(o, "irradiance", Rgb(1.f), folder_, &textures_, w_, &texture)
                               : o.get_rgb("irradiance", Rgb(1.f), folder_, w_, SpectrumUse::unbounded);
    const double aspect = texture >= 0 ? double(scene_.textures[size_t(texture)].width) / scene_.textures[size_t(texture)].height : 1.0;
    const FieldOfView fov = read_fov(o);
    if (!(fov.degrees > 0.0 && fov.degrees < 180.0)) throw Error(o.loc(), "projector emitter: fov must lie between 0 and 180 degrees");
    const HalfTangents t = half_tangents(fov, aspect, 1.0);
    const float scale = float(o.get_float("scale", 1.0));
    scene_.add_projector_light(m.point(Vec3()), f, irradiance * (kPi * scale), texture, float(-0.5 / t.x), float(0.5 / t.y), true);
    move_last_light(o, m, close, Vec3());
  }

  // An image environment: Mitsuba's lat-long mapping in the to_world frame (local y up,
  // lights/environment_map.h), radiance = scale * image.
  void envmap(const Object& o) {
    const std::string file = o.get_string("filename", "");
    const std::filesystem::path path = doc_.resolve_file(file, folder_);
    std::error_code ec;
    if (file.empty() || !std::filesystem::is_regular_file(path, ec))
      throw Error(o.find("filename") ? doc_.loc(o.find("filename")->node) : o.loc(),
                  "environment map '" + file + "' not found (looked for " + path.string() + ")");
    const Mat4 m = still_transform(o);
    EnvironmentImage image;
    try {
      image = read_environment_image(path.string(), EnvironmentMapping::lat_long, m.vector(Vec3(1, 0, 0)),
                                     m.vector(Vec3(0, 1, 0)), m.vector(Vec3(0, 0, 1)));
      const float scale = float(o.get_float("scale", 1.0));
      o.ignore({"filter_type", "mis_compensation"});
      scene_.add_environment_map(std::move(image), Rgb(scale));
    } catch (const Error& e) {
      throw Error(o.loc(), std::string("envmap: ") + e.what());
    }
  }

  const Document& doc_;
  const SceneLoadOptions& options_;
  LoadWarnings* w_;
  std::string folder_;
  Scene scene_;
  TextureBinding textures_{&scene_, {}};
  MediaReader media_{doc_, folder_, w_, &scene_.media};
  NamedMaterials named_;
  std::map<std::string, uint32_t> material_index_;
  int default_material_ = -1;
  bool has_sensor_ = false, has_environment_ = false;
  FileLoc sensor_loc_;
  Mat4 camera_to_world_, camera_to_world_end_;  // at shutter open and close
  Shutter shutter_;
  FieldOfView fov_;
  float aperture_radius_ = 0.f, focus_distance_ = 1.f;  // thinlens sensor; 0: pinhole
  std::map<std::string, pugi::xml_node> groups_;  // shapegroups by id, for the instances after them
  int film_width_ = 768, film_height_ = 576, spp_ = 0, max_segments_ = kUnboundedSegments;
  PixelFilter pixel_filter_;  // <rfilter>; without one the unit box, not Mitsuba's default gaussian
};

}  // namespace

Scene load_mitsuba_string(const std::string& text, const std::string& name, const std::string& folder,
                          const SceneLoadOptions& options, LoadWarnings* warnings, SceneFileSettings* settings) {
  const Document doc(text, name, options.defines, folder);
  Scene scene = Builder(doc, options, warnings, folder).run(settings);
  scene.name = name;
  return scene;
}

Scene load_mitsuba_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings,
                        SceneFileSettings* settings) {
  return load_mitsuba_string(read_file_bytes(path), path, std::filesystem::path(path).parent_path().string(), options, warnings,
                             settings);
}

}  // namespace pathspace::mitsuba
