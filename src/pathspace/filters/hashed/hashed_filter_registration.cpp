// `--filter hashed`: the options of hashed path space filtering (Binder, Fricke, Keller 2021) and
// its registration. Section numbers are those of the 2021 paper.
#include "pathspace/filters/common_filter_options.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/filters/hashed/hashed_filter.h"

namespace pathspace {

namespace {

OptionTable<HashedFilterSettings> hashed_options() {
  using S = HashedFilterSettings;
  OptionTable<S> t;
  t.number("psf-scale", [](S& s) -> float& { return s.key.psf_scale; }, 0.01, 10000.0,
           "Voxel edge in projected pixels at the vertex's distance", "sec. 3.1.1, sec. 4");
  t.flag("psf-no-jitter", [](S& s) -> bool& { return s.key.jitter; }, false,
         "Quantise without jittering (shows voxel blocks, fig. 6c)", "sec. 3.1.4");
  t.choice("psf-normal", [](S& s) -> NormalKeyMode& { return s.key.normal; },
           std::vector<std::pair<std::string, NormalKeyMode>>{
               {"key", NormalKeyMode::key}, {"fingerprint", NormalKeyMode::fingerprint}, {"off", NormalKeyMode::off}},
           "Normal in the key, only in the fingerprint, or off", "sec. 3.1.2, sec. 3.2.2 (fig. 7)");
  t.number("psf-table-factor", &S::table_factor, 0.001, 64.0, "Hash table cells per pixel (rounded up to a power of two)",
           "sec. 4");
  t.number("psf-probes", &S::max_probes, 1, 4096, "Linear probing limit (<= 16 stays in one cache line)", "sec. 3.2.2; 2019 paper sec. 3.1");
  t.number("psf-min-count", &S::min_count, 0, 1 << 20, "Voxels with fewer vertices are low-count", "sec. 3.3");
  t.number("psf-clamp", &S::max_luminance, 0.0, 1e30,
           "Largest luminance a vertex adds to its voxel's average: an anti-firefly clamp as SHaRC's, beyond the paper, "
           "biased low (0: no clamp)");
  t.flag("psf-neighbours", &S::neighbour_search, true, "Low-count voxels add their 26 neighbours", "sec. 3.3.1");
  t.flag("psf-multi-level", &S::multi_level, true, "Low-count voxels use a voxel one level coarser", "sec. 3.3.2");
  t.flag("psf-adaptive", &S::adaptive, true,
         "Adaptive resolution: each vertex takes its voxel or the one a level coarser, whichever has the lower estimated "
         "squared error (finite difference across the levels against the extra variance)",
         "sec. 3.1.3");
  add_aa_paths_option(t, &S::aa_paths);
  add_caustic_options(t, &S::caustics);
  t.flag("aov", &S::debug_images, true, "Also write the filter's debug images (voxel, count, level, probes; history, alpha with --temporal)");
  t.choice("temporal", [](S& s) -> TemporalMode& { return s.temporal.mode; },
           std::vector<std::pair<std::string, TemporalMode>>{
               {"off", TemporalMode::off}, {"integrate", TemporalMode::integrate}, {"ema", TemporalMode::ema},
               {"hybrid", TemporalMode::hybrid}},
           "Keep the table across passes and frames: integrate (alpha = N_old / (N_old + N_new)), an exponential moving "
           "average, or hybrid (integrate, less where re-traced paths show change)",
           "sec. 3.4.1");
  t.number("temporal-probe-fraction", [](S& s) -> float& { return s.temporal.probe_fraction; }, 1e-4, 1.0,
           "--temporal hybrid: share of the previous frame's paths traced again each frame (pixels take turns)", "sec. 3.4.1");
  t.flag("temporal-no-transfer", [](S& s) -> bool& { return s.temporal.level_transfer; }, false,
         "New voxels start empty instead of from the history of their finer or coarser voxels", "sec. 3.4.2");
  t.number("temporal-finer-weight", [](S& s) -> float& { return s.temporal.finer_weight; }, 0.0, 1.0,
           "A new voxel taking its coarser voxel's average keeps this share of its weight (0: none)", "sec. 3.4.2");
  t.number("temporal-change-threshold", [](S& s) -> float& { return s.temporal.change_threshold; }, 1e-4, 1e4,
           "--temporal hybrid: relative change of a voxel's re-traced paths at which the history's weight reaches 0",
           "sec. 3.4.1, fig. 9");
  t.flag("temporal-rectify", [](S& s) -> bool& { return s.temporal.rectify; }, true,
         "--temporal hybrid: scale a probed voxel's history by its re-traced paths' luminance now over before (a ratio "
         "estimator of the change; beyond the paper) before blending",
         "sec. 3.4.1, fig. 9");
  t.number("temporal-alpha", [](S& s) -> float& { return s.temporal.alpha; }, 0.0, 1.0,
           "--temporal ema: weight of the old average", "sec. 3.4.1");
  t.number("temporal-max-frames", [](S& s) -> int& { return s.temporal.max_frames; }, 0, 1 << 24,
           "History cap: a voxel keeps at most this many steps' worth of vertices (0: no cap)", "sec. 3.4.1");
  t.choice("temporal-eviction", [](S& s) -> EvictionPolicy& { return s.temporal.eviction; },
           std::vector<std::pair<std::string, EvictionPolicy>>{
               {"priority", EvictionPolicy::priority}, {"lru", EvictionPolicy::lru}, {"stale", EvictionPolicy::stale}},
           "Which cells leave the table between steps: priority bits in the fingerprint, least recently used, or unused for "
           "--temporal-stale-frames steps",
           "sec. 3.4.3");
  t.number("temporal-occupancy", [](S& s) -> float& { return s.temporal.occupancy; }, 0.0625, 1.0,
           "Eviction (priority, lru) keeps each probe window at most this full", "sec. 3.4.3");
  t.number("temporal-stale-frames", [](S& s) -> int& { return s.temporal.stale_frames; }, 1, 1 << 24,
           "--temporal-eviction stale: steps without use before a cell is evicted", "sec. 3.4.3");
  t.check([](const S& s) {
    if (int(s.neighbour_search) + int(s.multi_level) + int(s.adaptive) > 1)
      throw OptionError("--psf-neighbours, --psf-multi-level and --psf-adaptive are alternatives; pick one");
    if (s.temporal.rectify && s.temporal.mode != TemporalMode::hybrid)
      throw OptionError("--temporal-rectify scales histories by the change that --temporal hybrid measures: it needs --temporal hybrid");
    if (s.temporal.enabled() && (s.neighbour_search || s.multi_level || s.adaptive))
      throw OptionError(
          "--temporal keeps one level of voxels: it does not combine with --psf-neighbours, --psf-multi-level or --psf-adaptive");
  });
  return t;
}

const FilterRegistrar kRegistrar{make_filter_entry<HashedFilterSettings>(
    "hashed", "hashed path space filtering: jittered voxel averages in a hash table, per pass",
    "Binder, Fricke, Keller 2021, sec. 3.1-3.4", hashed_options(),
    [](const FilterContext& ctx, const HashedFilterSettings& s) -> std::unique_ptr<PathSpaceFilter> {
      return std::make_unique<HashedFilter>(s, ctx.camera, ctx.pixels);
    })};

}  // namespace

}  // namespace pathspace
