// Embree 3 backend of Accel: one triangle geometry for all triangles and one user geometry for all
// analytic spheres (exact quadratic intersection in geometry/shapes.h, not Embree's tessellation-free
// "sphere points", so glass spheres are hit identically from inside and outside).
#include <embree3/rtcore.h>
#include <fmt/core.h>

#include <algorithm>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {
constexpr unsigned kTriangleGeometry = 0;
constexpr unsigned kSphereGeometry = 1;

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  args->bounds_o->lower_x = s.center.x - s.radius;
  args->bounds_o->lower_y = s.center.y - s.radius;
  args->bounds_o->lower_z = s.center.z - s.radius;
  args->bounds_o->upper_x = s.center.x + s.radius;
  args->bounds_o->upper_y = s.center.y + s.radius;
  args->bounds_o->upper_z = s.center.z + s.radius;
}

void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  RTCRayHitN* rayhit = args->rayhit;
  RTCRayN* ray = RTCRayHitN_RayN(rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const Vec3 o(RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i), RTCRayN_org_z(ray, args->N, i));
    const Vec3 d(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i), RTCRayN_dir_z(ray, args->N, i));
    float t;
    if (!intersect_sphere(s, o, d, RTCRayN_tnear(ray, args->N, i), RTCRayN_tfar(ray, args->N, i), &t)) continue;
    RTCRayN_tfar(ray, args->N, i) = t;
    const Vec3 n = (o + d * t - s.center);
    RTCHitN_Ng_x(hit, args->N, i) = n.x;
    RTCHitN_Ng_y(hit, args->N, i) = n.y;
    RTCHitN_Ng_z(hit, args->N, i) = n.z;
    RTCHitN_u(hit, args->N, i) = 0.f;
    RTCHitN_v(hit, args->N, i) = 0.f;
    RTCHitN_primID(hit, args->N, i) = args->primID;
    RTCHitN_geomID(hit, args->N, i) = args->geomID;
    RTCHitN_instID(hit, args->N, i, 0) = RTC_INVALID_GEOMETRY_ID;
  }
}

void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  RTCRayN* ray = args->ray;
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const Vec3 o(RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i), RTCRayN_org_z(ray, args->N, i));
    const Vec3 d(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i), RTCRayN_dir_z(ray, args->N, i));
    float t;
    if (intersect_sphere(s, o, d, RTCRayN_tnear(ray, args->N, i), RTCRayN_tfar(ray, args->N, i), &t))
      RTCRayN_tfar(ray, args->N, i) = -kInfinity;  // Embree's "occluded" marker
  }
}

void error_callback(void*, RTCError code, const char* str) {
  fmt::print(stderr, "embree error {}: {}\n", int(code), str ? str : "");
}

inline void fill_ray(const Ray& r, RTCRay* out) {
  out->org_x = r.o.x;
  out->org_y = r.o.y;
  out->org_z = r.o.z;
  out->dir_x = r.d.x;
  out->dir_y = r.d.y;
  out->dir_z = r.d.z;
  out->tnear = r.tmin;
  out->tfar = r.tmax;
  out->time = 0.f;
  out->mask = 0xffffffffu;
  out->id = 0;
  out->flags = 0;
}
}  // namespace

struct Accel::Impl {
  const Scene* scene = nullptr;
  const Point2* uvs = nullptr;   // per vertex, or nullptr
  const Vec3* normals = nullptr; // per vertex, or nullptr
  bool textured = false;         // uvs are only computed for scenes with textures (atan2/acos on spheres)
  RTCDevice device = nullptr;
  RTCScene rtc_scene = nullptr;

  ~Impl() {
    if (rtc_scene) rtcReleaseScene(rtc_scene);
    if (device) rtcReleaseDevice(device);
  }

  bool fill_hit(const Ray& ray, const RTCRayHit& rh, SurfaceHit* hit) const {
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit->t = rh.ray.tfar;
    hit->prim = rh.hit.primID;
    if (rh.hit.geomID == kTriangleGeometry) {
      const Triangle& tri = scene->triangles[rh.hit.primID];
      const Vec3 &p0 = scene->positions[tri.v[0]], &p1 = scene->positions[tri.v[1]], &p2 = scene->positions[tri.v[2]];
      const float u = rh.hit.u, v = rh.hit.v;
      hit->p = p0 * (1.f - u - v) + p1 * u + p2 * v;  // barycentric: more precise than o + t d
      hit->ng = triangle_normal(p0, p1, p2);
      hit->u = u;
      hit->v = v;
      hit->uv = textured ? triangle_uv(tri, uvs, u, v) : Point2{};
      hit->ns = triangle_shading_normal(tri, normals, u, v, hit->ng);
      hit->kind = ShapeKind::triangle;
      hit->material = tri.material;
      hit->light = tri.light;
    } else {
      const Sphere& s = scene->spheres[rh.hit.primID];
      const Vec3 p = ray.at(rh.ray.tfar);
      const Vec3 radial = normalize(p - s.center);
      hit->p = s.center + radial * s.radius;  // re-project onto the surface
      hit->ng = s.inward_normals ? -radial : radial;
      hit->u = hit->v = 0.f;
      hit->uv = textured ? sphere_uv(s, hit->p) : Point2{};
      hit->ns = hit->ng;
      hit->kind = ShapeKind::sphere;
      hit->material = s.material;
      hit->light = s.light;
    }
    return true;
  }
};

Accel::Accel(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = &scene;
  // Scene::finalize pads the vertex attributes to one per position; only then are they used.
  if (!scene.uvs.empty() && scene.uvs.size() == scene.positions.size()) impl_->uvs = scene.uvs.data();
  if (!scene.normals.empty() && scene.normals.size() == scene.positions.size()) impl_->normals = scene.normals.data();
  impl_->textured = !scene.textures.empty();
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw Error(fmt::format("cannot create an Embree device (error {})", int(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(impl_->device, error_callback, nullptr);
  impl_->rtc_scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->rtc_scene, RTC_BUILD_QUALITY_HIGH);

  // geomID 0: all triangles (an empty placeholder keeps the ids fixed).
  RTCGeometry tri_geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Copies, not shared buffers: Embree reads vertices with 16-byte loads past the last element,
  // which a std::vector<Vec3> does not guarantee to be padded for.
  auto* vertices = static_cast<Vec3*>(rtcSetNewGeometryBuffer(tri_geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              sizeof(Vec3), scene.positions.size()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(tri_geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), scene.triangles.size()));
  std::copy(scene.positions.begin(), scene.positions.end(), vertices);
  for (size_t i = 0; i < scene.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = scene.triangles[i].v[k];
  rtcCommitGeometry(tri_geom);
  rtcAttachGeometryByID(impl_->rtc_scene, tri_geom, kTriangleGeometry);
  rtcReleaseGeometry(tri_geom);

  RTCGeometry sph_geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(sph_geom, unsigned(scene.spheres.size()));
  rtcSetGeometryUserData(sph_geom, const_cast<Sphere*>(scene.spheres.data()));
  rtcSetGeometryBoundsFunction(sph_geom, sphere_bounds, nullptr);
  rtcSetGeometryIntersectFunction(sph_geom, sphere_intersect);
  rtcSetGeometryOccludedFunction(sph_geom, sphere_occluded);
  rtcCommitGeometry(sph_geom);
  rtcAttachGeometryByID(impl_->rtc_scene, sph_geom, kSphereGeometry);
  rtcReleaseGeometry(sph_geom);

  rtcCommitScene(impl_->rtc_scene);
  const RTCError err = rtcGetDeviceError(impl_->device);
  if (err != RTC_ERROR_NONE) throw Error(fmt::format("Embree failed to build the scene (error {})", int(err)));
}

Accel::~Accel() = default;

bool Accel::intersect(const Ray& ray, SurfaceHit* hit) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  fill_ray(ray, &rh.ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->rtc_scene, &ctx, &rh);
  return impl_->fill_hit(ray, rh, hit);
}

bool Accel::occluded(const Ray& ray) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r;
  fill_ray(ray, &r);
  rtcOccluded1(impl_->rtc_scene, &ctx, &r);
  return r.tfar < 0.f;
}

void Accel::intersect_batch(const Ray* rays, SurfaceHit* hits, bool* found, uint32_t count, bool coherent) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  std::vector<RTCRayHit> rh(count);
  for (uint32_t i = 0; i < count; ++i) {
    fill_ray(rays[i], &rh[i].ray);
    rh[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect1M(impl_->rtc_scene, &ctx, rh.data(), count, sizeof(RTCRayHit));
  for (uint32_t i = 0; i < count; ++i) found[i] = impl_->fill_hit(rays[i], rh[i], &hits[i]);
}

void Accel::occluded_batch(const Ray* rays, bool* blocked, uint32_t count) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  std::vector<RTCRay> r(count);
  for (uint32_t i = 0; i < count; ++i) fill_ray(rays[i], &r[i]);
  rtcOccluded1M(impl_->rtc_scene, &ctx, r.data(), count, sizeof(RTCRay));
  for (uint32_t i = 0; i < count; ++i) blocked[i] = r[i].tfar < 0.f;
}

}  // namespace pathspace
