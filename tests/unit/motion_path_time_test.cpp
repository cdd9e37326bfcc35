// Every ray of a path carries the path's one time (scene/motion.h): a tracer that records the time
// of each ray it is asked for checks the kernels directly, path by path. PT traces at the camera
// path's time, LT at its light path's, BPT's light subpath at its camera path's time (so that every
// connection joins one instant), and the camera paths and photons of an SPPM pass, like the eye and
// light paths of a PCLT pass, share the pass's time.
#include <gtest/gtest.h>

#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/bpt/bpt_integrator.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/lt/lt_kernel.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/integrators/sppm/sppm_kernel.h"
#include "pathspace/scene/scene.h"

namespace pathspace {
namespace {

// Accel's answers, with the time of every ray asked.
struct TimeRecordingTracer {
  const Accel* accel;
  std::vector<float>* times;
  bool intersect(const Ray& r, SurfaceHit* hit) const {
    times->push_back(r.time);
    return accel->intersect(r, hit);
  }
  bool occluded(const Ray& r) const {
    times->push_back(r.time);
    return accel->occluded(r);
  }
};

// A closed white box with a ceiling light and a sliding diffuse block in it: long paths, every
// strategy used.
Scene moving_box() {
  Scene s;
  const uint32_t white = s.add_material(make_diffuse(Rgb(0.7f)));
  const float e = 1.f;
  const Vec3 c[8] = {{-e, -e, -e}, {e, -e, -e}, {e, e, -e}, {-e, e, -e}, {-e, -e, e}, {e, -e, e}, {e, e, e}, {-e, e, e}};
  // Inward-facing walls.
  s.add_quad(c[0], c[3], c[2], c[1], white);
  s.add_quad(c[4], c[5], c[6], c[7], white);
  s.add_quad(c[0], c[1], c[5], c[4], white);
  s.add_quad(c[2], c[3], c[7], c[6], white);
  s.add_quad(c[1], c[2], c[6], c[5], white);
  s.add_quad(c[0], c[4], c[7], c[3], white);
  s.add_quad(Vec3(-0.3f, -0.3f, 0.99f), Vec3(-0.3f, 0.3f, 0.99f), Vec3(0.3f, 0.3f, 0.99f), Vec3(0.3f, -0.3f, 0.99f), white, Rgb(5.f));
  s.add_quad(Vec3(-0.6f, -0.2f, 0.f), Vec3(-0.2f, -0.2f, 0.f), Vec3(-0.2f, 0.2f, 0.f), Vec3(-0.6f, 0.2f, 0.f), white);
  s.positions_end = s.positions;
  for (size_t i = s.positions.size() - 6; i < s.positions.size(); ++i) s.positions_end[i].x += 0.8f;
  s.camera = make_perspective_camera(Vec3(0.f, -0.9f, 0.f), Vec3(0, 1, 0), Vec3(0, 0, 1), 80.f, 8, 8);
  s.finalize();
  return s;
}

// The box, its accel and a recording tracer for each test.
class MotionPathTime : public ::testing::Test {
 protected:
  const Scene scene = moving_box();
  const SceneView v = scene.view();
  const Accel accel{scene};
  std::vector<float> times;
  const TimeRecordingTracer tracer{&accel, &times};
};

void expect_all(const std::vector<float>& times, float expected, const char* what) {
  ASSERT_FALSE(times.empty()) << what;
  for (float t : times) ASSERT_EQ(t, expected) << what << ": a ray of the path at another time";
}

TEST_F(MotionPathTime, PathTracingRaysShareTheCameraPathsTime) {
  for (uint32_t pixel = 0; pixel < 64; ++pixel) {
    times.clear();
    const Sampler sampler(7, pixel, 3);
    const float t = camera_path_time(v, sampler);
    PathCounters counters;
    pt_trace_path(v, tracer, sampler, sample_camera_ray(v.camera, sampler, pixel, t), PtSettings{}, &counters);
    expect_all(times, t, "pt");
  }
}

TEST_F(MotionPathTime, LightTracingRaysShareTheLightPathsTime) {
  SplatFilm splats(v.camera.width, v.camera.height);
  for (uint64_t path = 0; path < 64; ++path) {
    times.clear();
    const Sampler sampler(7, path, 3);
    PathCounters counters;
    lt_trace_path(v, tracer, sampler, LtSettings{}, 1.f / 64.f, splats.view(), &counters);
    if (!times.empty()) expect_all(times, light_path_time(v, sampler), "lt");
  }
}

TEST_F(MotionPathTime, BidirectionalSubpathsShareTheCameraPathsTime) {
  BptSettings settings;
  BptBuffers buffers(v.camera.width, v.camera.height, settings, v.max_path_segments);
  const BptFilms films = buffers.worker_films();
  for (uint32_t pixel = 0; pixel < 64; ++pixel) {
    times.clear();
    const Sampler cs(7, pixel, 3), ls(7, pixel, (uint64_t(1) << 63) | 3);
    PathCounters counters;
    bpt_trace_pixel(v, tracer, cs, ls, settings, pixel, films, &counters);
    expect_all(times, camera_path_time(v, cs), "bpt");
  }
}

TEST_F(MotionPathTime, PhotonsTakeTheTimeTheyAreGiven) {
  const float t = pass_time(v, 7, 3);
  EXPECT_NE(t, pass_time(v, 7, 4));
  for (uint64_t i = 0; i < 64; ++i) {
    PathCounters counters;
    sppm_walk_photon(v, tracer, Sampler(7, i, 3), SppmSettings{}, v.max_path_segments, t, &counters, [](const PhotonHit&) {});
  }
  expect_all(times, t, "sppm photons");
}

}  // namespace
}  // namespace pathspace
