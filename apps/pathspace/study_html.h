// The one-page HTML report of `pathspace study`: a table per PCLT paper figure with the renders, their
// false-colour error maps and numbers side by side. Self-contained: inline CSS, every PNG embedded
// once as a base64 data URI (CSS classes, so an image shown in several figures is stored once); no
// script and no external resource, so the page can be mailed or committed as it is.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study_pclt_figures.h"

namespace pathspace::cli {

// What the page shows about a scene once its StudyScene is gone.
struct StudySceneSummary {
  std::string id, name;
  size_t light_count = 0;
  std::string reference_png;
  nlohmann::ordered_json reference;  // StudyScene::reference_info
};

// Builds the page; images are read from out_dir (paths in the runs are relative to it).
std::string study_html(const std::string& out_dir, const std::string& title, const nlohmann::ordered_json& settings,
                       const std::vector<StudySceneSummary>& scenes, const std::vector<StudyFigure>& figures);

}  // namespace pathspace::cli
