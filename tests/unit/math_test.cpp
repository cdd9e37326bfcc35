// Unit tests: vectors, frames, Fresnel identities.
#include <gtest/gtest.h>

#include "pathspace/materials/fresnel.h"
#include "pathspace/math/frame.h"

namespace pathspace {
namespace {

TEST(Vec3, CrossAndDot) {
  const Vec3 x(1, 0, 0), y(0, 1, 0);
  EXPECT_EQ(cross(x, y), Vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(dot(Vec3(1, 2, 3), Vec3(4, 5, 6)), 32.f);
  EXPECT_FLOAT_EQ(length(normalize(Vec3(3, -4, 12))), 1.f);
}

TEST(Frame, OrthonormalForManyNormals) {
  for (int i = 0; i < 1000; ++i) {
    const float z = -1.f + 2.f * (i + 0.5f) / 1000.f, phi = 2.399963f * i;
    const float r = std::sqrt(std::max(0.f, 1.f - z * z));
    const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
    const Frame f(n);
    EXPECT_NEAR(dot(f.s, f.t), 0.f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.f, 1e-5f);
    EXPECT_NEAR(length(f.s), 1.f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.f, 1e-5f);
    const Vec3 v(0.3f, -0.5f, 0.8f);
    const Vec3 back = f.to_world(f.to_local(v));
    EXPECT_NEAR(back.x, v.x, 1e-5f);
    EXPECT_NEAR(back.y, v.y, 1e-5f);
    EXPECT_NEAR(back.z, v.z, 1e-5f);
  }
}

TEST(Fresnel, NormalIncidenceAndTotalInternalReflection) {
  EXPECT_NEAR(fresnel_dielectric(1.f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(-1.f, 1.5f), 0.04f, 1e-6f);
  EXPECT_FLOAT_EQ(fresnel_dielectric(-0.1f, 1.6f), 1.f);  // inside, beyond the critical angle
  Vec3 wt;
  EXPECT_FALSE(refract_local(normalize(Vec3(0.99f, 0.f, -0.1f)), 1.6f, &wt));
  ASSERT_TRUE(refract_local(normalize(Vec3(0.5f, 0.f, 0.8f)), 1.6f, &wt));
  const Vec3 wi = normalize(Vec3(0.5f, 0.f, 0.8f));
  const float sin_i = std::sqrt(1 - wi.z * wi.z), sin_t = std::sqrt(1 - wt.z * wt.z);
  EXPECT_NEAR(sin_i, 1.6f * sin_t, 1e-5f);  // Snell
  EXPECT_LT(wt.z, 0.f);
}

}  // namespace
}  // namespace pathspace
