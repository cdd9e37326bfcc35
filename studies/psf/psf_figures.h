// `pathspace study psf`: the figures of the two path space filtering papers as the study reproduces
// them on built-in scenes, one function per figure, on the study harness (src/pathspace/study/):
//   Keller, Dahm, Binder 2014 (--filter consistent): fig. 2 iterated averaging, fig. 3 progressive
//     filtering, fig. 4 the similarity weights, fig. 7 anti-aliasing on filter-fence, sec. 2.3 photon-mapped caustics (studies/psf2014/figures_2014.cpp);
//   Binder, Fricke, Keller 2021 (--filter hashed): fig. 1 one path per pixel, fig. 4 voxel size,
//     fig. 10 second-bounce filtering, and the 2019 short version's figs. 7 and 8 (hash collisions,
//     filter time) on fixed vertex sets (studies/psf2021/figures_2021.cpp);
//   equal-time comparisons neither paper has, at the hashed filter's time for 1, 4 and 16 paths per
//     pixel: PT, PT + hashed, PT + consistent and PT followed by an edge-avoiding à-trous filter in
//     screen space (studies/psf/equal_time.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "pathspace/options/option_values.h"
#include "pathspace/study/figure.h"
#include "pathspace/study/svg_plot.h"
#include "studies/common/study_options.h"

namespace pathspace::studies {

struct PsfStudyParams {
  uint64_t seed = 0;     // of every run (the reference has its own)
  uint32_t max_spp = 64; // 2014 fig. 3's last checkpoint
  std::vector<uint32_t> equal_time_spp = {1, 4, 16};  // PsfStudyOptions::equal_time_spp
};

// Every section in page order, with its texts and no runs yet.
// equal_time_spp: one equal-time figure per count ("equal-time-4spp").
std::vector<study::Figure> make_psf_figures(const std::vector<uint32_t>& equal_time_spp);
// The id of the equal-time figure at the hashed filter's `spp` paths per pixel.
std::string equal_time_figure_id(uint32_t spp);

// Per scene (each appends its runs, findings and plots to its figure).
void run_2014_fig2(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2014_fig3(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2014_fig4(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2014_sec23(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
// Once per study, on the built-in filter-fence scene.
void run_2014_fig7(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2021_fig1(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2021_fig4(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_2021_fig10(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
void run_equal_time(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures);
// Once per study: 2019 figs. 7 and 8 on cornell-box vertex sets of width x height.
void run_hash_table_figures(int width, int height, int threads, bool quiet, std::vector<study::Figure>* figures);

// Once per study: the hashed filter's table across frames (2021 sec. 3.4; studies/psf2021/temporal_figures.cpp):
// the orbit on a static scene (3.4.1), the moving light of fig. 9, the eviction flight (3.4.3).
// Each adds its figure's runs, plots and tables; the frames' references become scene entries of
// their own (ids "<scene>-orbit-f<N>", "ml_c-f<N>"), so that the page shows each frame's renders
// beside that frame's reference.
struct TemporalStudyParams {
  int width = 128, height = 128;
  uint64_t seed = 0;
  double reference_s = 60.0;  // the study's per-scene reference time, shared by the frames' references
  uint32_t frames = 64;       // 0: skip the orbit and fig. 9
  uint32_t eviction_frames = 10000;  // 0: skip the eviction flight
  std::string room_scene;     // resolved path of scenes/textured-room/scene.pbrt
};
// The textured-room file: `given` when it exists, else relative to the folders above the binary
// (build/apps/pathspace/ in the repository); throws UsageError naming --room-scene when neither.
std::string resolve_room_scene(const std::string& given);
void run_temporal_figures(const study::ExperimentRunner& runner, const TemporalStudyParams& params,
                          std::vector<study::Figure>* figures, std::vector<study::SceneSummary>* scenes);

// Shared by the figure files: a PT configuration with a filter and options given by name, as the CLI
// takes them ({"psf-iterations", "2"}; a flag has an empty value).
study::Configuration pt_with(const std::string& label, const std::string& filter,
                             std::initializer_list<std::pair<std::string, std::string>> options = {});
// The filter's statistics that pt_with collects, as table rows ("hashed" or "consistent").
std::vector<study::MetricRow> filter_metric_rows(const std::string& filter);
// relMSE of the runs against x(run), one series.
study::PlotSeries rel_mse_series(const std::string& name, const std::vector<study::Measurement>& runs,
                                 const std::function<double(const study::Measurement&)>& x);

}  // namespace pathspace::studies
