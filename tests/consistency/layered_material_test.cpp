// Layered materials (materials/layered_bsdf.h) in whole renders: the empty Cornell box (SmallVCM
// e_c) with its walls replaced by coated materials (a Lambertian base under a smooth or rough coat,
// one with a scattering slab, and a rough conductor under a coat) renders the same image with PT,
// BPT and LT (per-pixel z-tests, alpha = 0.01 Sidak-corrected over kComparisons). BPT weights its
// strategies with the layered BSDF's forward and reverse pdfs, and LT connects to the camera
// through eval in importance mode, so agreement checks that eval, pdf and sample fit together in
// both transport modes. LT cannot see a smooth coat's mirror lobe directly, so LT compares against
// PT with rough coats only.
#include <gtest/gtest.h>

#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 2;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

// The Cornell box's diffuse walls, each coated in turn by one of three layered materials.
Scene coated_cornell_box(bool smooth_coats) {
  Scene s = make_cornell_box(1, 16, 16);
  std::vector<bool> wall(s.materials.size(), false);
  for (const Triangle& t : s.triangles)
    if (t.light == kNoLight && s.materials[t.material].type == MaterialType::standard && !is_black(s.materials[t.material].diffuse))
      wall[t.material] = true;
  int k = 0;
  for (size_t i = 0; i < s.materials.size(); ++i) {
    if (!wall[i]) continue;
    Material& m = s.materials[i];
    m.ior = 1.5f;
    m.thickness = 0.05f;
    switch (k++ % 3) {
      case 0:
        m.type = MaterialType::coated_diffuse;
        m.alpha = smooth_coats ? 0.f : 0.2f;
        break;
      case 1:
        m.type = MaterialType::coated_diffuse;
        m.alpha = 0.4f;
        m.medium_albedo = Rgb(0.6f, 0.7f, 0.8f);
        m.g = 0.3f;
        m.thickness = 0.4f;
        break;
      default:
        m.type = MaterialType::coated_conductor;
        m.alpha = smooth_coats ? 0.f : 0.15f;
        m.base_alpha = 0.3f;
        m.eta = Rgb(0.2f, 0.9f, 1.1f) * (1.f / m.ior);
        m.k = Rgb(3.9f, 2.4f, 2.2f) * (1.f / m.ior);
        break;
    }
  }
  s.finalize();
  return s;
}

TEST(LayeredMaterial, BidirectionalPathTracingAgreesWithPathTracing) {
  const Scene scene = coated_cornell_box(true);
  const testing::Rendered bpt =
      testing::render_integrator(scene, make_render_config("bpt", BptSettings{}, testing::test_seed(501)), 256);
  const testing::Rendered pt =
      testing::render_integrator(scene, make_render_config("pt", PtSettings{}, testing::test_seed(502)), 1024);
  testing::expect_same_image(bpt, pt, "layered-bpt-vs-pt", kAlphaImage, "bpt", "pt");
}

TEST(LayeredMaterial, LightTracingAgreesWithPathTracing) {
  const Scene scene = coated_cornell_box(false);
  LtSettings lt;
  lt.light_paths = 4096;
  const testing::Rendered a = testing::render_integrator(scene, make_render_config("lt", lt, testing::test_seed(503)), 256);
  const testing::Rendered b =
      testing::render_integrator(scene, make_render_config("pt", PtSettings{}, testing::test_seed(504)), 1024);
  testing::expect_same_image(a, b, "layered-lt-vs-pt", kAlphaImage, "lt", "pt");
}

}  // namespace
}  // namespace pathspace
