// RenderSession: one render with state across passes. It owns (or shares) the scene and its
// acceleration structure, the integrator with its filter, and the film, and runs passes until a
// pass count, a time budget or cancel(). Between passes it can be snapshotted (images and
// statistics so far) and its whole state saved and restored, so a render can be continued bit for
// bit: run(4) + run(4) equals run(8), in one session or across a save_state()/restore_state().
// The CLI, the studies, the benchmarks and the tests all render through it.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "pathspace/film/film.h"
#include "pathspace/film/film_exchange.h"
#include "pathspace/film/image.h"
#include "pathspace/parallel/cancellable_work.h"
#include "pathspace/parallel/process_group.h"
#include "pathspace/session/render_config.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

class Accel;
class Integrator;
class Scene;

// How long one run() goes on. cancel() and the time budget take effect between passes; only
// abort() interrupts one.
struct RunLimit {
  uint32_t passes = 0;   // > 0: this many passes
  double seconds = 0.0;  // > 0: whole passes until this much wall time has passed (at least one)
  // Both 0: until cancel().
  static RunLimit for_passes(uint32_t n) { return {n, 0.0}; }
  static RunLimit for_seconds(double s) { return {0, s}; }
  static RunLimit until_cancelled() { return {0, 0.0}; }
};

// After every pass of a run.
struct RenderProgress {
  uint32_t passes_done = 0;   // in this run
  uint32_t passes_total = 0;  // of this run; 0 when time-limited or until cancelled
  uint32_t session_passes = 0;  // in the whole session (restored passes included)
  double elapsed_s = 0.0;     // of this run
  double fraction = 0.0;      // 0..1 of this run's passes or time budget; 0 until cancelled
  uint64_t rays = 0;          // in this run
  uint64_t paths = 0;
  // A distributed render: this call follows request_gather(), rank 0's film now holds every pass so
  // far (nothing was rendered since the previous call).
  bool gathered = false;
};

// While a pass runs (RenderSession::pass_progress, from any thread).
struct PassProgress {
  bool running = false;
  uint32_t pass = 0;      // 1-based index in the session
  double seconds = 0.0;   // since the pass started
  double fraction = 0.0;  // of the data-parallel work started so far in the pass (parallel/work_progress.h)
};

// One process of a distributed render (docs/distributed.md), as rank 0 reports it.
struct RankStats {
  uint32_t passes = 0;  // rendered by this rank
  int threads = 0;
  double wall_s = 0.0;     // in passes and the exchange
  double exchange_s = 0.0; // of which in the exchange and the stop agreement
  uint64_t rays = 0;
  uint64_t paths = 0;
  uint64_t bytes_sent = 0;
};

// The common counters of every render, plus the integrator's and filter's own statistics.
struct RenderStats {
  std::string integrator, filter;
  double wall_s = 0.0;  // time spent in passes, over all runs (and restored ones)
  uint32_t spp = 0;     // passes so far (samples per pixel for the camera-path integrators)
  uint64_t rays = 0;
  uint64_t shadow_rays = 0;
  uint64_t paths = 0;
  uint64_t dropped_samples = 0;  // NaN/Inf samples replaced by 0
  int threads = 0;
  uint64_t seed = 0;   // the session's (a frame's passes use frame_seed(seed, frame))
  uint64_t frame = 0;  // of an animation (begin_frame); 0 for a still render
  Statistics details;  // "<integrator or filter>.<what>" (Integrator::statistics); rank 0's in a distributed render
  // A distributed render, on rank 0: one entry per rank; the counters above are their totals.
  std::vector<RankStats> ranks;
  double mrays_per_s() const { return wall_s > 0 ? double(rays) / wall_s * 1e-6 : 0.0; }
  double paths_per_s() const { return wall_s > 0 ? double(paths) / wall_s : 0.0; }
};

// What a snapshot computes of the film: a sequence's frames skip the variance no file asks for.
enum class SnapshotImages { mean_and_variance, mean };

struct RenderSnapshot {
  Image mean, variance;          // the film's mean and variance of the mean (0x0 when not asked for)
  RenderStats stats;
  std::vector<NamedImage> aovs;  // the integrator's debug images, when its options asked for them
};

// One pixel of the film (RenderSession::pixel), as snapshot() shows it.
struct PixelStats {
  Rgb mean, variance_of_mean;
  uint32_t samples = 0;
};

struct RunResult {
  uint32_t passes = 0;  // run in this call
  double wall_s = 0.0;
  bool cancelled = false;
  bool aborted = false;  // abort() cut the last pass short: it was discarded (not in `passes`)
};

// The serializable state of a session: bytes of base/state_archive.h (session header, film sums,
// the integrator's and filter's own state). Restorable into a session with the same config and scene.
struct SessionState {
  std::vector<uint8_t> bytes;
};

// The seed of frame `frame`'s passes: the session's own for frame 0, so that frame 0 of an animation
// is the still render of its scene; a hash of both for the others.
uint64_t frame_seed(uint64_t seed, uint64_t frame);

class RenderSession {
 public:
  // Shares scene and accel (the session keeps them alive); a null accel is built from the scene.
  RenderSession(std::shared_ptr<const Scene> scene, std::shared_ptr<const Accel> accel, RenderConfig config);
  // Takes the scene (finalized) and builds its acceleration structure.
  RenderSession(Scene scene, RenderConfig config);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Renders with the processes of `group` from now on (before the first run; docs/distributed.md):
  // rank r renders passes r, r + R, ... and the films are reduced in pass order, so the image is
  // bit-identical to one process's. Collective: every rank's options, seed and scene, plus
  // `identity` (the caller's own: the binary, its image options), must agree, or every rank throws.
  void join(std::shared_ptr<ProcessGroup> group, const std::string& identity);
  // The rank of this process (0 without a group). Only rank 0 holds the whole film after a run.
  int rank() const { return group_ ? group_->rank() : 0; }

  // Runs passes until `limit` or cancel(); calls on_progress after each pass (outside the lock).
  // In a group: after each round of R passes, and collective; all ranks stop after the same round.
  RunResult run(const RunLimit& limit, const std::function<void(const RenderProgress&)>& on_progress = {});
  // Thread-safe. The current pass finishes, then run() returns. A cancel() while no run is going on
  // stops the next run before its first pass.
  void cancel();
  // Thread-safe. Like cancel(), but the pass in flight also stops early (its loops skip what they
  // have not started: parallel/cancellable_work.h), for a viewer whose camera moved. The pass is
  // discarded, and the film with it: until begin_frame() the session has no image, so run(),
  // snapshot() and save_state() throw. begin_frame() carries the filter only when the cut came
  // before the pass reached it (Integrator::carried_filter_after_abort), else starts it afresh: the
  // cut pass may have left its table half updated. A distributed run, whose
  // ranks must agree on every pass, treats abort() as cancel().
  void abort();
  // An aborted pass left the film incomplete (abort()); begin_frame() clears it.
  bool aborted() const;
  // Thread-safe. A distributed run gathers the film (and what Integrator::hand_over sums) onto rank
  // 0 at the next round boundary, when any rank asked, then calls on_progress with `gathered`: the
  // periodic writes of rank 0 (the CLI's --write-every, --checkpoint-every). Without a group the
  // film is always whole and this does nothing.
  void request_gather();
  bool distributed() const { return group_ && group_->size() > 1; }

  // Thread-safe; during a run it waits for the current pass to end (the run goes on).
  RenderSnapshot snapshot(SnapshotImages images = SnapshotImages::mean_and_variance) const;
  RenderStats stats() const;
  // Thread-safe, as snapshot(), for one pixel (a viewer's pixel inspector); throws pathspace::Error
  // outside the image and after an aborted pass.
  PixelStats pixel(int x, int y) const;
  SessionState save_state() const;
  // Before or between runs. Throws pathspace::Error when the state belongs to another integrator,
  // filter, option values, seed, scene or image size, or is damaged; the session is then unchanged.
  void restore_state(const SessionState& state);

  // Starts frame `frame` of an animation with this scene (same image size): a new film and pass
  // count, a new integrator seeded with frame_seed(seed, frame), and the path space filter carried
  // over with its table (Integrator::carried_filter; 2021 paper sec. 3.4). The scene is validated
  // (scene_warnings()); a null accel is built, reusing the part of the previous frame's that does not
  // move (accel/accel.h), or kept when the scene is the session's own.
  // Between runs. A session that began a frame cannot save its state (checkpoints hold one frame).
  void begin_frame(std::shared_ptr<const Scene> scene, std::shared_ptr<const Accel> accel, uint64_t frame);
  uint64_t frame() const;
  // Integrator::frame_warm_up of this session's integrator.
  uint32_t frame_warm_up() const;

  uint32_t passes_done() const;
  // Lock-free: how far the pass in progress is. Its fraction counts the loops that have started,
  // so a pass made of several loops (trace, filter, resolve) can step back when the next one starts.
  PassProgress pass_progress() const;
  const RenderConfig& config() const { return config_; }
  // The warnings of the scene's validation (scene/scene_validation.h), which every session runs
  // before the scene reaches Embree: a scene with an out-of-range value is an Error at construction.
  const std::vector<std::string>& scene_warnings() const { return scene_warnings_; }
  const Scene& scene() const { return *scene_; }
  const Accel& accel() const { return *accel_; }
  // The acceleration structure shared, for another session on the same scene (between runs).
  std::shared_ptr<const Accel> shared_accel() const;

 private:
  RenderStats stats_locked() const;
  RunResult run_distributed(const RunLimit& limit, const std::function<void(const RenderProgress&)>& on_progress);
  // Renders pass `pass` into `film` with the lock held, published to pass_progress() while it runs
  // (run() and run_distributed() alike).
  void render_tracked_pass_locked(uint32_t pass, Film& film);
  // Rank 0 receives the film slices, the ranks' counters and the integrator's hand-over.
  void gather_locked(double exchange_s);
  void keep_restored_on_rank0();
  // Holds the lock for a reader (snapshot, stats, save_state); run() lets waiting readers go first.
  class ReaderLock {
   public:
    explicit ReaderLock(const RenderSession& s) : s_(s) {
      ++s_.readers_waiting_;
      s_.mutex_.lock();
      --s_.readers_waiting_;
    }
    ~ReaderLock() { s_.mutex_.unlock(); }
    ReaderLock(const ReaderLock&) = delete;
    ReaderLock& operator=(const ReaderLock&) = delete;

   private:
    const RenderSession& s_;
  };

  std::shared_ptr<const Scene> scene_;
  std::vector<std::string> scene_warnings_;  // before accel_: the scene is validated before it is built
  std::shared_ptr<const Accel> accel_;
  RenderConfig config_;
  std::unique_ptr<Integrator> integrator_;
  Film film_;
  PathCounters counters_;
  uint32_t passes_ = 0;
  double wall_s_ = 0.0;
  uint64_t frame_ = 0;
  bool in_sequence_ = false;  // begin_frame was called
  int threads_ = 0;
  mutable std::mutex mutex_;  // held while a pass renders and while the film is read
  mutable std::atomic<int> readers_waiting_{0};
  std::atomic<bool> cancel_{false};
  CancellableWork pass_work_;  // the pass in flight, for abort()
  bool aborted_ = false;       // under mutex_: see abort()
  std::atomic<bool> gather_requested_{false};
  // Distributed rendering (join): the group, the slice exchange, this rank's pass of a round, and on
  // rank 0 after a run every rank's statistics.
  std::shared_ptr<ProcessGroup> group_;
  std::unique_ptr<FilmExchange> exchange_;
  Film pass_film_{0, 0};
  uint32_t rank_passes_ = 0;
  double rank_exchange_s_ = 0.0;
  std::vector<RankStats> ranks_;
  PathCounters job_counters_;  // every rank's, summed
  // The pass in progress (pass_progress): its 1-based index (0: none), start time and the work
  // counters when it started.
  std::atomic<uint32_t> running_pass_{0};
  std::atomic<int64_t> pass_start_ns_{0};
  std::atomic<uint64_t> pass_work_started_{0}, pass_work_done_{0};
};

}  // namespace pathspace
