// `--filter consistent`: the options of consistent path space filtering (Keller, Dahm, Binder 2014)
// and its registration. Section, equation and figure numbers are those of the 2014 paper.
#include "pathspace/filters/common_filter_options.h"
#include "pathspace/filters/consistent_filter.h"
#include "pathspace/filters/filter_registry.h"

namespace pathspace {

namespace {

OptionTable<ConsistentFilterSettings> consistent_options() {
  using S = ConsistentFilterSettings;
  OptionTable<S> t;
  t.number("psf-alpha", &S::alpha, 1e-3, 0.999, "Radius exponent: r(n) = r0 / n^alpha, n paths per pixel so far", "eq. 2, sec. 2.2");
  t.number("psf-radius-pixels", &S::radius_pixels, 0.01, 1000.0,
           "r0 from the solid angle of K x K pixels at the length of the camera path to the vertex", "sec. 2.2");
  t.number("psf-radius", &S::radius, 0.0, 1e30, "r0 in scene units for every vertex instead (0: from --psf-radius-pixels)", "eq. 2");
  t.number("psf-medium-radius-scale", &S::medium_radius_scale, 1.0, 1000.0,
           "r0 of vertices in participating media, in multiples of a surface vertex's (a ball around a point of a volume "
           "holds fewer vertices than around a point of a surface)",
           "sec. 3; docs/media.md");
  t.choice("psf-weights", &S::weights,
           std::vector<std::pair<std::string, uint32_t>>{{"normal,albedo,visibility", kWeightNormal | kWeightAlbedo | kWeightVisibility},
                                                         {"normal,albedo", kWeightNormal | kWeightAlbedo},
                                                         {"normal,visibility", kWeightNormal | kWeightVisibility},
                                                         {"albedo,visibility", kWeightAlbedo | kWeightVisibility},
                                                         {"normal", kWeightNormal},
                                                         {"albedo", kWeightAlbedo},
                                                         {"visibility", kWeightVisibility},
                                                         {"none", 0u}},
           "Binary similarity weights: normal, albedo (with the direction on glossy layers), visibility, a combination, or none",
           "sec. 2.1, fig. 4");
  t.number("psf-normal-threshold", &S::normal_threshold, -1.0, 1.0, "Normal weight: smallest <n_j, n_i> averaged", "sec. 2.1");
  t.number("psf-albedo-threshold", &S::albedo_threshold, 0.0, 1e30,
           "Albedo weight: largest difference of the stored attenuation per channel", "sec. 2.1");
  t.number("psf-visibility-threshold", &S::visibility_threshold, 0.0, 1.0,
           "Visibility weight: largest relative difference of the lengths of the vertices' rays along the normal", "sec. 2.1");
  add_aa_paths_option(t, &S::aa_paths);
  t.number("psf-iterations", &S::iterations, 1, 64, "Iterated averaging: average the averages this many times", "sec. 2, fig. 2");
  add_caustic_options(t, &S::caustics);
  t.number("psf-batch-memory", &S::batch_memory_mb, 0.0, 1e9,
           "MiB for filtering one batch of paths; a pass is filtered in as many batches as needed (0: an eighth of the RAM)", "sec. 2");
  return t;
}

const FilterRegistrar kRegistrar{make_filter_entry<ConsistentFilterSettings>(
    "consistent", "consistent path space filtering: weighted averages in a ball whose radius shrinks with the paths so far",
    "Keller, Dahm, Binder 2014, sec. 2-2.2", consistent_options(),
    [](const FilterContext& ctx, const ConsistentFilterSettings& s) -> std::unique_ptr<PathSpaceFilter> {
      return std::make_unique<ConsistentFilter>(s, ctx.camera, ctx.pixels);
    })};

}  // namespace

}  // namespace pathspace
