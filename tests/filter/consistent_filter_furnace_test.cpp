// Furnace tests with the consistent filter (Keller, Dahm, Binder 2014) on: in a closed scene with a
// constant radiance field every vertex's contribution has the same expectation, so the weighted
// average of eq. 1 is unbiased for any radius, weights, iterations and batch size, and so are the
// anti-aliasing queries; the image mean must stay exact. The samples of the t-test are whole
// single-pass renders (independent seeds). alpha = 0.01, Sidak-corrected over the tests here.
#include <gtest/gtest.h>

#include <functional>

#include "filter_render.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "support/statistics.h"
#include "support/test_names.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kPasses = 40;
constexpr int kVariants = 7;
constexpr int kScenes = 2;
const double kAlpha = testing::sidak(0.01, kVariants * kScenes);

struct Variant {
  const char* name;
  std::function<void(ConsistentFilterSettings*)> apply;
};

const Variant kVariantList[kVariants] = {
    {"default", [](ConsistentFilterSettings*) {}},
    {"no_weights", [](ConsistentFilterSettings* s) { s->weights = 0; }},
    {"huge_radius", [](ConsistentFilterSettings* s) { s->radius = 100.f; }},
    {"tiny_radius", [](ConsistentFilterSettings* s) { s->radius = 1e-6f; }},
    {"three_iterations", [](ConsistentFilterSettings* s) { s->iterations = 3; }},
    {"query_paths", [](ConsistentFilterSettings* s) { s->aa_paths = 2; }},
    {"small_batches", [](ConsistentFilterSettings* s) { s->batch_memory_mb = 0.05; }},
};

void expect_exact_mean(const Scene& scene, const Variant& v, double expected) {
  testing::expect_exact_image_mean(
      scene,
      [&](int p) {
        ConsistentFilterSettings s;
        v.apply(&s);
        return with_filter(make_render_config("pt", PtSettings{}, 2000 + uint64_t(p)), "consistent", s);
      },
      kPasses, expected, kAlpha, v.name);
}

class ConsistentFilterFurnace : public ::testing::TestWithParam<int> {};

TEST_P(ConsistentFilterFurnace, ClosedBoxStaysExact) {
  const float le = 0.8f, albedo = 0.6f;
  expect_exact_mean(testing::make_furnace_box(le, albedo, 32), kVariantList[GetParam()], le / (1.0 - albedo));
}

TEST_P(ConsistentFilterFurnace, SphereWithPointLightStaysExact) {
  const float radius = 2.f, albedo = 0.5f, intensity = 3.f;
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_exact_mean(testing::make_sphere_with_point_light(radius, albedo, intensity, 32), kVariantList[GetParam()], expected);
}

INSTANTIATE_TEST_SUITE_P(Variants, ConsistentFilterFurnace, ::testing::Range(0, kVariants),
                         [](const ::testing::TestParamInfo<int>& i) { return testing::test_name(kVariantList[i.param].name); });

}  // namespace
}  // namespace pathspace
