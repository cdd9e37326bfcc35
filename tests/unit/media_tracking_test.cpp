// Distance sampling and transmittance in media (media/free_flight.h, media/majorant_walk.h) against
// closed forms and quadrature:
//  - homogeneous transmittance is exp(-sigma_t d) per channel, exactly;
//  - the majorant walk covers the ray's part inside the box with contiguous segments whose bound
//    holds at every point of them;
//  - a grid's ratio-tracking transmittance and the free flight's "passed" weight estimate the
//    transmittance from quadrature of the trilinear field, and the free flight's scattering weight
//    estimates the integral of sigma_s T over an interval, and so do the camera-side branches'
//    scatter and pass weights (t-tests, alpha = 0.01 Sidak-corrected
//    over the file's kTests tests), for chromatic homogeneous media and a chromatic grid.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/media/free_flight.h"
#include "pathspace/scene/scene_media.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kTests = 60;
const double kAlpha = testing::sidak(0.01, kTests);

// A 5x4x3 grid with 3 channels of varying values, over the box [-1, 2] x [0, 1] x [0, 2].
SceneMedia grid_scene() {
  SceneMedia m;
  GridMediumDesc d;
  d.nx = 5;
  d.ny = 4;
  d.nz = 3;
  d.channels = 3;
  for (uint32_t i = 0; i < d.nx * d.ny * d.nz; ++i) {
    d.density.push_back(0.2f + float(i % 7) * 0.4f);
    d.density.push_back(float((i * 3) % 5) * 0.5f);
    d.density.push_back(1.f + float(i % 2));
  }
  d.sigma_t_scale = Rgb(1.5f, 1.f, 0.5f);
  d.albedo = Rgb(0.8f, 0.5f, 0.9f);
  const float w[12] = {1.f / 3.f, 0.f, 0.f, 1.f / 3.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 0.5f, 0.f};
  std::copy(std::begin(w), std::end(w), d.world_to_grid);
  m.add_grid(d);
  m.add_homogeneous(Rgb(0.3f, 0.1f, 0.6f), Rgb(0.5f, 1.2f, 0.2f), 0.f);
  return m;
}

const Ray kRay{Vec3(-1.5f, 0.2f, 0.3f), normalize(Vec3(1.f, 0.25f, 0.5f)), 0.f, kInfinity, 0.f};

// Midpoint quadrature of the optical depth of the field along `ray` over [a, b].
Rgb optical_depth(const Medium& m, const float* values, const Ray& ray, float a, float b, int n = 20000) {
  Rgb tau;
  const float h = (b - a) / float(n);
  for (int i = 0; i < n; ++i) tau += medium_sigma_t(m, values, grid_point(m, ray.at(a + (float(i) + 0.5f) * h))) * h;
  return tau;
}

// The integral over [a, b) of sigma_s(t) T(t) dt along kRay (midpoint rule): what a flight's
// scattering weight estimates over that interval.
Rgb scatter_integral(const Medium& med, const float* values, float a, float b) {
  constexpr int n = 4000;
  const float h = (b - a) / float(n);
  Rgb tau = optical_depth(med, values, kRay, 0.f, a), scatter;
  for (int i = 0; i < n; ++i) {
    const float t = a + (float(i) + 0.5f) * h;
    const Vec3 gp = grid_point(med, kRay.at(t));
    const Rgb st = medium_sigma_t(med, values, gp);
    const Rgb tr = Rgb(std::exp(-(tau.r + st.r * h / 2)), std::exp(-(tau.g + st.g * h / 2)), std::exp(-(tau.b + st.b * h / 2)));
    scatter += medium_albedo(med, values, gp) * st * tr * h;
    tau += st * h;
  }
  return scatter;
}

void expect_mean(const std::vector<double>& x, double expected, const char* what) {
  double s = 0, s2 = 0;
  for (double v : x) {
    s += v;
    s2 += v * v;
  }
  const testing::MeanTest t = testing::t_test_mean(s, s2, double(x.size()), expected);
  if (t.std_error < 1e-6 * expected) {  // an exact estimator (homogeneous): the float quadrature's error
    EXPECT_NEAR(t.mean, expected, 1e-3 * expected) << what;
    return;
  }
  EXPECT_GT(t.p, kAlpha) << what << ": mean " << t.mean << " +- " << t.std_error << " expected " << expected;
}

TEST(MediaTracking, HomogeneousTransmittanceIsBeerLambert) {
  const SceneMedia m = grid_scene();
  const MediaView v = m.view();
  Pcg32 rng;
  const Rgb tr = medium_transmittance(v, 1, kRay, 2.5f, rng);
  const Rgb st = m.media[1].sigma_t;
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(tr[c], std::exp(-st[c] * 2.5f)) << c;
  const Rgb inf = medium_transmittance(v, 1, kRay, kInfinity, rng);
  EXPECT_TRUE(is_black(inf));
}

TEST(MediaTracking, MajorantWalkCoversTheBoxAndBoundsTheField) {
  const SceneMedia m = grid_scene();
  const Medium& g = m.media[0];
  const float* values = m.grid_values.data();
  MajorantWalk walk(g, values, kRay, 100.f);
  MajorantSegment seg;
  float last = -1.f, first = -1.f;
  int segments = 0;
  Pcg32 rng(3, 4);
  while (walk.next(&seg)) {
    if (last >= 0.f) {
      EXPECT_FLOAT_EQ(seg.t0, last);
    } else {
      first = seg.t0;
    }
    EXPECT_LE(seg.t0, seg.t1);
    for (int k = 0; k < 50; ++k) {
      const float t = seg.t0 + (seg.t1 - seg.t0) * rng.next_float();
      EXPECT_LE(max_component(medium_sigma_t(g, values, grid_point(g, kRay.at(t)))), seg.sigma * (1.f + 1e-5f)) << "t " << t;
    }
    last = seg.t1;
    ++segments;
  }
  EXPECT_GT(segments, 3);
  // The ray enters the box at x = -1 and leaves it where it first reaches a face (y = 1).
  EXPECT_NEAR(first, 0.5f / kRay.d.x, 1e-4f);
  EXPECT_NEAR(last, std::fmin(std::fmin(3.5f / kRay.d.x, 0.8f / kRay.d.y), 1.7f / kRay.d.z), 1e-4f);
}

// 0: the grid, 1: homogeneous; 2, 3: the same with a chromatic path throughput (the channels'
// shares of the sampling, media/free_flight.h).
class MediaEstimators : public ::testing::TestWithParam<int> {
 protected:
  const SceneMedia m = grid_scene();
  const MediaView v = m.view();
  const int medium = GetParam() % 2;
  const Rgb throughput = GetParam() < 2 ? Rgb(1.f) : Rgb(0.2f, 1.5f, 0.05f);
  const Medium& med = m.media[size_t(medium)];
  const float* values = m.grid_values.data();
  // The segment's end, and the interval over which the scattering weights are checked.
  const float tmax = 3.f, a = 0.8f, b = 1.9f;
};

TEST_P(MediaEstimators, TransmittanceIsUnbiased) {
  const Rgb tau = optical_depth(med, values, kRay, 0.f, tmax);
  Pcg32 rng(11, uint64_t(medium));
  std::vector<double> x[3];
  for (int i = 0; i < 200000; ++i) {
    const Rgb t = medium_transmittance(v, medium, kRay, tmax, rng);
    for (int c = 0; c < 3; ++c) x[c].push_back(t[c]);
  }
  for (int c = 0; c < 3; ++c) expect_mean(x[c], std::exp(-double(tau[c])), "transmittance");
}

TEST_P(MediaEstimators, FreeFlightPassAndScatterWeightsAreUnbiased) {
  // Expected: T(tmax), and the integral over [a, b] of sigma_s(t) T(t) dt (midpoint rule).
  const Rgb pass = [&] {
    const Rgb tau = optical_depth(med, values, kRay, 0.f, tmax);
    return Rgb(std::exp(-tau.r), std::exp(-tau.g), std::exp(-tau.b));
  }();
  const Rgb scatter = scatter_integral(med, values, a, b);
  Pcg32 rng(23, uint64_t(medium));
  std::vector<double> xp[3], xs[3];
  for (int i = 0; i < 400000; ++i) {
    const FreeFlight f = sample_free_flight(v, medium, kRay, tmax, throughput, rng);
    const bool passed = f.event == MediumEvent::passed;
    const bool in = f.event == MediumEvent::scattered && f.t >= a && f.t < b;
    for (int c = 0; c < 3; ++c) {
      xp[c].push_back(passed ? f.weight[c] : 0.0);
      xs[c].push_back(in ? f.weight[c] : 0.0);
    }
  }
  for (int c = 0; c < 3; ++c) {
    expect_mean(xp[c], pass[c], "passed");
    expect_mean(xs[c], scatter[c], "scattered in [a, b)");
  }
}

// Camera-side branches (free_flight.h): the scatter branch's weight over [a, b) and the pass branch's
// weight estimate what the free flight's two outcomes do; a homogeneous scatter branch always collides.
TEST_P(MediaEstimators, BranchWeightsAreUnbiased) {
  const Rgb tau_max = optical_depth(med, values, kRay, 0.f, tmax);
  const Rgb scatter = scatter_integral(med, values, a, b);
  Pcg32 rng(29, uint64_t(medium));
  std::vector<double> xp[3], xs[3];
  int passed = 0, missed = 0;  // scatter branches that passed; that did not collide before tmax
  for (int i = 0; i < 400000; ++i) {
    const FreeFlight s = sample_scatter_branch(v, medium, kRay, tmax, throughput, rng);
    const FreeFlight p = sample_pass_branch(v, medium, kRay, tmax, rng);
    passed += s.event == MediumEvent::passed ? 1 : 0;
    missed += s.event == MediumEvent::scattered && s.t < tmax ? 0 : 1;
    const bool in = s.event == MediumEvent::scattered && s.t >= a && s.t < b;
    for (int c = 0; c < 3; ++c) {
      xs[c].push_back(in ? s.weight[c] : 0.0);
      xp[c].push_back(p.event == MediumEvent::passed ? p.weight[c] : 0.0);
    }
  }
  EXPECT_EQ(passed, 0) << "a scatter branch never passes";
  for (int c = 0; c < 3; ++c) {
    expect_mean(xp[c], std::exp(-double(tau_max[c])), "pass branch");
    expect_mean(xs[c], scatter[c], "scatter branch in [a, b)");
  }
  if (medium == 1) {
    EXPECT_EQ(missed, 0) << "a homogeneous scatter branch always collides before tmax";
  }
}

INSTANTIATE_TEST_SUITE_P(GridAndHomogeneous, MediaEstimators, ::testing::Values(0, 1, 2, 3));

TEST(SceneMediaChecks, RejectBadValues) {
  SceneMedia m;
  EXPECT_THROW(m.add_homogeneous(Rgb(-1.f), Rgb(1.f), 0.f), Error);
  EXPECT_THROW(m.add_homogeneous(Rgb(1.f), Rgb(NAN), 0.f), Error);
  EXPECT_THROW(m.add_homogeneous(Rgb(1.f), Rgb(1.f), 1.f), Error);
  GridMediumDesc d;
  d.nx = d.ny = d.nz = 2;
  d.density.assign(7, 1.f);
  EXPECT_THROW(m.add_grid(d), Error);  // 7 values for 8 samples
  d.density.assign(8, 1.f);
  d.density[3] = -0.5f;
  EXPECT_THROW(m.add_grid(d), Error);
  d.density[3] = 0.5f;
  EXPECT_NO_THROW(m.add_grid(d));
  m.bind_triangle(4, make_medium_interface(0, 3));  // medium 3 does not exist
  EXPECT_THROW(m.finalize(5, 0, 0), Error);
  m.triangle_interfaces.clear();
  m.bind_light(0, 0);
  EXPECT_THROW(m.finalize(5, 0, 0), Error);  // a light the scene does not have
}

}  // namespace
}  // namespace pathspace
