// RenderSession::run for a process group (docs/distributed.md): passes are dealt round-robin, rank r
// renders pass k·R + r of round k, skips the others (Integrator::skip_pass keeps the state of the
// passes it does not render), and the round's passes are added to the film in pass order by the
// slice owners (FilmExchange). Before each round the ranks agree whether to stop, so every rank ends
// after the same pass. At the end of the run rank 0 gathers the film, counters and debug images.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

#include "pathspace/base/error.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Reasons to stop, as bits of the agreement's maximum (any rank's reason stops all), and a request
// to gather the film onto rank 0 before the round (request_gather).
constexpr uint64_t kStopCount = 1, kStopTime = 2, kStopCancel = 4, kStopAny = 7, kGather = 8;

}  // namespace

RunResult RenderSession::run_distributed(const RunLimit& limit, const std::function<void(const RenderProgress&)>& on_progress) {
  const int ranks = group_->size(), me = group_->rank();
  const auto start = Clock::now();
  const bool timed = limit.passes == 0 && limit.seconds > 0.0;
  const bool counted = limit.passes > 0;
  RunResult result;
  const PathCounters at_start = counters_;
  double exchange_s = 0.0;
  RenderProgress last;
  while (true) {
    const uint32_t round = counted ? std::min<uint32_t>(uint32_t(ranks), limit.passes - result.passes) : uint32_t(ranks);
    // Every rank's clock and cancel() count; the maximum of the reasons is the same on every rank.
    const auto agree_start = Clock::now();
    std::vector<uint64_t> stop = {(counted && round == 0 ? kStopCount : 0) |
                                  (timed && result.passes > 0 && seconds_since(start) >= limit.seconds ? kStopTime : 0) |
                                  (cancel_.exchange(false) ? kStopCancel : 0) | (gather_requested_.exchange(false) ? kGather : 0)};
    group_->all_max(&stop);
    exchange_s += seconds_since(agree_start);
    if ((stop[0] & kStopAny) != 0) {  // the gather at the end serves a pending request too
      result.cancelled = (stop[0] & kStopCancel) != 0;
      break;
    }
    if ((stop[0] & kGather) != 0) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        gather_locked(exchange_s);
        exchange_s = 0.0;
      }
      if (on_progress) {
        RenderProgress g = last;
        g.gathered = true;
        on_progress(g);
      }
    }
    RenderProgress p;
    while (readers_waiting_.load() > 0) std::this_thread::yield();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto pass_start = Clock::now();
      PathCounters before_mine = counters_;
      for (uint32_t i = 0; i < round; ++i) {
        const uint32_t pass = passes_ + i;
        if (int(i) != me) {
          integrator_->skip_pass(pass, film_.pixel_count());
          continue;
        }
        before_mine = counters_;
        pass_film_.clear();
        render_tracked_pass_locked(pass, pass_film_);
        ++rank_passes_;
      }
      if (integrator_->reports_passes()) {
        const auto agree_start = Clock::now();
        const int mine = me < int(round) ? me : -1;
        std::vector<uint64_t> reports = group_->all_gather(mine >= 0 ? integrator_->pass_report() : 0);
        reports.resize(round);
        exchange_s += seconds_since(agree_start);
        if (integrator_->agree_round(passes_, reports, mine)) {
          // An earlier pass of the round changed what this one does (the integrator took it back).
          counters_ = before_mine;
          pass_film_.clear();
          integrator_->render_pass(passes_ + uint32_t(mine), pass_film_, counters_);
        }
      }
      const auto exchange_start = Clock::now();
      exchange_->add_round(pass_film_, int(round), &film_);
      exchange_s += seconds_since(exchange_start);
      passes_ += round;
      wall_s_ += seconds_since(pass_start);
      p.session_passes = passes_;
      p.rays = counters_.rays - at_start.rays;
      p.paths = counters_.paths - at_start.paths;
    }
    result.passes += round;
    if (on_progress) {
      p.passes_done = result.passes;
      p.passes_total = counted ? limit.passes : 0;
      p.elapsed_s = seconds_since(start);
      p.fraction = counted ? double(result.passes) / double(limit.passes) : timed ? std::min(1.0, p.elapsed_s / limit.seconds) : 0.0;
      last = p;
      on_progress(p);
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    gather_locked(exchange_s);
  }
  result.wall_s = seconds_since(start);
  return result;
}

void RenderSession::gather_locked(double exchange_s) {
  const auto start = Clock::now();
  exchange_->gather(&film_);
  integrator_->hand_over(*group_);
  std::vector<uint64_t> totals = {counters_.rays, counters_.shadow_rays, counters_.paths, counters_.dropped};
  group_->all_sum(&totals);
  job_counters_ = PathCounters{totals[0], totals[1], totals[2], totals[3]};
  rank_exchange_s_ += exchange_s + seconds_since(start);
  RankStats mine;
  mine.passes = rank_passes_;
  mine.threads = threads_;
  mine.wall_s = wall_s_;
  mine.exchange_s = rank_exchange_s_;
  mine.rays = counters_.rays;
  mine.paths = counters_.paths;
  mine.bytes_sent = exchange_->bytes_sent();
  std::vector<uint8_t> bytes(sizeof(RankStats));
  std::memcpy(bytes.data(), &mine, sizeof(RankStats));  // the same binary on every rank (join checks)
  const std::vector<std::vector<uint8_t>> all = group_->gather(bytes);
  ranks_.clear();
  for (const std::vector<uint8_t>& b : all) {
    if (b.size() != sizeof(RankStats)) throw Error("distributed render: a rank's statistics of the wrong size");
    RankStats r;
    std::memcpy(&r, b.data(), sizeof(RankStats));
    ranks_.push_back(r);
  }
}

}  // namespace pathspace
