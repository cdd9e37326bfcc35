#include "pathspace/scene/scene_validation.h"

#include <cmath>

#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "pathspace/scene/surface_opacity.h"

namespace pathspace {

namespace {

std::string text(const Vec3& v) { return fmt::format("({:g}, {:g}, {:g})", v.x, v.y, v.z); }
std::string text(const Rgb& c) { return fmt::format("({:g}, {:g}, {:g})", c.r, c.g, c.b); }

// At the element's file:line:column when the loader recorded it (scene_sources.h).
[[noreturn]] void fail(const FileLoc* at, const std::string& message) {
  if (at) throw Error(*at, message);
  throw Error(message);
}

bool in_range(float x) { return std::isfinite(x) && std::fabs(x) <= kMaxSceneCoordinate; }
bool in_range(const Vec3& v) { return in_range(v.x) && in_range(v.y) && in_range(v.z); }

void check_point(const Vec3& p, const std::string& what, const FileLoc* at) {
  if (!in_range(p))
    fail(at, fmt::format("{} at {} is outside the supported range: every coordinate finite and within +-{:g}", what, text(p),
                            kMaxSceneCoordinate));
}

void check_length(float x, const std::string& what, bool zero_allowed, const FileLoc* at) {
  if (!in_range(x) || x < 0.f || (!zero_allowed && x == 0.f))
    fail(at, fmt::format("{} is {:g}, outside the supported range: {} and at most {:g}", what, x, zero_allowed ? ">= 0" : "> 0",
                            kMaxSceneCoordinate));
}

void check_direction(const Vec3& d, const std::string& what, const FileLoc* at) {
  if (!all_finite(d) || !(dot(d, d) > 0.f)) fail(at, fmt::format("{} {} is not a direction", what, text(d)));
}

// Reflectances, emission, complex IOR: finite and >= 0 per channel.
void check_non_negative(const Rgb& c, const std::string& what, const FileLoc* at) {
  if (!all_finite(c) || c.r < 0.f || c.g < 0.f || c.b < 0.f)
    fail(at, fmt::format("{} {} must be finite and >= 0 in every channel", what, text(c)));
}

void check_scalar(float x, float min, const std::string& what, const FileLoc* at) {
  if (!std::isfinite(x) || x < min) fail(at, fmt::format("{} is {:g}: it must be finite and >= {:g}", what, x, min));
}

void check_camera(const PerspectiveCamera& c, const FileLoc* at) {
  if (c.width < 1 || c.height < 1 || c.width > kMaxImageSide || c.height > kMaxImageSide)
    fail(at, fmt::format("the camera's image is {}x{} pixels: each side must be between 1 and {} (-r sets it)", c.width,
                            c.height, kMaxImageSide));
  check_point(c.position, "the camera", at);
  for (const Vec3& axis : {c.forward, c.right, c.up}) check_direction(axis, "a camera axis", at);
  if (!std::isfinite(c.tan_x) || !std::isfinite(c.tan_y) || !(c.tan_x > 0.f) || !(c.tan_y > 0.f))
    fail(at, fmt::format("the camera's field of view is not valid (tan of half angles {:g}, {:g})", c.tan_x, c.tan_y));
  check_length(c.lens_radius, "the camera's lens radius", true, at);
  if (!c.is_pinhole()) check_length(c.focus_distance, "the camera's focus distance", false, at);
}

void check_material(const Material& m, size_t i, const FileLoc* at, std::vector<std::string>* gains) {
  const std::string name = "material " + std::to_string(i);
  check_non_negative(m.diffuse, name + ": diffuse reflectance", at);
  check_non_negative(m.glossy, name + ": glossy reflectance", at);
  check_non_negative(m.specular, name + ": specular reflectance", at);
  check_scalar(m.exponent, 0.f, name + ": Phong exponent", at);
  check_scalar(m.ior, 0.f, name + ": index of refraction", at);
  check_scalar(m.alpha, 0.f, name + ": roughness", at);
  check_non_negative(m.eta, name + ": conductor eta", at);
  check_non_negative(m.k, name + ": conductor k", at);
  check_non_negative(m.tint, name + ": conductor reflectance factor", at);
  if (m.type == MaterialType::rough_dielectric && !(m.ior > 0.f))
    fail(at, fmt::format("{}: a rough dielectric needs an index of refraction > 0, not {:g}", name, m.ior));
  if (m.type == MaterialType::coated_diffuse || m.type == MaterialType::coated_conductor) {
    if (!(m.ior > 0.f)) fail(at, fmt::format("{}: a coat needs an index of refraction > 0, not {:g}", name, m.ior));
    check_scalar(m.base_alpha, 0.f, name + ": base roughness", at);
    check_scalar(m.thickness, 0.f, name + ": coat thickness", at);
    check_non_negative(m.medium_albedo, name + ": coat albedo", at);
    if (max_component(m.medium_albedo) > 1.f) fail(at, name + ": coat albedo above 1");
    if (!(m.g > -1.f && m.g < 1.f)) fail(at, fmt::format("{}: coat g must lie in (-1, 1), not {:g}", name, m.g));
    if (m.max_depth < 1 || m.n_samples < 1) fail(at, name + ": coat max_depth and n_samples must be at least 1");
  }
  if (!(m.opacity >= 0.f && m.opacity <= 1.f)) fail(at, fmt::format("{}: opacity is {:g}: it must lie in [0, 1]", name, m.opacity));
  if (max_component(m.diffuse + m.glossy) > 1.f || max_component(m.specular) > 1.f ||
      (m.type == MaterialType::rough_conductor && max_component(m.tint) > 1.f))
    gains->push_back(name);
}

// Image texels (textures, the environment image): NaN or Inf is an error (it would spread through
// every estimate that reads it); negative texels (an HDR map's ringing, say) are used as they are,
// with a warning.
void check_texels(const std::vector<Rgb>& texels, int width, const std::string& what, const FileLoc* at,
                  std::vector<std::string>* warnings) {
  size_t negative = 0;
  for (size_t i = 0; i < texels.size(); ++i) {
    const Rgb& t = texels[i];
    if (!all_finite(t))
      fail(at, fmt::format("{}: texel ({}, {}) is {}: every texel must be finite", what, width > 0 ? i % size_t(width) : 0,
                              width > 0 ? i / size_t(width) : 0, text(t)));
    if (t.r < 0.f || t.g < 0.f || t.b < 0.f) ++negative;
  }
  if (negative > 0)
    warnings->push_back(fmt::format("warning: {}{}: {} of its {} texels are negative (used as they are)", at ? at->to_string() + ": " : "",
                                    what, negative, texels.size()));
}

// Cutout opacity applies to triangles that do not emit (scene/surface_opacity.h): a warning where a
// scene gives it to spheres or emitters, which ignore it.
void warn_ignored_cutouts(const Scene& scene, std::vector<std::string>* warnings) {
  const auto cutout = [&](uint32_t material) { return material < scene.materials.size() && has_cutout(scene.materials[material]); };
  size_t spheres = 0, emitters = 0;
  for (const Sphere& s : scene.spheres) spheres += cutout(s.material);
  for (const Triangle& t : scene.triangles) emitters += t.light != kNoLight && cutout(t.material);
  if (spheres > 0) warnings->push_back(fmt::format("warning: opacity (a mask or alpha) on {} sphere(s) is ignored: only triangles have cutouts", spheres));
  if (emitters > 0) warnings->push_back(fmt::format("warning: opacity (a mask or alpha) on {} emitting triangle(s) is ignored: emitters are opaque", emitters));
}

}  // namespace

void validate_scene(const Scene& scene, std::vector<std::string>* warnings) {
  using K = SceneSources::Kind;
  const SceneSources& src = scene.sources;
  check_camera(scene.camera, src.camera());
  if (scene.camera_moves) {
    check_point(scene.camera_end.position, "the camera at shutter close", src.camera());
    for (const Vec3& axis : {scene.camera_end.forward, scene.camera_end.right, scene.camera_end.up})
      check_direction(axis, "a camera axis at shutter close", src.camera());
  }
  for (size_t i = 0; i < scene.positions.size(); ++i)
    check_point(scene.positions[i], "vertex " + std::to_string(i), src.find(K::kVertex, i));
  for (size_t i = 0; i < scene.positions_end.size(); ++i)
    check_point(scene.positions_end[i], "vertex " + std::to_string(i) + " at shutter close", src.find(K::kVertex, i));
  // Texture coordinates and shading normals from any format (OBJ vt/vn, PLY u v / nx ny nz, glTF
  // accessors): a NaN would become a NaN texel index or shading frame at every hit near it.
  for (size_t i = 0; i < scene.uvs.size(); ++i)
    if (!std::isfinite(scene.uvs[i].x) || !std::isfinite(scene.uvs[i].y))
      fail(src.find(K::kVertex, i), fmt::format("vertex {}: texture coordinates ({:g}, {:g}) must be finite", i, scene.uvs[i].x, scene.uvs[i].y));
  for (const std::vector<Vec3>* normals : {&scene.normals, &scene.normals_end})
    for (size_t i = 0; i < normals->size(); ++i)
      if (!all_finite((*normals)[i])) fail(src.find(K::kVertex, i), fmt::format("vertex {}: its normal must be finite", i));
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& s = scene.spheres[i];
    check_point(s.center, "the centre of sphere " + std::to_string(i), src.find(K::kSphere, i));
    check_length(s.radius, "the radius of sphere " + std::to_string(i), false, src.find(K::kSphere, i));
  }
  std::vector<std::string> gains;
  for (size_t i = 0; i < scene.materials.size(); ++i) check_material(scene.materials[i], i, src.find(K::kMaterial, i), &gains);
  warn_ignored_cutouts(scene, warnings);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    const std::string name = "light " + std::to_string(i);
    const FileLoc* at = src.find(K::kLight, i);
    check_non_negative(l.value, name + ": emission", at);
    if (is_point_light(l)) check_point(l.position, name, at);
    if (is_point_light(l) && l.moves) check_point(l.position_end, name + " at shutter close", at);
    if (l.type == LightType::directional || l.type == LightType::spot || l.type == LightType::projector)
      check_direction(l.direction, name + ": direction", at);
    if (l.type == LightType::projector && !(std::isfinite(l.uv_scale_u) && std::isfinite(l.uv_scale_v) && l.uv_scale_u != 0.f && l.uv_scale_v != 0.f))
      fail(at, name + ": the projector's field of view is not valid");
  }
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    const ImageTexture& t = scene.textures[i];
    const std::string name = "texture " + std::to_string(i) + " ('" + t.name + "')";
    if (!std::isfinite(t.uscale) || !std::isfinite(t.vscale) || !std::isfinite(t.udelta) || !std::isfinite(t.vdelta))
      fail(src.find(K::kTexture, i), name + ": its uv scale and offset must be finite");
    check_texels(t.texels, t.width, name, src.find(K::kTexture, i), warnings);  // 8-bit ones (bytes) are finite and >= 0
  }
  if (!scene.environment_image.empty()) {
    const FileLoc* at = nullptr;  // the environment light's statement
    for (size_t i = 0; i < scene.lights.size() && !at; ++i)
      if (scene.lights[i].type == LightType::environment) at = src.find(K::kLight, i);
    check_texels(scene.environment_image.texels, scene.environment_image.width, "the environment image", at, warnings);
  }
  if (!gains.empty())
    warnings->push_back(fmt::format("warning: {} reflect{} more light than {} receive{} (a reflectance above 1 adds energy)",
                                    fmt::join(gains, ", "), gains.size() == 1 ? "s" : "", gains.size() == 1 ? "it" : "they",
                                    gains.size() == 1 ? "s" : ""));
  if (scene.lights.empty())
    warnings->push_back("warning: the scene has no light sources (no emitting surface, light or environment): the image will be black");
}

}  // namespace pathspace
