// The statistics a configuration requires (StatisticMetric), read from a render's typed statistics
// (stats/statistics.h) into metrics. Missing is an error, never 0.
#pragma once

#include <vector>

#include "pathspace/stats/statistics.h"
#include "pathspace/study/experiment.h"
#include "pathspace/study/record.h"

namespace pathspace::study {

// Sets one metric per requested statistic: counters and byte sizes at scale 1 as integers, other
// numbers times the scale, text as text. Throws pathspace::Error when a statistic was not reported
// (naming what was) or is a histogram.
void collect_statistics(const Statistics& stats, const std::vector<StatisticMetric>& wanted, Record* metrics);

}  // namespace pathspace::study
