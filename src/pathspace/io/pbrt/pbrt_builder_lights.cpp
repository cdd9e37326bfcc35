// The pbrt-v4 scene builder's LightSource statements (pbrt_builder.h): point, spot, projection,
// distant and infinite lights, and point-like lights under animated transforms.
#include "pathspace/io/pbrt/pbrt_builder.h"

#include <cmath>
#include <filesystem>

#include "pathspace/io/environment_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/pbrt/pbrt_environment.h"

namespace pathspace::pbrt {

void SceneBuilder::light(const Statement& st) {
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

void SceneBuilder::move_point_light(const FileLoc& loc, Light* l) {
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

void SceneBuilder::add_light(const Statement& st) {
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

void SceneBuilder::projection_light(const Statement& st, float scale, float power) {
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

void SceneBuilder::add_environment(const Rgb& radiance, const FileLoc& loc) {
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

void SceneBuilder::image_environment(const Statement& st, const Param& file, float scale) {
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

}  // namespace pathspace::pbrt
