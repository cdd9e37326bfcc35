#include "pathspace/study/measurement.h"

namespace pathspace::study {

Measurement reuse(const Measurement& m, const std::string& experiment, const std::string& label) {
  Measurement r = m;
  r.same_render_as = m.experiment;
  r.experiment = experiment;
  r.label = label;
  return r;
}

nlohmann::ordered_json to_json(const Measurement& m) {
  nlohmann::ordered_json j;
  j["scene"] = m.scene_id;
  j["label"] = m.label;
  j["integrator"] = m.integrator;
  if (!m.filter.empty() && m.filter != "none") j["filter"] = m.filter;
  j["seed"] = m.seed;
  j["settings"] = to_json(m.settings);
  if (m.time_budget_s > 0) j["time_budget_s"] = m.time_budget_s;
  j["time_s"] = m.time_s;
  j["iterations"] = m.iterations;
  j["rel_mse"] = m.error.rel_mse;
  j["rel_mse_debiased"] = m.rel_mse_debiased;
  j["mse"] = m.error.mse;
  j["mean"] = m.error.mean_image;
  j["mean_reference"] = m.error.mean_reference;
  j["metrics"] = to_json(m.metrics);
  j["image_png"] = m.image_png;
  j["error_png"] = m.error_png;
  if (!m.image_exr.empty()) j["image_exr"] = m.image_exr;
  if (!m.same_render_as.empty()) j["same_render_as"] = m.same_render_as;
  return j;
}

Record to_record(const Measurement& m) {
  Record r;
  r.set("experiment", m.experiment);
  r.set("scene", m.scene_id);
  r.set("label", m.label);
  r.set("integrator", m.integrator);
  r.set("filter", m.filter.empty() ? std::string("none") : m.filter);
  r.set("seed", m.seed);
  r.merge(m.settings);
  if (m.time_budget_s > 0) r.set("time_budget_s", m.time_budget_s);
  r.set("time_s", m.time_s);
  r.set("iterations", m.iterations);
  r.set("rel_mse", m.error.rel_mse);
  r.set("rel_mse_debiased", m.rel_mse_debiased);
  r.set("mse", m.error.mse);
  r.set("mse_debiased", m.mse_debiased);
  r.set("mean", m.error.mean_image);
  r.set("mean_reference", m.error.mean_reference);
  r.merge(m.metrics);
  if (!m.image_png.empty()) r.set("image_png", m.image_png);
  if (!m.error_png.empty()) r.set("error_png", m.error_png);
  if (!m.image_exr.empty()) r.set("image_exr", m.image_exr);
  return r;
}

}  // namespace pathspace::study
