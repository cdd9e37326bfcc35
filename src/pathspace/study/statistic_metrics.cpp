#include "pathspace/study/statistic_metrics.h"

#include <cmath>

#include "pathspace/base/error.h"

namespace pathspace::study {

void collect_statistics(const Statistics& stats, const std::vector<StatisticMetric>& wanted, Record* metrics) {
  for (const StatisticMetric& w : wanted) {
    const Statistic& s = stats.at(w.statistic);  // throws when not reported
    switch (s.kind) {
      case StatKind::histogram:
        throw Error("statistic '" + w.statistic + "' is a histogram, not a metric");
      case StatKind::text:
        metrics->set(w.name(), s.text);
        break;
      case StatKind::counter:
      case StatKind::bytes:
        if (w.scale == 1.0) {
          metrics->set(w.name(), int64_t(std::llround(s.number)));
          break;
        }
        [[fallthrough]];
      default:
        metrics->set(w.name(), s.number * w.scale);
    }
  }
}

}  // namespace pathspace::study
