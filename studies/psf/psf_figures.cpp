// The sections of `pathspace study psf` (studies/psf/psf_figures.h): what each paper figure shows and how
// the study reproduces it, in page order, and the helpers the figure files share.
#include "studies/psf/psf_figures.h"

#include <fmt/format.h>

namespace pathspace::studies {

namespace {

study::Figure figure(std::string id, std::string title, std::string paper, std::string method) {
  study::Figure f;
  f.id = std::move(id);
  f.title = std::move(title);
  f.paper = std::move(paper);
  f.method = std::move(method);
  return f;
}


}  // namespace

std::string equal_time_figure_id(uint32_t spp) { return fmt::format("equal-time-{}spp", spp); }

std::vector<study::Figure> make_psf_figures(const std::vector<uint32_t>& equal_time_spp) {
  std::vector<study::Figure> f;
  // Keller, Dahm, Binder 2014: consistent path space filtering.
  f.push_back(figure("2014-fig2", "2014 fig. 2 - iterated averaging",
                     "Iterating the weighted average (eq. 1) smooths very efficiently by relaxation, at the cost of some "
                     "illumination detail; filtering brightens the image where unfiltered pixels were black.",
                     "PT + consistent filter at 4 paths per pixel with 1, 2 and 4 iterations (--psf-iterations), the same seed; "
                     "PT alone for comparison."));
  f.push_back(figure("2014-fig3", "2014 fig. 3 - progressive filtering is consistent",
                     "As more batches of paths are filtered the radius r(n) shrinks (eq. 2) and the splotchy artefacts vanish: "
                     "the filtered image converges to the right answer.",
                     "One render with PT and one with PT + consistent filter, each measured at 1, 4, 16, ... paths per pixel "
                     "(--max-spp); the plot shows relMSE against paths per pixel, the images are those of the last checkpoint."));
  f.push_back(figure("2014-fig4", "2014 fig. 4 - the similarity weights",
                     "At 16 paths per pixel: uniform weights blur and move light around corners; similar normals keep geometry "
                     "crisp; the attenuation (albedo) weight keeps texture detail; the visibility weight improves shadow "
                     "boundaries.",
                     "PT + consistent filter at 16 paths per pixel with each --psf-weights setting this build has (a setting "
                     "the filter does not know yet is listed as missing), and PT alone."));
  f.push_back(figure("2014-fig7", "2014 fig. 7 - anti-aliasing by extra camera paths (sec. 3)",
                     "One light transport path per pixel plus three extra camera paths per pixel whose queries average the "
                     "first paths' contributions: anti-aliasing across discontinuities without more light transport.",
                     "On the built-in filter-fence scene (bars about a pixel wide at 128x128): PT and PT + consistent filter at "
                     "1 path per pixel, the same with --psf-aa-paths 3 (three query-only camera paths per pixel; a path whose "
                     "query finds nothing similar is not counted), and PT at 4 paths per pixel, the cost of tracing the extra "
                     "camera paths as full paths."));
  f.push_back(figure("2014-sec2.3", "2014 sec. 2.3, fig. 1 - caustics by photon mapping as the complement",
                     "Contributions that path tracing samples badly (caustics) come from progressive photon mapping and are "
                     "not averaged again by path space filtering; without them they are missing or add high variance.",
                     "PT + consistent filter at 16 paths per pixel without and with --psf-caustic-photons (1 and 4 photons per "
                     "pixel and pass, gathered at every sufficiently diffuse camera-path vertex, radius shrinking as in "
                     "SPPM), and PT alone."));
  // Binder, Fricke, Keller 2021 (and the 2019 short version): hashed path space filtering.
  f.push_back(figure("2021-fig1", "2021 fig. 1 - one path per pixel, filtered",
                     "Path tracing at one path per pixel with hashed path space filtering very closely approximates the "
                     "reference at 1024 paths per pixel, for about 1.5 ms in HD.",
                     "PT and PT + hashed filter (defaults, s = 12 px) at 1 path per pixel against the scene's reference; PT "
                     "at 64 paths per pixel for scale."));
  f.push_back(figure("2021-fig4", "2021 fig. 4 - voxel size: noise against blur",
                     "Larger voxels (lower resolution s(k)) blur shadows more and leak more light and shadow.",
                     "PT + hashed filter at 4 paths per pixel with voxel edges --psf-scale 3, 6, 12, 24 and 48 projected "
                     "pixels; the plot shows relMSE against s (noise falls, bias grows), with PT at 4 paths per pixel."));
  f.push_back(figure("2019-fig7", "2019 fig. 7 - hash collisions and occupancy against the table size",
                     "(Short version of the 2021 paper.) Collisions fall as the table grows; with a table of about one cell per "
                     "pixel, occupancy is low and collision resolution is cheap.",
                     "The hashed filter alone (no rendering) on the selected vertices of one 1-spp pass of cornell-box "
                     "(primary hits and second-bounce hits), local combining off so every vertex probes: extra probes per "
                     "insertion and occupancy for voxel sizes 1-8 px and 1/16 to 8 cells per pixel."));
  f.push_back(figure("2019-fig8", "2019 fig. 8 - filter time against the voxel size",
                     "(Short version of the 2021 paper.) Filtering gets faster with larger voxels (fewer distinct voxels); "
                     "primary hits are about twice as fast as incoherent second-bounce hits.",
                     "The same vertex sets: clear + accumulate + lookup per pass, median of 5 timed passes, with the "
                     "per-thread combining on (ours) and off, on this machine's CPU (the paper: a Titan V GPU)."));
  f.push_back(figure("2021-fig10", "2021 fig. 10 - filtering at the second bounce",
                     "Filtering only at the second diffuse vertex (final gathering) at 16 paths per pixel dramatically "
                     "reduces the variance of indirect illumination while direct illumination stays sharp.",
                     "PT, PT + hashed filter at the first vertex, and PT + hashed filter at the second (--psf-select nth "
                     "--psf-nth 2), all at 16 paths per pixel."));
  // 2021 sec. 3.4: the table across frames (studies/psf2021/temporal_figures.cpp), once per study.
  f.push_back(figure("2021-sec3.4.1", "2021 sec. 3.4.1 - temporal integration of a static scene, orbiting camera",
                     "Keeping the hash table across frames and blending each voxel's earlier average with the new one "
                     "(alpha = N_old / (N_old + N_new)) is true temporal integration of static content: the error falls "
                     "frame after frame although each frame traces one path per pixel.",
                     "cornell-box (the camera orbiting 0.25 degrees per frame, so that it stays in front of the box) and "
                     "scenes/textured-room/scene.pbrt (1 degree per frame) at the study's resolution, 1 spp per frame for "
                     "--temporal-frames frames, PT + hashed filter with --temporal integrate and with off; relMSE of the frames "
                     "1, 2, 4, ... and the last against a PT reference of that frame (an eighth of --reference-time each; "
                     "debiased: minus the reference's own noise). The image tables show the first and the last frame beside "
                     "that frame's reference."));
  f.push_back(figure("2021-fig9", "2021 fig. 9 - a moving light: ema, integration and hybrid blending",
                     "Integration keeps the old lighting where a light moved (ghosting of the shadow), an exponential moving "
                     "average follows it but stays noisy; the hybrid blend integrates where nothing changed and restarts "
                     "where re-traced paths show a change.",
                     "cornell-moving-light without jitter (--psf-no-jitter), 1 spp per frame, frames 0 to 32 (fewer when "
                     "--temporal-frames is smaller), --temporal ema, integrate and hybrid; frame 32 against its PT reference, "
                     "over the whole image and in the band of pixels whose reference changed by more than 20% between frames "
                     "24 and 32 (the moving shadow's boundary). Plots: the luminance along the image row with the most band "
                     "pixels, and the mean alpha of each frame's step."));
  f.push_back(figure("2021-sec3.4.3", "2021 sec. 3.4.3 - eviction: a flight through a scene the table cannot hold",
                     "A table kept across frames fills up; evicting by a priority of recency and sample count keeps the "
                     "occupancy bounded, inserts succeeding and the memory constant however long the animation runs.",
                     "textured-room at 160x90, the camera flying through eight views of the room (corners, centre, floor, "
                     "ceiling; keyframes every 2 s) for --eviction-frames frames, PT + hashed filter with --temporal integrate, "
                     "voxels of 3 projected pixels and --psf-table-factor 0.25 (4096 cells; the room needs more), for each "
                     "--temporal-eviction policy (priority and lru evict down to --temporal-occupancy 0.75, stale after 32 "
                     "unused steps): occupancy after each step, evictions, failed inserts (probe limit) per vertex, the "
                     "process's resident memory (VmRSS), the time per frame and the temporal bookkeeping's share of the "
                     "filter's time (hashed.temporal.s_per_step against clear + accumulate + lookup per pass)."));
  // Ours.
  for (const uint32_t spp : equal_time_spp)
    f.push_back(figure(equal_time_figure_id(spp),
                       fmt::format("Equal time at the hashed filter's {} path{} per pixel: path space filters against a "
                                   "screen-space filter", spp, spp == 1 ? "" : "s"),
                       "Neither paper compares at equal time. The 2021 paper calls screen-space noise filters complementary "
                       "(sec. 4); the edge-avoiding à-trous wavelet filter (Dammertz et al. 2010) is such a filter.",
                       fmt::format("PT + hashed filter (its defaults, caustic photons included) for {} pass{}; its wall time "
                                   "is the budget of PT and of PT + consistent filter (whole passes, at least one); and the "
                                   "PT render followed by 5 à-trous iterations guided by the first hits' normals, albedo and "
                                   "positions (cast by the study), its time = PT's + the filter's.",
                                   spp, spp == 1 ? "" : "es")));
  for (study::Figure& fig : f) {
    if (fig.id.rfind("2014-", 0) == 0) fig.metric_rows = filter_metric_rows("consistent");
    if (fig.id == "2021-fig1" || fig.id == "2021-fig4" || fig.id == "2021-fig10") fig.metric_rows = filter_metric_rows("hashed");
  }
  return f;
}

study::Configuration pt_with(const std::string& label, const std::string& filter,
                             std::initializer_list<std::pair<std::string, std::string>> options) {
  OptionValues values;
  for (const auto& [name, value] : options) values.set(name, value);
  study::Configuration c = study::configuration(label, "pt", filter, values);
  using study::MetricFormat;
  if (filter == "hashed")
    c.statistics = {{"hashed.accumulate_s_per_pass", "accumulate_s_per_pass", 1.0, MetricFormat::seconds},
                    {"hashed.lookup_s_per_pass", "lookup_s_per_pass", 1.0, MetricFormat::seconds},
                    {"hashed.occupancy", "occupancy_percent", 100.0, MetricFormat::percent}};
  if (filter == "consistent")
    c.statistics = {{"consistent.mean_neighbours", "mean_neighbours", 1.0, MetricFormat::number},
                    {"consistent.radius_scale", "radius_scale", 1.0, MetricFormat::number}};
  return c;
}

std::vector<study::MetricRow> filter_metric_rows(const std::string& filter) {
  using study::MetricFormat;
  if (filter == "hashed")
    return {{"accumulate_s_per_pass", "filter accumulate / pass", MetricFormat::seconds},
            {"lookup_s_per_pass", "filter lookup / pass", MetricFormat::seconds}};
  return {{"mean_neighbours", "mean vertices per ball", MetricFormat::number},
          {"radius_scale", "r(n) / r0, last batch", MetricFormat::number}};
}

study::PlotSeries rel_mse_series(const std::string& name, const std::vector<study::Measurement>& runs,
                                 const std::function<double(const study::Measurement&)>& x) {
  study::PlotSeries s;
  s.name = name;
  for (const study::Measurement& m : runs) s.points.push_back({x(m), m.error.rel_mse});
  return s;
}

}  // namespace pathspace::studies
