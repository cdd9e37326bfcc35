// Closed forms of the microfacet distributions (materials/microfacet_distribution.h), by numerical
// quadrature over the hemisphere of normals: the projected normal distribution integrates to one,
// int D(m) m.z dm = 1, and so does the visible-normal density for every view,
// int G1(w) max(0, w.m) D(m) / w.z dm = 1, which holds only with the exact Smith Lambda of the
// distribution. Also the erf inversion behind Beckmann's visible-slope sampling.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/materials/microfacet_distribution.h"

namespace pathspace {
namespace {

using microfacet::d;
using microfacet::visible_normal_pdf;

// Midpoint rule in (s, phi) with s = atan(tan(theta) / alpha) in [0, pi/2), i.e. theta spaced in
// tan(theta) / alpha, so that narrow lobes get as many points as wide ones and GGX's long tail is
// covered up to the horizon.
template <typename F>
double integrate_hemisphere(float alpha, F f) {
  const int nt = 3000, np = 256;
  double sum = 0.0;
  const double t_max = M_PI / 2;
  for (int i = 0; i < nt; ++i) {
    const double s = (i + 0.5) / nt * t_max;  // s = atan(tan(theta) / alpha)
    const double tan_theta = alpha * std::tan(s);
    const double theta = std::atan(tan_theta);
    // dtheta/ds = alpha sec^2(s) / (1 + alpha^2 tan^2 s)
    const double jac = alpha / (std::cos(s) * std::cos(s)) / (1.0 + tan_theta * tan_theta) * (t_max / nt);
    for (int j = 0; j < np; ++j) {
      const double phi = (j + 0.5) / np * 2.0 * M_PI;
      const Vec3 m(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
      sum += f(m) * std::sin(theta) * jac * (2.0 * M_PI / np);
    }
  }
  return sum;
}

TEST(MicrofacetDistribution, ProjectedBeckmannAreaIsOne) {
  for (const float alpha : {0.05f, 0.3f, 1.f}) {
    const double area = integrate_hemisphere(alpha, [&](const Vec3& m) { return d(m, alpha, MicrofacetDistribution::beckmann) * m.z; });
    EXPECT_NEAR(area, 1.0, 1e-3) << "alpha " << alpha;
  }
}

TEST(MicrofacetDistribution, VisibleNormalDensitiesIntegrateToOne) {
  for (const MicrofacetDistribution dist : {MicrofacetDistribution::beckmann, MicrofacetDistribution::ggx})
    for (const float alpha : {0.1f, 0.5f})
      for (const float cos_theta : {0.95f, 0.5f, 0.1f}) {
        const Vec3 w(std::sqrt(1.f - cos_theta * cos_theta), 0.f, cos_theta);
        const double total = integrate_hemisphere(alpha, [&](const Vec3& m) { return visible_normal_pdf(w, m, alpha, dist); });
        EXPECT_NEAR(total, 1.0, 1e-3)
            << (dist == MicrofacetDistribution::ggx ? "ggx" : "beckmann") << " alpha " << alpha << " cos " << cos_theta;
      }
}

TEST(MicrofacetDistribution, SampledBeckmannNormalsAreVisibleAndUpward) {
  for (const float cos_theta : {1.f, 0.5f, 0.02f, -0.5f})
    for (int i = 0; i < 200; ++i) {
      const Vec3 w(std::sqrt(std::max(0.f, 1.f - cos_theta * cos_theta)), 0.f, cos_theta);
      const Point2 u{(i % 20 + 0.5f) / 20.f, (i / 20 + 0.5f) / 10.f};
      const Vec3 m = microfacet::sample_visible_normal(w, 0.4f, MicrofacetDistribution::beckmann, u);
      ASSERT_GT(m.z, 0.f);
      ASSERT_NEAR(length(m), 1.f, 1e-5f);
      ASSERT_GT(dot(cos_theta < 0.f ? -w : w, m), -1e-4f) << "a normal facing away from the view";
    }
}

TEST(MicrofacetDistribution, ErfInverse) {
  for (const float y : {-0.999999f, -0.9f, -0.3f, 0.f, 1e-4f, 0.5f, 0.99f, 0.999999f}) {
    const float x = microfacet::detail::erf_inverse(y);
    EXPECT_NEAR(std::erf(double(x)), double(y), 2e-6) << y;
  }
}

}  // namespace
}  // namespace pathspace
