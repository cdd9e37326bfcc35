// Statistical tests of BSDF sampling (docs/testing.md, Method: chi-square): a chi-square test of the sampled
// directions against bsdf_pdf for every material at several incident directions (grazing and,
// for the rough dielectric, from inside), and for every sample: weight == f |cos| / pdf,
// bsdf_pdf(sampled wi) == returned pdf, consistent lobe flags and eta. Delta lobes are checked by
// their discrete probabilities (extra chi-square cells) and exact directions; the layered BSDFs'
// exact mixture density (materials/layered_bsdf.h) likewise. Also reciprocity,
// the adjoint relation of transmission, and the albedo of a white rough conductor.
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests chi-square tests
// (each incident direction of each material is one test).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "pathspace/materials/bsdf.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kChi2Tests = 79;
const double kAlpha = testing::sidak(0.01, kChi2Tests);
constexpr float kRelTolerance = 1e-3f;

Vec3 incident(float cos_theta, float phi = 0.7f) {
  const float s = safe_sqrt(1.f - cos_theta * cos_theta);
  return {s * cosf(phi), s * sinf(phi), cos_theta};
}

bool close(float a, float b, float rel = kRelTolerance, float abs = 1e-20f) {
  return fabsf(a - b) <= rel * fmaxf(fabsf(a), fabsf(b)) + abs;
}
bool close(const Rgb& a, const Rgb& b, float rel = kRelTolerance, float abs = 1e-20f) {
  return close(a.r, b.r, rel, abs) && close(a.g, b.g, rel, abs) && close(a.b, b.b, rel, abs);
}
std::string str(float x, float y, float z) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.7g, %.7g, %.7g)", x, y, z);
  return buf;
}
std::string str(const Vec3& v) { return str(v.x, v.y, v.z); }
std::string str(const Rgb& c) { return str(c.r, c.g, c.b); }

// Per-sample consistency checks; counts violations and keeps the first message.
struct Checks {
  uint64_t failures = 0;
  std::string first;
  template <class Message>  // a callable: the message is built for the first failure only
  void fail(Message message) {
    if (failures++ == 0) first = message();
  }
};

// Draws one sample and checks it. Non-delta samples become continuous outcomes; a delta lobe is
// discrete outcome 1 (reflection) or 2 (transmission) after its direction was checked.
testing::Outcome sample_and_check(const Material& m, const Vec3& wo, TransportMode mode, Pcg32& rng, Checks& c) {
  const float u_lobe = rng.next_float();
  const Point2 u{rng.next_float(), rng.next_float()};
  BsdfSample s;
  if (!bsdf_sample(m, wo, u_lobe, u, mode, &s)) return {};
  const bool transmit = s.wi.z * wo.z < 0.f;
  const auto where = [&] { return "wo " + str(wo) + " wi " + str(s.wi) + ": "; };
  if (!(s.pdf_w > 0.f) || !all_finite(s.weight) || !close(length(s.wi), 1.f))
    c.fail([&] { return where() + "bad pdf, weight or length"; });
  if (bool(s.lobe & kLobeTransmission) != transmit || bool(s.lobe & kLobeReflection) == transmit)
    c.fail([&] { return where() + "lobe flags disagree with the sides of wo and wi"; });
  const float ior = m.ior > 0.f ? m.ior : 1.f;
  const float expected_eta = transmit ? (wo.z > 0.f ? ior : 1.f / ior) : 1.f;
  if (!close(s.eta, expected_eta)) c.fail([&] { return where() + "eta " + std::to_string(s.eta); });
  if (s.delta) {
    if (!(s.lobe & kLobeSpecular)) c.fail([&] { return where() + "delta sample without the specular flag"; });
    Vec3 expected_wi(-wo.x, -wo.y, wo.z);
    if (transmit && !refract_local(wo, m.ior, &expected_wi))
      c.fail([&] { return where() + "transmission under total internal reflection"; });
    if (!close(dot(expected_wi, s.wi), 1.f, 1e-6f))
      c.fail([&] { return where() + "delta direction, expected " + str(expected_wi); });
    return {transmit ? 2 : 1, 0, 0, {}};
  }
  const float pdf = bsdf_pdf(m, wo, s.wi, mode);
  if (!close(pdf, s.pdf_w))
    c.fail([&] { return where() + "pdf " + std::to_string(s.pdf_w) + " != bsdf_pdf " + std::to_string(pdf); });
  const Rgb expected_weight = bsdf_eval(m, wo, s.wi, mode) * (fabsf(s.wi.z) / s.pdf_w);
  if (!close(s.weight, expected_weight))
    c.fail([&] { return where() + "weight " + str(s.weight) + " != f cos / pdf " + str(expected_weight); });
  return {0, 0, 0, s.wi};
}

// Chi-square of one material at one incident direction, plus the per-sample checks.
// `discrete` lists the probabilities of delta reflection and transmission (empty: none).
void check_sampling(const std::string& name, const Material& m, const Vec3& wo, std::vector<double> discrete = {},
                    TransportMode mode = TransportMode::radiance, uint64_t samples = 1000000) {
  SCOPED_TRACE(name + " wo " + str(wo));
  static uint64_t seed = 0;
  testing::Chi2Options o;
  o.samples = samples;
  o.seed = ++seed;
  o.alpha = kAlpha;
  o.name = name;
  if (!discrete.empty()) discrete.insert(discrete.begin(), 0.0);
  o.discrete = discrete;
  Checks checks;
  const auto r = testing::direction_chi2(
      {}, [&](Pcg32& rng) { return sample_and_check(m, wo, mode, rng, checks); },
      [&](const Vec3& wi) { return double(bsdf_pdf(m, wo, wi, mode)); }, o);
  std::printf("%s wo.z %.3f: chi2 %.1f dof %.0f p %.4f\n", name.c_str(), wo.z, r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " < " << kAlpha
                                << " " << r.error << "; evidence: " << r.evidence;
  EXPECT_EQ(checks.failures, 0u) << checks.first;
}

TEST(BsdfChi2, Lambert) {
  const Material m = make_diffuse(Rgb(0.8f, 0.5f, 0.2f));
  for (const float c : {0.7f, 0.05f}) check_sampling("lambert", m, incident(c));  // 2 tests
}

TEST(BsdfChi2, Phong) {
  for (const float n : {1.f, 10.f, 100.f}) {  // 6 tests
    const Material m = make_phong(Rgb(0.f), Rgb(0.7f), n);
    for (const float c : {0.7f, 0.05f}) check_sampling("phong_" + std::to_string(int(n)), m, incident(c));
  }
}

TEST(BsdfChi2, DiffusePlusPhong) {
  const Material m = make_phong(Rgb(0.3f, 0.2f, 0.1f), Rgb(0.4f), 20.f);
  for (const float c : {0.9f, 0.3f, 0.05f}) check_sampling("diffuse_phong", m, incident(c));  // 3 tests
}

TEST(BsdfChi2, RoughConductor) {
  for (const float alpha : {0.05f, 0.3f, 0.8f}) {  // 9 tests
    const Material m = make_rough_conductor(alpha, Rgb(0.2f, 0.9f, 1.1f), Rgb(3.9f, 2.4f, 2.2f));
    for (const float c : {0.95f, 0.5f, 0.05f})
      check_sampling("rough_conductor_" + std::to_string(alpha), m, incident(c));
  }
}

Material beckmann(Material m) {
  m.distribution = MicrofacetDistribution::beckmann;
  return m;
}

TEST(BsdfChi2, BeckmannRoughConductor) {
  for (const float alpha : {0.05f, 0.3f, 0.8f}) {  // 9 tests
    const Material m = beckmann(make_rough_conductor(alpha, Rgb(0.2f, 0.9f, 1.1f), Rgb(3.9f, 2.4f, 2.2f)));
    for (const float c : {0.95f, 0.5f, 0.05f})
      check_sampling("beckmann_rough_conductor_" + std::to_string(alpha), m, incident(c));
  }
}

TEST(BsdfChi2, BeckmannRoughDielectric) {
  for (const float alpha : {0.1f, 0.5f}) {  // 10 tests
    const Material m = beckmann(make_rough_dielectric(alpha, 1.5f));
    for (const float c : {0.8f, 0.4f, 0.05f, -0.6f, -0.05f})
      check_sampling("beckmann_rough_dielectric_" + std::to_string(alpha), m, incident(c));
  }
}

void check_rough_dielectric(float ior) {
  for (const float alpha : {0.1f, 0.5f}) {  // 2 x 5 tests per ior
    const Material m = make_rough_dielectric(alpha, ior);
    // Outside (near normal, oblique, grazing) and inside the glass (oblique, grazing).
    for (const float c : {0.8f, 0.4f, 0.05f, -0.6f, -0.05f})
      check_sampling("rough_dielectric_" + std::to_string(alpha) + "_" + std::to_string(ior), m, incident(c));
  }
}
TEST(BsdfChi2, RoughDielectricDenserInside) { check_rough_dielectric(1.5f); }
TEST(BsdfChi2, RoughDielectricDenserOutside) { check_rough_dielectric(1.f / 1.5f); }

TEST(BsdfChi2, RoughDielectricImportance) {
  const Material m = make_rough_dielectric(0.3f, 1.5f);
  for (const float c : {0.6f, -0.6f})  // 2 tests
    check_sampling("rough_dielectric_importance", m, incident(c), {}, TransportMode::importance);
}

// Delta lobes: the chi-square sees the discrete lobe probabilities as extra cells.
TEST(BsdfChi2, DiffusePlusMirror) {
  Material m = make_diffuse(Rgb(0.4f));
  m.specular = Rgb(0.6f);
  for (const float c : {0.8f, 0.1f}) {  // 2 tests
    const auto p = standard::lobe_probabilities(m, incident(c));
    EXPECT_NEAR(p.reflect, 0.6f, 1e-6f);
    check_sampling("diffuse_mirror", m, incident(c), {p.reflect});
  }
}

TEST(BsdfChi2, SmoothGlass) {
  const Material m = make_glass(1.5f);
  for (const float c : {0.8f, 0.1f, -0.9f}) {  // 3 tests (-0.5 would be total internal reflection)
    const Vec3 wo = incident(c);
    const float f = fresnel_dielectric(wo.z, 1.5f);
    check_sampling("smooth_glass", m, wo, {f, 1.f - f}, TransportMode::radiance, 200000);
  }
}

// Layered BSDFs: the sampled directions follow pdf (an exact mixture density) for smooth and rough
// coats over Lambert and conductor bases; a smooth coat's mirror is a discrete cell.
Material coated(MaterialType type, float alpha, float base_alpha) {
  Material m;
  m.type = type;
  m.two_sided = true;
  m.ior = 1.5f;
  m.alpha = alpha;
  m.base_alpha = base_alpha;
  m.diffuse = Rgb(0.7f, 0.5f, 0.3f);
  m.eta = Rgb(0.2f, 0.6f, 1.1f);
  m.k = Rgb(3.f, 2.5f, 2.f);
  m.thickness = 0.1f;
  return m;
}

void check_layered(const std::string& name, const Material& m, float c) {
  Vec3 wo = incident(c);
  Vec3 up = wo;
  if (up.z < 0.f) up.z = -up.z;  // two-sided: the proposal of the mirrored wo
  const float mirror = layered::proposal(m, up).mirror;
  check_sampling(name, m, wo, mirror > 0.f ? std::vector<double>{mirror} : std::vector<double>{}, TransportMode::radiance, 400000);
}

TEST(BsdfChi2, Layered) {  // 13 tests (a smooth coat over a smooth conductor is a pure mirror: stat/layered_bsdf_test.cpp)
  for (const float alpha : {0.f, 0.1f, 0.5f})
    for (const float c : {0.8f, 0.2f}) check_layered("coated_diffuse_" + std::to_string(alpha), coated(MaterialType::coated_diffuse, alpha, 0.f), c);
  const float cases[][2] = {{0.f, 0.2f}, {0.2f, 0.2f}, {0.3f, 0.f}};
  for (const auto& ab : cases)
    for (const float c : {0.8f, 0.2f})
      check_layered("coated_conductor_" + std::to_string(ab[0]) + "_" + std::to_string(ab[1]),
                    coated(MaterialType::coated_conductor, ab[0], ab[1]), c);
  check_layered("coated_diffuse_from_below", coated(MaterialType::coated_diffuse, 0.1f, 0.f), -0.6f);
}

// Weights of the delta lobes (the chi-square only sees their probabilities).
TEST(BsdfDelta, WeightsAndTotalInternalReflection) {
  const Material glass = make_glass(1.5f);
  for (const TransportMode mode : {TransportMode::radiance, TransportMode::importance})
    for (const float c : {0.8f, -0.8f, -0.5f}) {
      const Vec3 wo = incident(c);
      const float f = fresnel_dielectric(wo.z, 1.5f);
      for (const float u_lobe : {0.f, 0.999f}) {
        BsdfSample s;
        ASSERT_TRUE(bsdf_sample(glass, wo, u_lobe, {0.5f, 0.5f}, mode, &s));
        EXPECT_TRUE(s.delta);
        if (s.lobe & kLobeReflection) {
          EXPECT_FLOAT_EQ(s.pdf_w, f);
          EXPECT_TRUE(close(s.weight, Rgb(1.f)));
        } else {
          const float eta = wo.z > 0.f ? 1.5f : 1.f / 1.5f;
          EXPECT_FLOAT_EQ(s.eta, eta);
          EXPECT_FLOAT_EQ(s.pdf_w, 1.f - f);
          EXPECT_TRUE(close(s.weight, Rgb(mode == TransportMode::radiance ? 1.f / (eta * eta) : 1.f))) << str(s.weight);
        }
      }
      if (c == -0.5f) {
        EXPECT_EQ(f, 1.f);  // beyond the critical angle: reflection only
      }
    }
  const Material mirror = make_mirror(Rgb(0.9f, 0.8f, 0.7f));
  BsdfSample s;
  ASSERT_TRUE(bsdf_sample(mirror, incident(0.3f), 0.5f, {0.1f, 0.2f}, TransportMode::radiance, &s));
  EXPECT_TRUE(s.delta);
  EXPECT_EQ(s.pdf_w, 1.f);
  EXPECT_TRUE(close(s.weight, Rgb(0.9f, 0.8f, 0.7f)));
  EXPECT_TRUE(close(dot(s.wi, Vec3(-incident(0.3f).x, -incident(0.3f).y, 0.3f)), 1.f, 1e-6f));
}

// f(wo, wi) == f(wi, wo) for reflection; for transmission f_radiance(wo, wi) etap^2 ==
// f_radiance(wi, wo) with etap = n_wi / n_wo, and f_importance(wo, wi) == f_radiance(wi, wo).
// Values below 1e-6 are compared absolutely: there (microfacets seen edge-on, 1 - F ~ 1e-7) float
// cancellation dominates and the values do not matter.
TEST(BsdfReciprocity, ReflectionAndTransmission) {
  const Material materials[] = {make_phong(Rgb(0.3f), Rgb(0.5f), 12.f),
                                make_rough_conductor(0.2f, Rgb(0.2f, 0.9f, 1.1f), Rgb(3.9f, 2.4f, 2.2f)),
                                make_rough_dielectric(0.3f, 1.5f), make_rough_dielectric(0.05f, 1.f / 1.33f),
                                beckmann(make_rough_conductor(0.2f, Rgb(0.2f, 0.9f, 1.1f), Rgb(3.9f, 2.4f, 2.2f))),
                                beckmann(make_rough_dielectric(0.3f, 1.5f))};
  Pcg32 rng(17, 5);
  for (const Material& m : materials) {
    int nonzero = 0, transmissions = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 a = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
      const Vec3 b = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
      const Rgb fab = bsdf_eval(m, a, b, TransportMode::radiance), fba = bsdf_eval(m, b, a, TransportMode::radiance);
      nonzero += !is_black(fab);
      if (a.z * b.z > 0.f) {
        ASSERT_TRUE(close(fab, fba, kRelTolerance, 1e-6f))
            << "wo " << str(a) << " wi " << str(b) << ": " << str(fab) << " vs " << str(fba);
        ASSERT_TRUE(close(fab, bsdf_eval(m, a, b, TransportMode::importance), kRelTolerance, 1e-6f));
      } else if (!is_black(fab)) {
        ++transmissions;
        const float etap = b.z < 0.f ? m.ior : 1.f / m.ior;
        ASSERT_TRUE(close(fab * (etap * etap), fba, kRelTolerance, 1e-6f)) << "wo " << str(a) << " wi " << str(b);
        ASSERT_TRUE(close(bsdf_eval(m, a, b, TransportMode::importance), fba, kRelTolerance, 1e-6f))
            << "wo " << str(a) << " wi " << str(b);
      }
    }
    EXPECT_GT(nonzero, 1000);
    if (m.type == MaterialType::rough_dielectric) {
      EXPECT_GT(transmissions, 1000);
    }
  }
}

// A white rough conductor (Fresnel == 1) reflects at most all energy, and nearly all of it when
// smooth: the mean sample weight (failures count 0) is <= 1 + 3 sigma and close to 1. Single
// scattering loses the energy of rays that would reflect again; GGX's long tails make that
// about 0.3% at normal incidence even for alpha = 0.05, and about 11% at cos = 0.05.
// Beckmann's lighter tails lose less: the same bounds hold for it.
TEST(BsdfEnergy, WhiteRoughConductorAlbedo) {
  for (const float c : {1.f, 0.7f, 0.3f, 0.05f}) ASSERT_GT(fresnel_conductor_channel(c, 1.f, 1e4f), 0.9999f);
  Pcg32 rng(3, 3);
  for (const MicrofacetDistribution dist : {MicrofacetDistribution::ggx, MicrofacetDistribution::beckmann})
  for (const float c : {0.95f, 0.5f, 0.2f, 0.05f}) {
    Material m = make_rough_conductor(0.05f, Rgb(1.f), Rgb(1e4f));
    m.distribution = dist;
    const Vec3 wo = incident(c);
    double sum = 0, sum_sq = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      BsdfSample s;
      const float u_lobe = rng.next_float();
      const Point2 u{rng.next_float(), rng.next_float()};
      const double w = bsdf_sample(m, wo, u_lobe, u, TransportMode::radiance, &s) ? s.weight.g : 0.0;
      sum += w;
      sum_sq += w * w;
    }
    const double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum_sq / n - mean * mean) / n);
    std::printf("white conductor (%s) alpha 0.05 wo.z %.2f: albedo %.5f +- %.5f\n",
                dist == MicrofacetDistribution::ggx ? "ggx" : "beckmann", c, mean, sigma);
    EXPECT_LE(mean, 1.0 + 3.0 * sigma + 1e-6);
    EXPECT_GT(mean, c >= 0.5f ? 0.99 : (c >= 0.2f ? 0.95 : 0.85));
  }
}

}  // namespace
}  // namespace pathspace
