// ExperimentResult: what an experiment produced: its scenes (with their references) and every
// measurement in run order. experiment_output.h writes it as CSV, JSON and HTML.
#pragma once

#include <string>
#include <vector>

#include "pathspace/study/measurement.h"
#include "pathspace/study/prepared_scene.h"

namespace pathspace::study {

struct ExperimentResult {
  std::string name;
  std::vector<SceneSummary> scenes;
  std::vector<Measurement> measurements;
};

}  // namespace pathspace::study
