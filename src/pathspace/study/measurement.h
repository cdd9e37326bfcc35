// Measurement: one result of an experiment: a configuration rendered on a scene with a seed, up to
// a budget or checkpoint, measured against the scene's reference. It becomes a JSON object
// (to_json), a table row (to_record) and a column of the HTML page.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "pathspace/film/image.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/study/record.h"

namespace pathspace::study {

struct Measurement {
  std::string experiment, scene_id, label, integrator, filter;
  Record settings;             // Configuration::settings
  uint64_t seed = 0;
  double time_budget_s = 0.0;  // 0 for pass budgets
  double time_s = 0.0;         // wall time of the passes so far
  uint32_t iterations = 0;     // passes so far (spp for the camera-path integrators)
  ImageError error;            // against the scene's reference
  // Minus the reference's own variance (film/image_metrics.h); equal to the plain ones without it.
  double rel_mse_debiased = 0.0, mse_debiased = 0.0;
  // The configuration's statistics (StatisticMetric columns), the experiment's image metrics and
  // whatever a study adds from the numbers (fig. 6: error against another run's image).
  Record metrics;
  std::string image_png, error_png, image_exr;  // relative to the output folder; empty when not written
  std::string same_render_as;  // another experiment whose identical render this lists again (reuse)
  Image image;                 // the mean image (RunnerOptions::keep_images; always during on_measurement)
};

// The same render listed again under another experiment and label (no new render).
Measurement reuse(const Measurement& m, const std::string& experiment, const std::string& label);

// scene, label, integrator, [filter], seed, settings, [time_budget_s], time_s, iterations, rel_mse,
// rel_mse_debiased, mse, mean, mean_reference, metrics, image_png, error_png, [image_exr], [same_render_as].
nlohmann::ordered_json to_json(const Measurement& m);

// The flat row: experiment, scene, label, integrator, filter, seed, the settings' fields,
// time_budget_s, time_s, iterations, rel_mse, rel_mse_debiased, mse, mse_debiased, mean,
// mean_reference, the metrics' fields, image_png, error_png, image_exr. Settings and metrics should
// not reuse these names (a field set again replaces the earlier one).
Record to_record(const Measurement& m);

}  // namespace pathspace::study
