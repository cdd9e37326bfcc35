// Embree 3 backend of Accel: one triangle geometry for all triangles and one user geometry for all
// analytic spheres (exact quadratic intersection in geometry/shapes.h, not Embree's tessellation-free
// "sphere points", so glass spheres are hit identically from inside and outside).
// A scene with moving parts (Scene::first_moving_triangle / first_moving_sphere), or any frame built
// after a previous one, is built in two levels: the static part and the moving part are two
// instanced Embree scenes, and the next frame's Accel reuses the static part when it is unchanged,
// so a frame rebuilds only the moving part and the two-instance top level (docs/animation.md). A
// frame in which nothing moves traces its static part directly, without the instance level.
// Cutouts (scene/surface_opacity.h) are tested in a context filter function, only in scenes that have
// them: the filter reads the current frame's materials through the query's context, so a reused
// static part needs no pointer into a frame that is gone.
#include <embree3/rtcore.h>
#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/accel/surface_hit_fill.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/surface_opacity.h"

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
    RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];  // the instance being traversed, if any
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

// What the cutout filter reads of the frame being rendered.
struct CutoutView {
  const Triangle* triangles = nullptr;
  const Material* materials = nullptr;
  const Point2* uvs = nullptr;
  const TextureView* textures = nullptr;
  uint32_t moving_triangle_offset = 0;  // primIDs of instance 1 (the moving part) start here
};

// A query's context: Embree's own first, so the filter can find the rest from the pointer it gets.
struct QueryContext {
  RTCIntersectContext rtc;
  const CutoutView* cutouts = nullptr;
};

// Rejects the candidate hits whose ray passes through a cutout; Embree then goes on traversing.
void cutout_filter(const RTCFilterFunctionNArguments* args) {
  const CutoutView& c = *reinterpret_cast<const QueryContext*>(args->context)->cutouts;
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] == 0 || RTCHitN_geomID(args->hit, n, i) != kTriangleGeometry) continue;
    const bool moving = RTCHitN_instID(args->hit, n, i, 0) == 1;
    const uint32_t prim = RTCHitN_primID(args->hit, n, i) + (moving ? c.moving_triangle_offset : 0);
    const Vec3 o(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i), RTCRayN_org_z(args->ray, n, i));
    const Vec3 d(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i), RTCRayN_dir_z(args->ray, n, i));
    if (ray_passes_cutout(c.triangles, c.materials, c.uvs, c.textures, prim, RTCHitN_u(args->hit, n, i),
                          RTCHitN_v(args->hit, n, i), o, d))
      args->valid[i] = 0;
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
  out->time = r.time;
  out->mask = 0xffffffffu;
  out->id = 0;
  out->flags = 0;
}

// Embree objects shared between the Accels of consecutive frames (instancing needs one device).
struct SharedDevice {
  RTCDevice device = nullptr;
  ~SharedDevice() {
    if (device) rtcReleaseDevice(device);
  }
};

// The geometry that does not move: its Embree scene and its own copy of the spheres it references
// (the user geometry keeps a pointer; the frame's Scene that was copied from goes away).
struct StaticPart {
  std::shared_ptr<SharedDevice> device;
  RTCScene scene = nullptr;
  std::vector<Sphere> spheres;
  uint32_t triangles = 0;
  uint64_t hash = 0;  // of the static triangles' vertices and indices and of the static spheres
  ~StaticPart() {
    if (scene) rtcReleaseScene(scene);
  }
};

// Embree picks the widest kernels the CPU has, and its AVX-512 kernels give hit distances that
// differ from its AVX2 kernels in the last bits: images would then depend on whether the CPU has
// AVX-512 (and the passes of a distributed render on such mixed machines would not add up to one
// process's image). Limited to AVX2, hits are the same on every x86-64 CPU with AVX2; on the
// development machine (AMD Zen 4) they are also faster: 0.967x the render time of a 640x360
// cornell-box frame (8 interleaved pairs; docs/animation.md). Checked by embree_kernels_test.cpp.
constexpr const char* kEmbreeDeviceConfig = "max_isa=avx2";

std::shared_ptr<SharedDevice> new_device() {
  auto d = std::make_shared<SharedDevice>();
  d->device = rtcNewDevice(kEmbreeDeviceConfig);
  if (!d->device) throw Error(fmt::format("cannot create an Embree device (error {})", int(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(d->device, error_callback, nullptr);
  return d;
}

// The vertices of triangles [begin, end): [first, last] (first > last: none).
struct VertexRange {
  uint32_t first = 0, last = 0;
  size_t count() const { return last >= first ? size_t(last - first) + 1 : 0; }
};
VertexRange vertex_range(const Scene& scene, uint32_t begin, uint32_t end) {
  if (begin >= end) return {1, 0};
  VertexRange r{UINT32_MAX, 0};
  for (uint32_t i = begin; i < end; ++i)
    for (uint32_t v : scene.triangles[i].v) r.first = std::min(r.first, v), r.last = std::max(r.last, v);
  return r;
}

// A fast hash of raw words (multiply and rotate): whether the static part changed between frames.
uint64_t hash_bytes(const void* data, size_t bytes, uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = std::rotl((h ^ w) * 0x9e3779b97f4a7c15ull, 29);
  }
  for (; i < bytes; ++i) h = std::rotl((h ^ p[i]) * 0x9e3779b97f4a7c15ull, 29);
  return h;
}

// An Embree scene of triangles [tri_begin, tri_end) of `scene` (geomID 0; their primIDs count from
// tri_begin) and `sphere_count` spheres (geomID 1). Empty geometries keep the ids fixed.
// `cutouts`: queries call the context's filter function (cutout_filter).
RTCScene build_part(RTCDevice device, const Scene& scene, uint32_t tri_begin, uint32_t tri_end, const Sphere* spheres,
                    uint32_t sphere_count, RTCBuildQuality quality, bool cutouts) {
  RTCScene part = rtcNewScene(device);
  if (cutouts) rtcSetSceneFlags(part, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(part, quality);
  RTCGeometry tri_geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Only the vertices the part's triangles use (a moving part is usually a short range at the end).
  const VertexRange range = vertex_range(scene, tri_begin, tri_end);
  // Copies, not shared buffers: Embree reads vertices with 16-byte loads past the last element,
  // which a std::vector<Vec3> does not guarantee to be padded for.
  auto* vertices = static_cast<Vec3*>(rtcSetNewGeometryBuffer(tri_geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              sizeof(Vec3), range.count()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(tri_geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), tri_end - tri_begin));
  std::copy(scene.positions.begin() + range.first, scene.positions.begin() + range.first + range.count(), vertices);
  if (!scene.positions_end.empty()) {
    // Motion blur (scene/motion.h): time step 1 holds the vertices at shutter close; Embree blends the
    // two linearly at each ray's time.
    if (scene.positions_end.size() != scene.positions.size())
      throw Error("motion blur: one end position per vertex is needed (Scene::finalize pads them)");
    rtcSetGeometryTimeStepCount(tri_geom, 2);
    auto* end = static_cast<Vec3*>(rtcSetNewGeometryBuffer(tri_geom, RTC_BUFFER_TYPE_VERTEX, 1, RTC_FORMAT_FLOAT3,
                                                           sizeof(Vec3), range.count()));
    std::copy(scene.positions_end.begin() + range.first, scene.positions_end.begin() + range.first + range.count(), end);
  }
  for (uint32_t i = tri_begin; i < tri_end; ++i)
    for (int k = 0; k < 3; ++k) indices[3 * (i - tri_begin) + k] = scene.triangles[i].v[k] - range.first;
  rtcCommitGeometry(tri_geom);
  rtcAttachGeometryByID(part, tri_geom, kTriangleGeometry);
  rtcReleaseGeometry(tri_geom);

  RTCGeometry sph_geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(sph_geom, sphere_count);
  rtcSetGeometryUserData(sph_geom, const_cast<Sphere*>(spheres));
  rtcSetGeometryBoundsFunction(sph_geom, sphere_bounds, nullptr);
  rtcSetGeometryIntersectFunction(sph_geom, sphere_intersect);
  rtcSetGeometryOccludedFunction(sph_geom, sphere_occluded);
  rtcCommitGeometry(sph_geom);
  rtcAttachGeometryByID(part, sph_geom, kSphereGeometry);
  rtcReleaseGeometry(sph_geom);
  rtcCommitScene(part);
  return part;
}

// The static part as Embree sees it: its triangles' vertex indices, the vertices they use, and the
// spheres' centres and radii (field by field: padding bytes are not part of a value).
uint64_t static_hash(const Scene& scene, uint32_t triangles, uint32_t spheres, bool cutouts) {
  uint64_t h = 0x243f6a8885a308d3ull ^ uint64_t(cutouts);  // the part's scene flags depend on it
  h = hash_bytes(scene.triangles.data(), triangles * sizeof(Triangle), h);  // no padding: five 32-bit fields
  const VertexRange range = vertex_range(scene, 0, triangles);
  if (range.count() > 0) h = hash_bytes(&scene.positions[range.first], range.count() * sizeof(Vec3), h);
  if (range.count() > 0 && !scene.positions_end.empty())
    h = hash_bytes(&scene.positions_end[range.first], range.count() * sizeof(Vec3), h);
  for (uint32_t i = 0; i < spheres; ++i) {
    const Sphere& s = scene.spheres[i];
    h = hash_bytes(&s.center, sizeof s.center, h);
    h = hash_bytes(&s.radius, sizeof s.radius, h);
  }
  return h;
}

// What Scene::view() sets of the fields surface_hit_fill.h reads; Scene::finalize pads the vertex
// attributes to one per position, only then are they used.
SceneView geometry_view(const Scene& scene) {
  SceneView v;
  v.positions = scene.positions.data();
  v.uvs = !scene.uvs.empty() && scene.uvs.size() == scene.positions.size() ? scene.uvs.data() : nullptr;
  v.normals = !scene.normals.empty() && scene.normals.size() == scene.positions.size() ? scene.normals.data() : nullptr;
  v.positions_end = scene.positions_end.size() == scene.positions.size() && !scene.positions_end.empty() ? scene.positions_end.data() : nullptr;
  v.normals_end = v.positions_end && v.normals && scene.normals_end.size() == scene.normals.size() ? scene.normals_end.data() : nullptr;
  v.triangles = scene.triangles.data();
  v.num_triangles = uint32_t(scene.triangles.size());
  v.spheres = scene.spheres.data();
  v.num_spheres = uint32_t(scene.spheres.size());
  v.num_textures = uint32_t(scene.textures.size());  // Scene::view() has one TextureView per texture
  return v;
}
}  // namespace

struct Accel::Impl {
  // The scene's geometry as accel/surface_hit_fill.h reads it (positions, uvs, normals, triangles,
  // spheres, num_textures); the rest of the view is not set (Scene::view() needs a finalised scene).
  SceneView geometry;
  // Set when the scene has cutouts (queries then install cutout_filter); its textures point here.
  bool cutouts = false;
  CutoutView cutout_view;
  std::vector<TextureView> textures;
  std::shared_ptr<SharedDevice> device;
  RTCScene rtc_scene = nullptr;  // the whole scene, or the top level of the two parts
  // Two levels (moving parts): instance 0 is the static part, instance 1 the moving part, whose
  // primIDs start at these offsets in the scene's arrays.
  std::shared_ptr<StaticPart> static_part;
  uint32_t moving_triangle_offset = 0, moving_sphere_offset = 0;
  bool reused = false;

  ~Impl() {
    if (rtc_scene) rtcReleaseScene(rtc_scene);
  }

  bool fill_hit(const Ray& ray, const RTCRayHit& rh, SurfaceHit* hit) const {
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    const bool moving = rh.hit.instID[0] == 1;
    const uint32_t prim = rh.hit.primID + (moving ? (rh.hit.geomID == kTriangleGeometry ? moving_triangle_offset : moving_sphere_offset) : 0);
    const ShapeKind kind = rh.hit.geomID == kTriangleGeometry ? ShapeKind::triangle : ShapeKind::sphere;
    fill_surface_hit(geometry, kind, prim, rh.ray.tfar, rh.hit.u, rh.hit.v, ray, hit);
    return true;
  }

  // The context of one query: with the cutout filter when the scene has cutouts.
  QueryContext context(RTCIntersectContextFlags flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT) const {
    QueryContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.rtc.flags = flags;
    if (cutouts) {
      ctx.rtc.filter = cutout_filter;
      ctx.cutouts = &cutout_view;
    }
    return ctx;
  }

  // The moving part (triangles and spheres from the static counts on) and the top level of two
  // instances above it and the static part, which must be set.
  void build_two_levels(RTCDevice device, const Scene& scene, uint32_t static_triangles, uint32_t static_spheres) {
    const uint32_t triangles = uint32_t(scene.triangles.size()), spheres = uint32_t(scene.spheres.size());
    RTCScene moving = build_part(device, scene, static_triangles, triangles, scene.spheres.data() + static_spheres,
                                 spheres - static_spheres, RTC_BUILD_QUALITY_MEDIUM, cutouts);
    rtc_scene = rtcNewScene(device);
    if (cutouts) rtcSetSceneFlags(rtc_scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    const float identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};  // 3x4, column major
    for (const auto& [id, part] : {std::pair{0u, static_part->scene}, std::pair{1u, moving}}) {
      RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(instance, part);
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, identity);
      rtcCommitGeometry(instance);
      rtcAttachGeometryByID(rtc_scene, instance, id);
      rtcReleaseGeometry(instance);
    }
    rtcReleaseScene(moving);  // the instance holds it
    rtcCommitScene(rtc_scene);
  }
};

Accel::Accel(const Scene& scene, const Accel* previous) : impl_(std::make_unique<Impl>()) {
  impl_->geometry = geometry_view(scene);
  const bool cutouts = scene.any_cutout_triangle();
  impl_->cutouts = cutouts;
  if (cutouts) {
    for (const ImageTexture& t : scene.textures) impl_->textures.push_back(t.view());
    impl_->cutout_view = {scene.triangles.data(), scene.materials.data(), impl_->geometry.uvs, impl_->textures.data(), 0};
  }
  const uint32_t triangles = uint32_t(scene.triangles.size()), spheres = uint32_t(scene.spheres.size());
  // Frames of an animation (a previous frame given) are built in two levels even when nothing moves
  // (a camera moving through a still scene): their static part is then all of it, reused as it is.
  const bool two_level = previous || scene.first_moving_triangle < triangles || scene.first_moving_sphere < spheres;
  const Impl* before = previous ? previous->impl_.get() : nullptr;
  impl_->device = before && before->static_part ? before->device : new_device();
  const RTCDevice device = impl_->device->device;
  if (!two_level) {
    // geomID 0: all triangles, 1: all spheres.
    impl_->rtc_scene = build_part(device, scene, 0, triangles, scene.spheres.data(), spheres, RTC_BUILD_QUALITY_HIGH, cutouts);
  } else {
    const uint32_t static_triangles = std::min(scene.first_moving_triangle, triangles);
    const uint32_t static_spheres = std::min(scene.first_moving_sphere, spheres);
    const uint64_t hash = static_hash(scene, static_triangles, static_spheres, cutouts);
    const std::shared_ptr<StaticPart>& old = before ? before->static_part : nullptr;
    if (old && old->triangles == static_triangles && old->spheres.size() == static_spheres && old->hash == hash) {
      impl_->static_part = old;  // unchanged: reused as it is
      impl_->reused = true;
    } else {
      auto part = std::make_shared<StaticPart>();
      part->device = impl_->device;
      part->spheres.assign(scene.spheres.begin(), scene.spheres.begin() + static_spheres);
      part->triangles = static_triangles;
      part->hash = hash;
      part->scene = build_part(device, scene, 0, static_triangles, part->spheres.data(), static_spheres, RTC_BUILD_QUALITY_HIGH,
                               cutouts);
      impl_->static_part = std::move(part);
    }
    impl_->moving_triangle_offset = static_triangles;
    impl_->cutout_view.moving_triangle_offset = static_triangles;
    impl_->moving_sphere_offset = static_spheres;
    if (static_triangles == triangles && static_spheres == spheres) {
      // Nothing moves: the static part is the whole scene and is traced as it is. An instance level
      // above it would cost every ray a second traversal (its hits would be the same).
      impl_->rtc_scene = impl_->static_part->scene;
      rtcRetainScene(impl_->rtc_scene);
    } else {
      impl_->build_two_levels(device, scene, static_triangles, static_spheres);
    }
  }
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE) throw Error(fmt::format("Embree failed to build the scene (error {})", int(err)));
}

Accel::~Accel() = default;

bool Accel::reused_static_part() const { return impl_->reused; }

namespace {
// Embree's nearest-hit query of one ray (Accel::intersect fills a SurfaceHit from it).
RTCRayHit nearest_hit(RTCScene scene, QueryContext ctx, const Ray& ray) {
  RTCRayHit rh;
  fill_ray(ray, &rh.ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx.rtc, &rh);
  return rh;
}
}  // namespace

bool Accel::intersect(const Ray& ray, SurfaceHit* hit) const {
  return impl_->fill_hit(ray, nearest_hit(impl_->rtc_scene, impl_->context(), ray), hit);
}

bool Accel::occluded(const Ray& ray) const {
  QueryContext ctx = impl_->context();
  RTCRay r;
  fill_ray(ray, &r);
  rtcOccluded1(impl_->rtc_scene, &ctx.rtc, &r);
  return r.tfar < 0.f;
}

float Accel::hit_distance(const Ray& ray) const {
  const RTCRayHit rh = nearest_hit(impl_->rtc_scene, impl_->context(), ray);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
}

void Accel::intersect_batch(const Ray* rays, SurfaceHit* hits, bool* found, uint32_t count, bool coherent) const {
  QueryContext ctx = impl_->context(coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
  constexpr uint32_t kStream = 64;  // rays per Embree stream: on the stack, no allocation per call
  RTCRayHit rh[kStream];
  for (uint32_t first = 0; first < count; first += kStream) {
    const uint32_t n = std::min(kStream, count - first);
    for (uint32_t i = 0; i < n; ++i) {
      fill_ray(rays[first + i], &rh[i].ray);
      rh[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect1M(impl_->rtc_scene, &ctx.rtc, rh, n, sizeof(RTCRayHit));
    for (uint32_t i = 0; i < n; ++i) found[first + i] = impl_->fill_hit(rays[first + i], rh[i], &hits[first + i]);
  }
}

void Accel::occluded_batch(const Ray* rays, bool* blocked, uint32_t count) const {
  QueryContext ctx = impl_->context();
  std::vector<RTCRay> r(count);
  for (uint32_t i = 0; i < count; ++i) fill_ray(rays[i], &r[i]);
  rtcOccluded1M(impl_->rtc_scene, &ctx.rtc, r.data(), count, sizeof(RTCRay));
  for (uint32_t i = 0; i < count; ++i) blocked[i] = r[i].tfar < 0.f;
}

}  // namespace pathspace
