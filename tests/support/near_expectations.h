// gtest expectations that colours and vectors are near each other, channel by channel (the tests
// that compare loaded or looked-up values with their closed forms).
#pragma once

#include <gtest/gtest.h>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace::testing {

inline void expect_rgb_near(const Rgb& a, const Rgb& b, float eps = 1e-5f) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], eps) << "channel " << c;
}

inline void expect_vec_near(const Vec3& a, const Vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace pathspace::testing
