// `pathspace study psf`: the figures of both path space filtering papers (psf_figures.h; the 2014
// paper's in studies/psf2014/, the 2021 paper's in studies/psf2021/) and the equal-time comparison,
// on one page (docs/hashed-filter.md, docs/consistent-filter.md).
#pragma once

#include "studies/common/study_options.h"

namespace pathspace::studies {

// Throws UsageError for invalid options, pathspace::Error for failures; returns the exit status.
int run_psf_study(const StudyOptions& options, const PsfStudyOptions& psf_options);

}  // namespace pathspace::studies
