#include "pathspace/study/experiment.h"

#include <fmt/format.h>

#include "pathspace/base/error.h"

namespace pathspace::study {

Configuration configuration(std::string label, RenderConfig render, Record settings) {
  Configuration c;
  c.label = std::move(label);
  c.render = std::move(render);
  c.settings = std::move(settings);
  return c;
}

Configuration configuration(std::string label, const std::string& integrator, const std::string& filter,
                            const OptionValues& options) {
  Record settings;
  if (filter != FilterChoice::kNone) settings.set("filter", filter);
  for (const auto& [name, value] : options.items()) {
    if (value.empty())
      settings.set(name, true);  // a flag
    else
      settings.set(name, value);
  }
  return configuration(std::move(label), configure_render(integrator, filter, options), std::move(settings));
}

void check_budget(const Budget& budget, const std::string& what) {
  if (budget.timed() && !budget.passes.empty()) throw Error(what + ": a budget is passes or seconds, not both");
  if (!budget.timed() && budget.passes.empty()) throw Error(what + ": the budget needs passes or seconds");
  uint32_t last = 0;
  for (uint32_t p : budget.passes) {
    if (p <= last) throw Error(fmt::format("{}: pass checkpoints must increase from 1 ({} after {})", what, p, last));
    last = p;
  }
}

void check_experiment(const Experiment& e) {
  const std::string what = "experiment '" + e.name + "'";
  if (e.scenes.empty()) throw Error(what + " has no scenes");
  if (e.configurations.empty()) throw Error(what + " has no configurations");
  if (e.seeds.empty()) throw Error(what + " has no seeds");
  check_budget(e.budget, what);
  if (e.reference.image_file.empty()) {
    check_composition(e.reference.render.integrator, e.reference.render.filter.name);
    check_budget(e.reference.budget, what + " reference");
  }
  for (const Configuration& c : e.configurations) {
    check_composition(c.render.integrator, c.render.filter.name);
    if (c.budget) check_budget(*c.budget, what + " '" + c.label + "'");
  }
}

}  // namespace pathspace::study
