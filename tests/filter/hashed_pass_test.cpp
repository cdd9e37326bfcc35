// The hashed filter's pass sequence (hashed_pass.h), which both devices run: which steps run for
// which settings and in which order, the step numbers the histories see, and how one pass's counts
// and times land in the statistics. A recording device stands in for the CPU's and the GPU's steps.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pathspace/filters/hashed/hashed_pass.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {
namespace {

class RecordingSteps final : public HashedPassSteps {
 public:
  std::vector<std::string> calls;
  uint64_t failures = 0;
  bool cells_change_hands = true;
  HashedPassCounts counts;

  void mark(PassMark at) override { times[int(at)] = 10.0 * (int(at) + 1) + int(at) * int(at); }
  void clear() override { calls.push_back("clear"); }
  void accumulate(uint64_t) override { calls.push_back("accumulate"); }
  uint64_t probe_failures() override { return failures; }
  bool settle_overflows(uint64_t, uint64_t n) override {
    calls.push_back("settle " + std::to_string(n));
    return cells_change_hands;
  }
  void list_step_cells() override { calls.push_back("list"); }
  void transfer_levels(uint64_t, uint32_t step) override { calls.push_back("transfer " + std::to_string(step)); }
  void exchange_probes(uint64_t, uint32_t pass) override { calls.push_back("probes " + std::to_string(pass)); }
  void lookup(uint64_t) override { calls.push_back("lookup"); }
  void end_step(uint32_t step) override { calls.push_back("end_step " + std::to_string(step)); }
  HashedPassCounts finish() override {
    calls.push_back("finish");
    return counts;
  }
  double milliseconds(PassMark from, PassMark to) const override { return times[int(to)] - times[int(from)]; }

 private:
  double times[int(PassMark::count)] = {};
};

std::string joined(const std::vector<std::string>& calls) {
  std::string s;
  for (const std::string& c : calls) s += (s.empty() ? "" : ", ") + c;
  return s;
}

TEST(HashedPass, WithoutHistoryEveryPassClearsAccumulatesAndLooksUp) {
  RecordingSteps steps;
  HashedFilterStats stats;
  run_hashed_pass(steps, HashedFilterSettings{}, 1, 0, &stats);
  EXPECT_EQ(joined(steps.calls), "clear, accumulate, list, lookup, finish");
  EXPECT_EQ(stats.passes, 1u);
  EXPECT_EQ(stats.steps, 0u);
  EXPECT_EQ(stats.settled_passes, 0u);
}

TEST(HashedPass, ProbeWindowsAreSettledOnlyWhenOneCacheLineAndSomethingFailed) {
  HashedFilterSettings settings;
  RecordingSteps failed;
  failed.failures = 3;
  HashedFilterStats stats;
  run_hashed_pass(failed, settings, 1, 0, &stats);
  EXPECT_EQ(joined(failed.calls), "clear, accumulate, settle 3, list, lookup, finish");
  EXPECT_EQ(stats.settled_passes, 1u);

  RecordingSteps nothing_changed;  // the decision kept every cell with its key: not a settled pass
  nothing_changed.failures = 3;
  nothing_changed.cells_change_hands = false;
  run_hashed_pass(nothing_changed, settings, 1, 1, &stats);
  EXPECT_EQ(stats.settled_passes, 1u);

  settings.max_probes = 2 * kFingerprintsPerLine;  // windows beyond a line: no deterministic settling
  RecordingSteps long_windows;
  long_windows.failures = 3;
  run_hashed_pass(long_windows, settings, 1, 0, &stats);
  EXPECT_EQ(joined(long_windows.calls), "clear, accumulate, list, lookup, finish");
}

TEST(HashedPass, TemporalStepsSeeTheHistoriesClock) {
  HashedFilterSettings settings;
  settings.temporal.mode = TemporalMode::integrate;
  HashedFilterStats stats;
  stats.steps = 6;  // e.g. restored from a checkpoint
  RecordingSteps steps;
  run_hashed_pass(steps, settings, 1, 0, &stats);
  EXPECT_EQ(joined(steps.calls), "clear, accumulate, list, transfer 6, lookup, end_step 7, finish");
  EXPECT_EQ(stats.steps, 7u);

  settings.temporal.level_transfer = false;
  RecordingSteps without_transfer;
  run_hashed_pass(without_transfer, settings, 1, 0, &stats);
  EXPECT_EQ(joined(without_transfer.calls), "clear, accumulate, list, lookup, end_step 8, finish");
}

TEST(HashedPass, HybridProbesAreExchangedInAFramesFirstPassOnly) {
  HashedFilterSettings settings;
  settings.temporal.mode = TemporalMode::hybrid;
  HashedFilterStats stats;
  RecordingSteps first, second;
  run_hashed_pass(first, settings, 1, 0, &stats);
  run_hashed_pass(second, settings, 1, 1, &stats);
  EXPECT_EQ(joined(first.calls), "clear, accumulate, list, transfer 0, probes 0, lookup, end_step 1, finish");
  EXPECT_EQ(joined(second.calls), "clear, accumulate, list, transfer 1, lookup, end_step 2, finish");
}

TEST(HashedPass, CountsAndTimesAddUpOverPasses) {
  HashedFilterSettings settings;
  settings.temporal.mode = TemporalMode::ema;
  HashedFilterStats stats;
  for (int pass = 0; pass < 2; ++pass) {
    RecordingSteps steps;
    steps.failures = 1;
    steps.counts.vertices = 100;
    steps.counts.insertions = 40;
    steps.counts.probes = 50;
    steps.counts.probes_max = 3u + uint64_t(pass);
    steps.counts.failures = 2;
    steps.counts.blended = 80;
    steps.counts.alpha_fixed = uint64_t(0.5 * 80 * 4294967296.0);
    steps.counts.evicted = 5;
    steps.counts.occupied_cells = 30;
    run_hashed_pass(steps, settings, 7, uint32_t(pass), &stats);
  }
  EXPECT_EQ(stats.passes, 2u);
  EXPECT_EQ(stats.vertices, 200u);
  EXPECT_EQ(stats.insertions, 80u);
  EXPECT_EQ(stats.probes_total, 100u);
  EXPECT_EQ(stats.probes_max, 4u);
  EXPECT_EQ(stats.probe_failures, 4u);
  EXPECT_EQ(stats.probe_failures_last, 2u);
  EXPECT_EQ(stats.blended, 160u);
  EXPECT_DOUBLE_EQ(stats.alpha_sum, 80.0);
  EXPECT_DOUBLE_EQ(stats.mean_alpha_last, 0.5);
  EXPECT_EQ(stats.evicted, 10u);
  EXPECT_EQ(stats.evicted_last, 5u);
  EXPECT_EQ(stats.occupied_cells_last, 30u);
  // mark(m) notes 10 (m + 1) + m^2: clear is begin..cleared; accumulate is cleared..accumulated,
  // the settling (accumulated..settled) and listing the cells (settled..listed); the lookup is
  // transferred..looked_up; the temporal bookkeeping listed..transferred and looked_up..end.
  const auto at = [](PassMark m) { return 10.0 * (int(m) + 1) + int(m) * int(m); };
  const auto span = [&](PassMark a, PassMark b) { return at(b) - at(a); };
  EXPECT_DOUBLE_EQ(stats.clear_ms_last, span(PassMark::begin, PassMark::cleared));
  EXPECT_DOUBLE_EQ(stats.settle_ms_last, span(PassMark::accumulated, PassMark::settled));
  EXPECT_DOUBLE_EQ(stats.accumulate_ms_last, span(PassMark::cleared, PassMark::listed));
  EXPECT_DOUBLE_EQ(stats.lookup_ms_last, span(PassMark::transferred, PassMark::looked_up));
  EXPECT_DOUBLE_EQ(stats.temporal_ms_last,
                   span(PassMark::listed, PassMark::transferred) + span(PassMark::looked_up, PassMark::end));
  EXPECT_DOUBLE_EQ(stats.clear_ms, 2 * stats.clear_ms_last);
  EXPECT_DOUBLE_EQ(stats.temporal_ms, 2 * stats.temporal_ms_last);
}

}  // namespace
}  // namespace pathspace
