// Layered BSDFs (materials/layered_bsdf.h, pbrt-v4's coateddiffuse and coatedconductor) against
// closed forms and against an analog simulation of the layer (docs/testing.md):
//  - a smooth coat without absorption over a Lambertian base of albedo rho: the albedo for light
//    from wo is F + (1 - F) rho (1 - Fi) / (1 - rho Fi), Fi the cosine-weighted Fresnel reflectance
//    from inside (total internal reflection included), within 1% at four angles;
//  - white furnace: exactly 1 (within 1%) for a white base under a smooth coat that absorbs nothing,
//    at most 1 for rough coats (single-scattering microfacets lose energy), conductors and slabs;
//  - eval against an analog simulation, in which light enters through the coat, crosses the slab
//    (free flights, absorption, Henyey-Greenstein scattering), scatters at the base and leaves, every
//    event drawn with the interfaces' own samplers: the energy reflected into five bins of
//    cos(theta_i) agrees with the mean sample weight of bsdf_sample (weight = eval |cos| / pdf),
//    in both transport modes. Two-sample z-tests, alpha = 0.01 Sidak-corrected over kZTests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pathspace/materials/bsdf.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kBins = 5;
constexpr int kAngles = 2;
constexpr int kModes = 2;
constexpr int kConfigs = 9;
constexpr int kZTests = kConfigs * kAngles * kModes * kBins;

Vec3 incident(float cos_theta) { return {safe_sqrt(1.f - cos_theta * cos_theta), 0.f, cos_theta}; }

Material coated(MaterialType type) {
  Material m;
  m.type = type;
  m.two_sided = true;
  m.ior = 1.5f;
  m.alpha = 0.f;  // a smooth coat unless a test says otherwise (Material's default is 0.1)
  m.diffuse = Rgb(0.7f, 0.5f, 0.3f);
  m.eta = Rgb(0.2f, 0.6f, 1.1f);
  m.k = Rgb(3.f, 2.5f, 2.f);
  m.thickness = 0.1f;
  m.max_depth = 100;
  return m;
}

// Per-bin sums of a weight and its square, for the mean and its variance.
struct Tally {
  std::vector<double> sum = std::vector<double>(kBins, 0.0), sum_sq = std::vector<double>(kBins, 0.0);
  double total = 0;
  void add(const Vec3& wi, double weight) {
    const int b = std::min(kBins - 1, int(wi.z * kBins));
    sum[b] += weight;
    sum_sq[b] += weight * weight;
    total += weight;
  }
};

// Light arriving along wo through the layer, every event analog: the interfaces' own sampling
// (the coat's Fresnel choice between reflection and refraction), free flights in the slab with
// absorption as termination (grey albedo), the base's sampling. Tallies the red channel.
Tally analog(const Material& m, const Vec3& wo, int n, Pcg32& rng) {
  const Material top = layered::coat_smooth(m) ? make_glass(m.ior) : layered::coat_material(m);
  const auto r = [&rng] { return rng.next_float(); };
  Tally t;
  for (int i = 0; i < n; ++i) {
    BsdfSample s;
    if (!bsdf_sample(top, wo, r(), {r(), r()}, TransportMode::radiance, &s)) continue;
    float beta = s.weight.r;
    if (s.wi.z > 0.f) {
      t.add(s.wi, beta);
      continue;
    }
    Vec3 w = s.wi;
    float z = m.thickness;
    for (int depth = 0; depth < 100000 && beta > 0.f; ++depth) {
      const float dz = -logf(1.f - r()) * fabsf(w.z);
      const float zp = w.z > 0.f ? z + dz : z - dz;
      if (zp > 0.f && zp < m.thickness) {
        if (r() >= m.medium_albedo.r) break;  // absorbed in the slab
        w = hg_sample(w, m.g, {r(), r()});
        z = zp;
        continue;
      }
      z = zp <= 0.f ? 0.f : m.thickness;
      BsdfSample e;
      if (z == 0.f) {
        const Vec3 up = -w;
        if (m.type == MaterialType::coated_diffuse) {
          e.wi = square_to_cosine_hemisphere({r(), r()});
          e.weight = m.diffuse;
        } else if (layered::base_delta(m)) {
          e.wi = Vec3(-up.x, -up.y, up.z);
          e.weight = fresnel_conductor(up.z, m.eta, m.k);
        } else if (!rough_conductor::sample(layered::base_conductor(m), up, 0.f, {r(), r()}, TransportMode::radiance, &e)) {
          break;
        }
      } else if (!bsdf_sample(top, -w, r(), {r(), r()}, TransportMode::radiance, &e)) {
        break;
      }
      beta *= e.weight.r;
      w = e.wi;
      if (z == m.thickness && w.z > 0.f) {  // left through the coat
        t.add(w, beta);
        break;
      }
      if (depth > 8 && beta < 0.1f) {  // Russian roulette
        if (r() < 0.5f) break;
        beta *= 2.f;
      }
    }
  }
  return t;
}

// bsdf_sample's weights (red), delta lobes included, tallied by the sampled direction.
Tally sampled(const Material& m, const Vec3& wo, TransportMode mode, int n, Pcg32& rng) {
  Tally t;
  for (int i = 0; i < n; ++i) {
    BsdfSample s;
    if (bsdf_sample(m, wo, rng.next_float(), {rng.next_float(), rng.next_float()}, mode, &s)) t.add(s.wi, s.weight.r);
  }
  return t;
}

double mean_albedo(const Material& m, const Vec3& wo, int n, TransportMode mode = TransportMode::radiance) {
  Pcg32 rng(12345, uint64_t(1000 * wo.z));
  return sampled(m, wo, mode, n, rng).total / n;
}

TEST(LayeredBsdf, SmoothCoatOverLambertMatchesTheClosedFormAlbedo) {
  for (const float rho : {0.8f, 0.3f}) {
    Material m = coated(MaterialType::coated_diffuse);
    m.diffuse = Rgb(rho);
    m.thickness = 1e-6f;  // nothing absorbed on the way through the slab
    m.max_depth = 400;    // no truncation of the internal bounces
    const double fi = internal_diffuse_fresnel(m.ior, 1 << 20);
    for (const float c : {0.95f, 0.6f, 0.3f, 0.1f}) {
      const double f = fresnel_dielectric(c, m.ior);
      const double closed = f + (1 - f) * rho * (1 - fi) / (1 - rho * fi);
      const double got = mean_albedo(m, incident(c), 1 << 20);
      std::printf("rho %.1f cos %.2f: albedo %.5f, closed form %.5f\n", rho, c, got, closed);
      EXPECT_NEAR(got / closed, 1.0, 0.01) << "rho " << rho << " cos " << c;
    }
  }
}

TEST(LayeredBsdf, WhiteFurnace) {
  Material white = coated(MaterialType::coated_diffuse);
  white.diffuse = Rgb(1.f);
  white.thickness = 1e-6f;
  white.max_depth = 400;
  for (const float c : {0.9f, 0.4f, 0.1f}) EXPECT_NEAR(mean_albedo(white, incident(c), 1 << 19), 1.0, 0.01) << c;
  // Everything else keeps at most what arrives (3 standard errors of slack for the estimate).
  std::vector<Material> others;
  for (const float alpha : {0.1f, 0.5f}) {
    Material m = white;
    m.alpha = alpha;
    others.push_back(m);
  }
  Material conductor = coated(MaterialType::coated_conductor);
  conductor.eta = Rgb(0.2f);
  conductor.k = Rgb(8.f);
  for (const float base_alpha : {0.f, 0.3f})
    for (const float alpha : {0.f, 0.3f}) {
      Material m = conductor;
      m.base_alpha = base_alpha;
      m.alpha = alpha;
      others.push_back(m);
    }
  Material slab = white;
  slab.medium_albedo = Rgb(1.f);
  slab.thickness = 1.f;
  slab.g = 0.6f;
  others.push_back(slab);
  for (size_t i = 0; i < others.size(); ++i)
    for (const float c : {0.9f, 0.4f, 0.1f}) {
      Pcg32 rng(i, uint64_t(c * 100));
      const int n = 1 << 18;
      const Tally t = sampled(others[i], incident(c), TransportMode::radiance, n, rng);
      double sq = 0;
      for (double v : t.sum_sq) sq += v;
      const double mean = t.total / n, se = std::sqrt(std::max(0.0, sq / n - mean * mean) / n);
      EXPECT_LE(mean, 1.0 + 3 * se) << "material " << i << " cos " << c;
    }
}

TEST(LayeredBsdf, EvalAgreesWithAnAnalogSimulationOfTheLayer) {
  struct Config {
    const char* name;
    Material m;
  };
  std::vector<Config> configs;
  const auto add = [&](const char* name, MaterialType type, float alpha, float base_alpha, float albedo, float g,
                       float thickness) {
    Material m = coated(type);
    m.alpha = alpha;
    m.base_alpha = base_alpha;
    m.medium_albedo = Rgb(albedo);
    m.g = g;
    m.thickness = thickness;
    configs.push_back({name, m});
  };
  add("lambert, smooth coat", MaterialType::coated_diffuse, 0.f, 0.f, 0.f, 0.f, 0.1f);
  add("lambert, rough coat", MaterialType::coated_diffuse, 0.3f, 0.f, 0.f, 0.f, 0.1f);
  add("lambert, rough coat, scattering slab", MaterialType::coated_diffuse, 0.3f, 0.f, 0.8f, 0.5f, 0.5f);
  add("lambert, smooth coat, scattering slab", MaterialType::coated_diffuse, 0.f, 0.f, 0.8f, -0.3f, 0.5f);
  add("rough conductor, smooth coat", MaterialType::coated_conductor, 0.f, 0.2f, 0.f, 0.f, 0.1f);
  add("rough conductor, rough coat", MaterialType::coated_conductor, 0.2f, 0.2f, 0.f, 0.f, 0.1f);
  add("smooth conductor, rough coat", MaterialType::coated_conductor, 0.3f, 0.f, 0.f, 0.f, 0.1f);
  add("rough conductor, smooth coat, scattering slab", MaterialType::coated_conductor, 0.f, 0.3f, 0.9f, 0.f, 0.3f);
  add("smooth conductor, smooth coat (a mirror)", MaterialType::coated_conductor, 0.f, 0.f, 0.f, 0.f, 0.1f);
  ASSERT_EQ(int(configs.size()), kConfigs);
  const double alpha = testing::sidak(0.01, kZTests);
  const int n = 1 << 18;
  Pcg32 rng(2024, 11);
  for (const Config& c : configs)
    for (const float cos_o : {0.8f, 0.3f}) {
      const Vec3 wo = incident(cos_o);
      const Tally reference = analog(c.m, wo, n, rng);
      for (const TransportMode mode : {TransportMode::radiance, TransportMode::importance}) {
        const Tally got = sampled(c.m, wo, mode, n, rng);
        for (int b = 0; b < kBins; ++b) {
          const auto variance_of_mean = [n](const Tally& t, int bin) {
            const double mean = t.sum[bin] / n;
            return std::max(0.0, t.sum_sq[bin] / n - mean * mean) / n;
          };
          const double a = reference.sum[b] / n, e = got.sum[b] / n;
          const double z = (a - e) / std::sqrt(variance_of_mean(reference, b) + variance_of_mean(got, b) + 1e-14);
          EXPECT_GE(testing::normal_two_sided_p(z), alpha)
              << c.name << ", cos " << cos_o << (mode == TransportMode::radiance ? ", radiance" : ", importance")
              << ", bin " << b << ": analog " << a << ", bsdf " << e << ", z " << z;
        }
        std::printf("%-48s cos %.1f %-10s albedo: analog %.4f, bsdf %.4f\n", c.name, cos_o,
                    mode == TransportMode::radiance ? "radiance" : "importance", reference.total / n, got.total / n);
      }
    }
}

}  // namespace
}  // namespace pathspace
