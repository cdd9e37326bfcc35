// Furnace tests with the hashed filter on: in a closed scene with a constant radiance field every
// vertex's contribution has the same expectation, so a voxel average is unbiased and the image mean
// must stay exact ("a constant radiance field is a fixed point of averaging"), and so must the
// anti-aliasing queries that read those averages. Voxel averages
// correlate pixels within a pass, so the samples of the t-test are whole passes (independent seeds).
// alpha = 0.01, Sidak-corrected over the tests in this file.
#include <gtest/gtest.h>

#include <functional>

#include "filter_render.h"
#include "support/statistics.h"
#include "support/test_names.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kPasses = 40;
constexpr int kVariants = 12;
constexpr int kScenes = 2;
const double kAlpha = testing::sidak(0.01, kVariants * kScenes);

struct Variant {
  const char* name;
  std::function<void(PtSettings*, HashedFilterSettings*)> apply;
};

const Variant kVariantList[kVariants] = {
    {"default", [](PtSettings*, HashedFilterSettings*) {}},
    {"no_jitter", [](PtSettings*, HashedFilterSettings* h) { h->key.jitter = false; }},
    {"normal_in_fingerprint", [](PtSettings*, HashedFilterSettings* h) { h->key.normal = NormalKeyMode::fingerprint; }},
    {"neighbour_search", [](PtSettings*, HashedFilterSettings* h) {
       h->neighbour_search = true;
       h->min_count = 64;
     }},
    {"multi_level", [](PtSettings*, HashedFilterSettings* h) {
       h->multi_level = true;
       h->min_count = 64;
     }},
    {"all_vertices", [](PtSettings* pt, HashedFilterSettings*) {
       pt->selection.mode = VertexSelectionMode::all;
       pt->selection.max_vertices = 3;
     }},
    {"second_vertex", [](PtSettings* pt, HashedFilterSettings*) {
       pt->selection.mode = VertexSelectionMode::nth;
       pt->selection.n = 2;
     }},
    {"large_voxels", [](PtSettings*, HashedFilterSettings* h) { h->key.psf_scale = 40.f; }},
    {"tiny_table", [](PtSettings*, HashedFilterSettings* h) {
       h->table_factor = 1.f / 64.f;
       h->max_probes = 2;
     }},
    // --psf-aa-paths: the query-only paths read the same voxel averages (hashed_filter_query.cpp).
    {"query_paths", [](PtSettings*, HashedFilterSettings* h) { h->aa_paths = 2; }},
    {"query_paths_multi_level", [](PtSettings*, HashedFilterSettings* h) {
       h->aa_paths = 2;
       h->multi_level = true;
       h->min_count = 64;
     }},
    {"query_paths_adaptive", [](PtSettings*, HashedFilterSettings* h) {
       h->aa_paths = 2;
       h->adaptive = true;
     }},
};

void expect_exact_mean(const Scene& scene, const Variant& v, double expected) {
  testing::expect_exact_image_mean(
      scene,
      [&](int p) {
        PtSettings pt;
        HashedFilterSettings h;
        v.apply(&pt, &h);
        return testing::hashed_config(1000 + uint64_t(p), h, pt);
      },
      kPasses, expected, kAlpha, v.name);
}

class HashedFilterFurnace : public ::testing::TestWithParam<int> {};

TEST_P(HashedFilterFurnace, ClosedBoxStaysExact) {
  const float le = 0.8f, albedo = 0.6f;
  expect_exact_mean(testing::make_furnace_box(le, albedo, 32), kVariantList[GetParam()], le / (1.0 - albedo));
}

TEST_P(HashedFilterFurnace, SphereWithPointLightStaysExact) {
  const float radius = 2.f, albedo = 0.5f, intensity = 3.f;
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_exact_mean(testing::make_sphere_with_point_light(radius, albedo, intensity, 32), kVariantList[GetParam()], expected);
}

INSTANTIATE_TEST_SUITE_P(Variants, HashedFilterFurnace, ::testing::Range(0, kVariants),
                         [](const ::testing::TestParamInfo<int>& i) { return testing::test_name(kVariantList[i.param].name); });

}  // namespace
}  // namespace pathspace
