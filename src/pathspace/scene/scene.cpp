// Scene construction helpers and finalisation (bounds, light-selection distribution).
#include "pathspace/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "pathspace/base/error.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/emission_cells_build.h"
#include "pathspace/scene/point_light_intensity.h"
#include "pathspace/scene/surface_opacity.h"

namespace pathspace {

uint32_t Scene::add_material(const Material& m) {
  materials.push_back(m);
  return uint32_t(materials.size() - 1);
}

uint32_t Scene::add_texture(ImageTexture t) {
  textures.push_back(std::move(t));
  return uint32_t(textures.size() - 1);
}

uint32_t Scene::add_vertex(const Vec3& p) {
  positions.push_back(p);
  return uint32_t(positions.size() - 1);
}

uint32_t Scene::add_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, uint32_t material, const Rgb& emission,
                             bool two_sided_emission) {
  Triangle t{{add_vertex(p0), add_vertex(p1), add_vertex(p2)}, material, kNoLight};
  const uint32_t index = uint32_t(triangles.size());
  if (!is_black(emission)) {
    Light l;
    l.type = LightType::area_triangle;
    l.shape = index;
    l.value = emission;
    l.two_sided = two_sided_emission;
    t.light = int32_t(lights.size());
    lights.push_back(l);
  }
  triangles.push_back(t);
  return index;
}

void Scene::add_quad(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, uint32_t material,
                     const Rgb& emission, bool two_sided_emission) {
  add_triangle(p0, p1, p2, material, emission, two_sided_emission);
  add_triangle(p2, p3, p0, material, emission, two_sided_emission);
}

uint32_t Scene::add_sphere(const Vec3& center, float radius, uint32_t material, const Rgb& emission,
                           bool inward_normals) {
  Sphere s{center, radius, material, kNoLight, inward_normals};
  const uint32_t index = uint32_t(spheres.size());
  if (!is_black(emission)) {
    Light l;
    l.type = LightType::area_sphere;
    l.shape = index;
    l.value = emission;
    s.light = int32_t(lights.size());
    lights.push_back(l);
  }
  spheres.push_back(s);
  return index;
}

void Scene::add_point_light(const Vec3& position, const Rgb& intensity) {
  Light l;
  l.type = LightType::point;
  l.position = position;
  l.value = intensity;
  lights.push_back(l);
}

void Scene::add_spot_light(const Vec3& position, const Vec3& axis, const Rgb& intensity, float cos_total, float cos_falloff) {
  Light l;
  l.type = LightType::spot;
  l.position = position;
  l.direction = normalize(axis);
  l.value = intensity;
  l.cos_total = cos_total;
  l.cos_falloff = cos_falloff > cos_total ? cos_falloff : cos_total + 1e-6f;  // keep the smoothstep defined
  lights.push_back(l);
}

void Scene::add_projector_light(const Vec3& position, const Frame& frame, const Rgb& value, int32_t texture, float uv_scale_u,
                                float uv_scale_v, bool irradiance_plane) {
  Light l;
  l.type = LightType::projector;
  l.position = position;
  l.direction = frame.n;
  l.axis_u = frame.s;
  l.axis_v = frame.t;
  l.value = value;
  l.texture = texture;
  l.uv_scale_u = uv_scale_u;
  l.uv_scale_v = uv_scale_v;
  l.irradiance_plane = irradiance_plane;
  lights.push_back(l);
}

void Scene::add_directional_light(const Vec3& propagation_direction, const Rgb& irradiance) {
  Light l;
  l.type = LightType::directional;
  l.direction = normalize(propagation_direction);
  l.value = irradiance;
  lights.push_back(l);
}

void Scene::add_environment_light(const Rgb& radiance) {
  Light l;
  l.type = LightType::environment;
  l.value = radiance;
  lights.push_back(l);
}

void Scene::add_environment_map(EnvironmentImage image, const Rgb& scale) {
  environment_image = std::move(image);
  add_environment_light(scale);
}

Bounds3 Scene::geometry_bounds() const {
  Bounds3 b;
  for (const Triangle& t : triangles)
    for (uint32_t v : t.v) {
      b.expand(positions[v]);
      if (v < positions_end.size()) b.expand(positions_end[v]);  // everywhere the shutter sees it
    }
  for (const Sphere& s : spheres) {
    b.expand(s.center - Vec3(s.radius));
    b.expand(s.center + Vec3(s.radius));
  }
  return b;
}

namespace {

// The luminance power of a spot or projector with an image (or Mitsuba's fade), by a midpoint rule:
// over the spot's cone in (cos theta, phi), or over the projector's image plane (dw = cos^3 dA), at
// least two points per texel up to 1024 per axis. It weights light selection only.
float imaged_point_light_power(const Light& l, const std::vector<ImageTexture>& textures) {
  std::vector<TextureView> views;
  for (const ImageTexture& t : textures) views.push_back(t.view());
  SceneView v;
  v.textures = views.data();
  v.num_textures = uint32_t(views.size());
  const int texels = l.texture >= 0 ? std::max(textures[size_t(l.texture)].width, textures[size_t(l.texture)].height) : 32;
  const int n = std::clamp(2 * texels, 64, 1024);
  double sum = 0.0;
  if (l.type == LightType::spot) {
    const Frame f(l.direction);
    const double cos_min = std::max(-1.0, double(l.cos_total));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float c = float(cos_min + (1.0 - cos_min) * (j + 0.5) / n), phi = float(kTwoPi * (i + 0.5) / n);
        const float sin = std::sqrt(std::max(0.f, 1.f - c * c));
        sum += luminance(point_light_intensity(v, l, f.to_world(Vec3(sin * std::cos(phi), sin * std::sin(phi), c))));
      }
    return float(sum * (1.0 - cos_min) * kTwoPi / (double(n) * n));
  }
  const float hu = projector_half_width_u(l), hv = projector_half_width_v(l);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 p = l.axis_u * (hu * (2.f * (float(i) + 0.5f) / float(n) - 1.f)) + l.axis_v * (hv * (2.f * (float(j) + 0.5f) / float(n) - 1.f)) + l.direction;
      const float r = length(p);
      sum += luminance(point_light_intensity(v, l, p / r)) / double(r * r * r);
    }
  return float(sum * 4.0 * hu * hv / (double(n) * n));
}

// The mean of an emission map over one triangle, by 8 x 8 stratified points of uniform area
// density: what its texture makes of the triangle's power. It weights light selection only.
Rgb triangle_texture_mean(const ImageTexture& texture, const Triangle& tri, const std::vector<Point2>& uvs) {
  constexpr int kSide = 8;
  const bool has_uvs = uvs.size() > tri.v[0] && uvs.size() > tri.v[1] && uvs.size() > tri.v[2];
  Rgb sum;
  // The whole triangle: corners (1, 0), (0, 1), (0, 0) in barycentrics.
  for_each_map_lookup(tri, has_uvs ? uvs.data() : nullptr, texture.view(), Point2{1.f, 0.f}, Point2{0.f, 1.f}, Point2{0.f, 0.f},
                      1.f, kSide, [&](const Rgb& texel) { sum += texel; });
  return sum * (1.f / float(kSide * kSide));
}

}  // namespace

float Scene::light_power(size_t i) const {
  const Light& l = lights[i];
  const float r = bounds_.radius;
  switch (l.type) {
    case LightType::area_triangle: {
      const Triangle& t = triangles[l.shape];
      const float area = triangle_area(positions[t.v[0]], positions[t.v[1]], positions[t.v[2]]);
      const Rgb value = l.texture >= 0 ? l.value * triangle_texture_mean(textures[size_t(l.texture)], t, uvs) : l.value;
      return kPi * area * luminance(value) * (l.two_sided ? 2.f : 1.f);
    }
    case LightType::area_sphere: {
      const float rs = spheres[l.shape].radius;
      return kPi * kFourPi * rs * rs * luminance(l.value);
    }
    case LightType::point: return kFourPi * luminance(l.value);
    // Integral of the smoothstep falloff over the sphere (pbrt-v4's SpotLight::Phi).
    case LightType::spot:
      if (l.texture < 0 && l.falloff == SpotFalloff::smoothstep_cosine)
        return kTwoPi * (1.f - 0.5f * (l.cos_falloff + l.cos_total)) * luminance(l.value);
      return imaged_point_light_power(l, textures);
    case LightType::projector: return imaged_point_light_power(l, textures);
    case LightType::directional: return kPi * r * r * luminance(l.value);
    case LightType::environment:
      return kFourPi * kPi * r * r * luminance(environment_image.empty() ? l.value : l.value * environment_image.sphere_mean());
  }
  return 0.f;
}

const std::vector<std::string>& light_selection_names() {
  static const std::vector<std::string> names{"uniform", "power", "bvh"};
  return names;
}

const std::string& light_selection_name(LightSelection s) { return light_selection_names()[size_t(s)]; }

bool parse_light_selection(const std::string& name, LightSelection* out) {
  const std::vector<std::string>& names = light_selection_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) {
      *out = LightSelection(i);
      return true;
    }
  return false;
}

namespace {
const float kHardSpotSpreadCos = std::cos(1e-3f);
}  // namespace

std::optional<LightBounds> Scene::light_bounds(size_t i) const {
  const Light& l = lights[i];
  LightBounds b;
  b.phi = light_power(i);
  if (is_point_light(l)) {
    b.box.expand(l.position);
    if (l.moves) b.box.expand(l.position_end);  // everywhere the shutter sees it
  }
  switch (l.type) {
    case LightType::area_triangle: {
      const Triangle& t = triangles[l.shape];
      const Vec3 p0 = positions[t.v[0]], p1 = positions[t.v[1]], p2 = positions[t.v[2]];
      for (const Vec3& p : {p0, p1, p2}) b.box.expand(p);
      // Emission leaves the front side (along the geometric normal), cosine-distributed.
      b.w = triangle_normal(p0, p1, p2);
      if (!all_finite(b.w)) b.phi = 0.f;  // a degenerate triangle emits nothing
      b.cos_theta_o = 1.f;
      if (!positions_end.empty()) {
        // Moving (motion blur): the box holds both ends of the motion, which is linear per vertex. A
        // triangle that turns takes normals between the ends that no cone through the two ends'
        // normals is sure to hold (the blend of its edges is not a rotation), so it gets every
        // direction; one that keeps its normal (a translation, up to rounding) keeps its cone,
        // widened to the end's normal.
        const Vec3 q0 = positions_end[t.v[0]], q1 = positions_end[t.v[1]], q2 = positions_end[t.v[2]];
        for (const Vec3& q : {q0, q1, q2}) b.box.expand(q);
        const Vec3 w_end = triangle_normal(q0, q1, q2);
        if (!all_finite(w_end)) b.phi = 0.f;
        const float c = dot(b.w, w_end);
        b.cos_theta_o = c > 0.9999f ? std::min(1.f, c) : -1.f;
      }
      b.cos_theta_e = 0.f;
      b.two_sided = l.two_sided;
      return b;
    }
    case LightType::area_sphere: {
      const Sphere& s = spheres[l.shape];
      b.box.expand(s.center - Vec3(s.radius));
      b.box.expand(s.center + Vec3(s.radius));
      b.cos_theta_o = -1.f;  // normals in every direction
      b.cos_theta_e = 0.f;
      return b;
    }
    case LightType::point:  // the box: above, as for spots and projectors
      b.cos_theta_o = -1.f;
      b.cos_theta_e = 0.f;
      return b;
    case LightType::spot: {
      // Full intensity within the falloff cone; the smoothstep reaches zero at the total angle.
      b.w = l.direction;
      b.cos_theta_o = std::clamp(l.cos_falloff, -1.f, 1.f);
      b.cos_theta_e = std::cos(std::max(0.f, std::acos(std::clamp(l.cos_total, -1.f, 1.f)) - std::acos(b.cos_theta_o)));
      // A hard-edged spot (cos_falloff = cos_total) has no spread: cos_theta_e = 1 would make the
      // importance test (cos_p <= cos_theta_e) reject even the points on its axis, and the tree would
      // never pick it. A spread of 1e-3 rad keeps the bound conservative.
      b.cos_theta_e = std::min(b.cos_theta_e, kHardSpotSpreadCos);
      return b;
    }
    case LightType::projector: {  // within the cone through the image plane's corners
      b.w = l.direction;
      const float hu = projector_half_width_u(l), hv = projector_half_width_v(l);
      b.cos_theta_o = 1.f;
      b.cos_theta_e = 1.f / std::sqrt(1.f + hu * hu + hv * hv);
      return b;
    }
    case LightType::directional:
    case LightType::environment: return std::nullopt;
  }
  return std::nullopt;
}

void Scene::finalize() {
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    for (uint32_t v : t.v)
      if (v >= positions.size()) throw Error("triangle " + std::to_string(i) + " references vertex " + std::to_string(v) + " of " + std::to_string(positions.size()));
    if (t.material >= materials.size()) throw Error("triangle " + std::to_string(i) + " has no material " + std::to_string(t.material));
  }
  for (size_t i = 0; i < spheres.size(); ++i) {
    if (!(spheres[i].radius > 0.f)) throw Error("sphere " + std::to_string(i) + " has radius " + std::to_string(spheres[i].radius) + " (must be > 0)");
    if (spheres[i].material >= materials.size()) throw Error("sphere " + std::to_string(i) + " has no material");
  }
  for (size_t i = 0; i < textures.size(); ++i) {
    const ImageTexture& t = textures[i];
    if (t.width <= 0 || t.height <= 0 || t.texel_count() != size_t(t.width) * size_t(t.height))
      throw Error("texture " + std::to_string(i) + " ('" + t.name + "') has no or inconsistent texels");
  }
  for (size_t i = 0; i < materials.size(); ++i)
    for (int32_t t : {materials[i].diffuse_texture, materials[i].glossy_texture, materials[i].specular_texture,
                      materials[i].opacity_texture})
      if (t >= int32_t(textures.size()) || t < -1) throw Error("material " + std::to_string(i) + " references texture " + std::to_string(t) + " of " + std::to_string(textures.size()));
  for (size_t i = 0; i < lights.size(); ++i) {
    Light& l = lights[i];
    if (l.texture >= int32_t(textures.size()) || l.texture < -1)
      throw Error("light " + std::to_string(i) + " references texture " + std::to_string(l.texture) + " of " + std::to_string(textures.size()));
    l.image_max = 1.f;
    if (l.texture >= 0) {
      l.image_max = 0.f;
      const ImageTexture& t = textures[size_t(l.texture)];
      for (size_t k = 0; k < t.texel_count(); ++k) l.image_max = std::max(l.image_max, max_component(t.texel(k)));
    }
    const size_t shapes = l.type == LightType::area_triangle ? triangles.size() : spheres.size();
    if ((l.type == LightType::area_triangle || l.type == LightType::area_sphere) && l.shape >= shapes)
      throw Error("light " + std::to_string(i) + " is " + (l.type == LightType::area_triangle ? "triangle " : "sphere ") +
                  std::to_string(l.shape) + " of " + std::to_string(shapes));
  }
  if (uvs.size() > positions.size() || normals.size() > positions.size())
    throw Error("more vertex uvs or normals than vertices");
  if (!uvs.empty()) uvs.resize(positions.size());
  emission_cells_ = build_emission_cells(triangles, uvs, textures, &lights);
  if (!normals.empty()) normals.resize(positions.size());
  if (positions_end.size() > positions.size() || normals_end.size() > normals.size())
    throw Error("more end positions or normals (motion blur) than vertices");
  if (!positions_end.empty()) {
    for (size_t i = positions_end.size(); i < positions.size(); ++i) positions_end.push_back(positions[i]);
    for (size_t i = normals_end.size(); i < normals.size(); ++i) normals_end.push_back(normals[i]);
  } else if (!normals_end.empty()) {
    throw Error("end normals (motion blur) without end positions");
  }
  if (camera.width <= 0 || camera.height <= 0) throw Error("scene has no camera resolution");
  media.finalize(triangles.size(), spheres.size(), lights.size());

  const Bounds3 b = geometry_bounds();
  bounds_ = has_bounds_override ? bounds_override : (b.empty() ? BoundingSphere{Vec3(), 1.f} : bounding_sphere(b));

  if (!environment_image.empty()) environment_image.prepare();
  environment_light_ = -1;
  std::vector<float> weights(lights.size(), 1.f);
  for (size_t i = 0; i < lights.size(); ++i) {
    if (lights[i].type == LightType::environment) {
      if (environment_light_ >= 0) throw Error("a scene can hold at most one environment light");
      environment_light_ = int32_t(i);
    }
    if (light_selection != LightSelection::uniform) weights[i] = light_power(i);
  }
  if (!environment_image.empty() && environment_light_ < 0) throw Error("an environment image without an environment light");
  light_distribution_.build(weights);
  light_tree_ = LightTree();
  if (light_selection == LightSelection::bvh) {
    std::vector<std::optional<LightBounds>> bounds(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) bounds[i] = light_bounds(i);
    light_tree_ = LightTree(bounds);
    if (!light_tree_.can_differ_from_power()) light_tree_ = LightTree();
  }
  has_cutouts_ = any_cutout_triangle();
  finalized_ = true;
}

bool Scene::any_cutout_triangle() const {
  std::vector<char> cutout(materials.size());
  bool any = false;
  for (size_t i = 0; i < materials.size(); ++i) {
    cutout[i] = has_cutout(materials[i]);
    any = any || cutout[i];
  }
  if (!any) return false;
  for (const Triangle& t : triangles)
    if (t.light == kNoLight && t.material < materials.size() && cutout[t.material]) return true;
  return false;
}

SceneView Scene::view() const {
  if (!finalized_) throw Error("Scene::view() called before finalize()");
  SceneView v;
  v.positions = positions.data();
  v.uvs = uvs.size() == positions.size() && !uvs.empty() ? uvs.data() : nullptr;
  v.normals = normals.size() == positions.size() && !normals.empty() ? normals.data() : nullptr;
  v.positions_end = positions_end.empty() ? nullptr : positions_end.data();
  v.normals_end = v.positions_end && v.normals ? normals_end.data() : nullptr;
  v.triangles = triangles.data();
  v.num_triangles = uint32_t(triangles.size());
  v.spheres = spheres.data();
  v.num_spheres = uint32_t(spheres.size());
  v.materials = materials.data();
  v.num_materials = uint32_t(materials.size());
  bool fresh = texture_views_.size() == textures.size();
  for (size_t i = 0; fresh && i < textures.size(); ++i)
    fresh = texture_views_[i].texels == textures[i].texels.data() && texture_views_[i].bytes == textures[i].view().bytes;
  if (!fresh) {
    texture_views_.clear();
    for (const ImageTexture& t : textures) texture_views_.push_back(t.view());
  }
  v.textures = texture_views_.empty() ? nullptr : texture_views_.data();
  v.num_textures = uint32_t(texture_views_.size());
  v.lights = lights.data();
  v.num_lights = uint32_t(lights.size());
  v.emission_cells = emission_cells_.empty() ? nullptr : emission_cells_.data();
  v.num_emission_cells = uint32_t(emission_cells_.size());
  v.light_selection = light_distribution_.view();
  if (light_selection == LightSelection::bvh && !light_tree_.nodes().empty()) v.light_tree = light_tree_.view();
  v.environment_light = environment_light_;
  v.environment_map = environment_image.view();
  v.media = media.view();
  v.camera = camera;
  v.camera_moves = camera_moves;
  v.lights_move = std::any_of(lights.begin(), lights.end(), [](const Light& l) { return is_point_light(l) && l.moves; });
  v.camera_end = camera_end;
  v.bounds = bounds_;
  v.ray_epsilon = ray_epsilon;
  v.max_path_segments = max_path_segments;
  v.has_cutouts = has_cutouts_;
  return v;
}

}  // namespace pathspace
