// Error vs samples per pixel with and without hashed path space filtering (Binder et al. 2021,
// sec. 4 / fig. 1: 1 path per pixel filtered vs a 1024 spp reference). Renders cornell-box at the
// reference's size (512x512) progressively (each pass filtered, then accumulated) and records the
// relMSE and MSE against a reference image after 1, 2, 4, ..., 64 spp, for several seeds: an
// experiment on the harness (src/pathspace/study/), one session per configuration and seed measured
// at each checkpoint. The filtered error at high spp is the bias the filter leaves (it no longer
// falls with 1/spp).
// Usage: psf_convergence REFERENCE.exr [REFERENCE_VARIANCE.exr] [OUT.csv]
#include <cstdio>
#include <string>

#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/io/image_io.h"
#include "pathspace/study/experiment_output.h"
#include "pathspace/study/experiment_runner.h"

using namespace pathspace;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: psf_convergence REFERENCE.exr [REFERENCE_VARIANCE.exr] [OUT.csv]\n");
    return 2;
  }
  const bool has_variance = argc > 2 && std::string(argv[2]) != "-";
  const std::string out = argc > 3 ? argv[3] : "docs/figures/psf_convergence.csv";
  const Image reference = read_image(argv[1]);  // for its size

  study::Experiment e;
  e.name = "psf_convergence";
  e.scenes = {{"cornell-box", reference.width, reference.height}};
  e.reference.image_file = argv[1];
  if (has_variance) e.reference.variance_file = argv[2];
  e.seeds = {1, 2, 3, 4};
  e.budget = study::Budget::at_passes({1, 2, 4, 8, 16, 32, 64});
  RenderConfig pt;
  pt.integrator = "pt";
  study::Record unfiltered;
  unfiltered.set("psf_scale", 0.0);
  e.configurations.push_back(study::configuration("none", pt, unfiltered));
  for (const float scale : {6.f, 12.f, 20.f}) {
    HashedFilterSettings s;
    s.key.psf_scale = scale;
    study::Record settings;
    settings.set("psf_scale", scale);
    e.configurations.push_back(study::configuration("hashed", with_filter(pt, "hashed", s), settings));
  }

  study::RunnerOptions options;
  options.quiet = true;
  options.on_measurement = [](const study::Measurement& m) {
    std::fprintf(stderr, "%s scale %g seed %d spp %u: relMSE %.4g\n", m.label.c_str(), m.settings.number("psf_scale"),
                 int(m.seed), m.iterations, m.rel_mse_debiased);
  };
  const study::ExperimentResult result = study::ExperimentRunner(options).run(e);

  // The relMSE and MSE are debiased by the reference's variance when it is given.
  study::Table table = study::results_table(result);
  table.column("filter").column("psf_scale").column("seed").column("spp", "", "iterations");
  table.column("rel_mse", "{:.6g}", "rel_mse_debiased").column("mse", "{:.6g}", "mse_debiased").column("seconds", "{:.3f}", "time_s");
  study::write_csv(out, table);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
