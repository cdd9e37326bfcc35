// A rough conductor's reflectance factor (Material::tint: Mitsuba's specular_reflectance,
// Tungsten's albedo) scales eval and the sampled weight channel by channel and leaves the pdf and
// the sampled direction alone; a factor of 1 changes no bit.
#include <gtest/gtest.h>

#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {
namespace {

TEST(ConductorTint, ScalesEvalAndWeightNotThePdf) {
  Material plain = make_rough_conductor(0.2f, Rgb(0.2f, 0.92f, 1.1f), Rgb(3.9f, 2.45f, 2.14f));
  Material tinted = plain;
  tinted.tint = Rgb(0.3f, 0.5f, 0.7f);
  Material unit = plain;
  unit.tint = Rgb(1.f);
  Pcg32 rng(5, 1);
  int sampled = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 wo = square_to_cosine_hemisphere({rng.next_float(), rng.next_float()});
    const Vec3 wi = square_to_cosine_hemisphere({rng.next_float(), rng.next_float()});
    const Rgb f = bsdf_eval(plain, wo, wi, TransportMode::radiance), ft = bsdf_eval(tinted, wo, wi, TransportMode::radiance);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(ft[c], f[c] * tinted.tint[c]);
    EXPECT_EQ(bsdf_pdf(tinted, wo, wi, TransportMode::radiance), bsdf_pdf(plain, wo, wi, TransportMode::radiance));
    EXPECT_EQ(bsdf_eval(unit, wo, wi, TransportMode::radiance), f);
    const Point2 u{rng.next_float(), rng.next_float()};
    BsdfSample a, b;
    const bool oa = bsdf_sample(plain, wo, 0.5f, u, TransportMode::radiance, &a);
    const bool ob = bsdf_sample(tinted, wo, 0.5f, u, TransportMode::radiance, &b);
    ASSERT_EQ(oa, ob);
    if (!oa) continue;
    ++sampled;
    EXPECT_EQ(a.wi, b.wi);
    EXPECT_EQ(a.pdf_w, b.pdf_w);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(b.weight[c], a.weight[c] * tinted.tint[c]);
  }
  EXPECT_GT(sampled, 900);
}

}  // namespace
}  // namespace pathspace
