// `pathspace study pclt`: the PCLT paper's figures (pclt_figures.h) on each scene in turn, written as
// study.json and study.html (docs/pclt.md).
#pragma once

#include "studies/common/study_options.h"

namespace pathspace::studies {

// Throws UsageError for invalid options, pathspace::Error for failures; returns the exit status.
int run_pclt_study(const StudyOptions& options);

}  // namespace pathspace::studies
