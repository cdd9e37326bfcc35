#include "pathspace/session/render_session.h"

#include <algorithm>
#include <chrono>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/base/state_archive.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {

std::unique_ptr<Integrator> create_integrator(const Scene& scene, const Accel& accel, const RenderConfig& config) {
  check_composition(config.integrator, config.filter.name);
  const IntegratorContext context{scene, accel, config.seed, config.filter};
  return integrator_registry().at(config.integrator).create(context, config.settings);
}

}  // namespace

RenderSession::RenderSession(std::shared_ptr<const Scene> scene, std::shared_ptr<const Accel> accel, RenderConfig config)
    : scene_(std::move(scene)),
      accel_(accel ? std::move(accel) : std::make_shared<const Accel>(*scene_)),
      config_(std::move(config)),
      integrator_(create_integrator(*scene_, *accel_, config_)),
      film_(scene_->camera.width, scene_->camera.height) {}

RenderSession::RenderSession(Scene scene, RenderConfig config)
    : RenderSession(std::make_shared<const Scene>(std::move(scene)), nullptr, std::move(config)) {}

RenderSession::~RenderSession() = default;

RunResult RenderSession::run(const RunLimit& limit, const std::function<void(const RenderProgress&)>& on_progress) {
  if (limit.passes == 0 && !(limit.seconds >= 0.0)) throw Error("the time budget must not be negative");
  ThreadLimit thread_limit(config_.threads);
  threads_ = ThreadLimit::active();
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const bool timed = limit.passes == 0 && limit.seconds > 0.0;
  const bool counted = limit.passes > 0;

  RunResult result;
  const PathCounters at_start = counters_;
  while (true) {
    if (cancel_.exchange(false)) {
      result.cancelled = true;
      break;
    }
    if (counted && result.passes >= limit.passes) break;
    if (timed && result.passes > 0 && elapsed() >= limit.seconds) break;
    RenderProgress p;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto pass_start = std::chrono::steady_clock::now();
      integrator_->render_pass(passes_, film_, counters_);
      ++passes_;
      wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - pass_start).count();
      p.session_passes = passes_;
      p.rays = counters_.rays - at_start.rays;
      p.paths = counters_.paths - at_start.paths;
    }
    ++result.passes;
    if (on_progress) {
      p.passes_done = result.passes;
      p.passes_total = counted ? limit.passes : 0;
      p.elapsed_s = elapsed();
      p.fraction = counted ? double(result.passes) / double(limit.passes)
                   : timed ? std::min(1.0, p.elapsed_s / limit.seconds)
                           : 0.0;
      on_progress(p);
    }
  }
  result.wall_s = elapsed();
  return result;
}

void RenderSession::cancel() { cancel_.store(true); }

uint32_t RenderSession::passes_done() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return passes_;
}

RenderStats RenderSession::stats_locked() const {
  RenderStats s;
  s.integrator = config_.integrator;
  s.filter = config_.filter.name;
  s.wall_s = wall_s_;
  s.spp = passes_;
  s.rays = counters_.rays;
  s.shadow_rays = counters_.shadow_rays;
  s.paths = counters_.paths;
  s.dropped_samples = counters_.dropped;
  s.threads = threads_ > 0 ? threads_ : ThreadLimit::active();
  s.seed = config_.seed;
  integrator_->statistics(s.details);
  return s;
}

RenderStats RenderSession::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_locked();
}

RenderSnapshot RenderSession::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  RenderSnapshot snap;
  snap.mean = film_.mean();
  snap.variance = film_.variance_of_mean();
  snap.stats = stats_locked();
  snap.aovs = integrator_->aovs();
  return snap;
}

SessionState RenderSession::save_state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  StateWriter out;
  out.put_string("session.integrator", config_.integrator);
  out.put_string("session.filter", config_.filter.name);
  out.put("session.seed", config_.seed);
  out.put("session.passes", passes_);
  out.put("session.counters", counters_);
  out.put("session.wall_s", wall_s_);
  film_.save_state(out);
  integrator_->save_state(out);
  return {out.take()};
}

void RenderSession::restore_state(const SessionState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  StateReader in(state.bytes);
  const std::string integrator = in.get_string("session.integrator");
  const std::string filter = in.get_string("session.filter");
  uint64_t seed = 0;
  in.get("session.seed", &seed);
  if (integrator != config_.integrator || filter != config_.filter.name || seed != config_.seed)
    throw Error("render state: made by --integrator " + integrator + " --filter " + filter + " --seed " + std::to_string(seed) +
                ", this render is --integrator " + config_.integrator + " --filter " + config_.filter.name + " --seed " +
                std::to_string(config_.seed));
  // Read into fresh objects first, so that a damaged state leaves this session as it was.
  uint32_t passes = 0;
  PathCounters counters;
  double wall_s = 0.0;
  in.get("session.passes", &passes);
  in.get("session.counters", &counters);
  in.get("session.wall_s", &wall_s);
  Film film(film_.width(), film_.height());
  film.load_state(in);
  std::unique_ptr<Integrator> restored = create_integrator(*scene_, *accel_, config_);
  restored->load_state(in);
  if (!in.at_end()) throw Error("render state: unexpected data after the integrator's state");
  passes_ = passes;
  counters_ = counters;
  wall_s_ = wall_s;
  film_ = std::move(film);
  integrator_ = std::move(restored);
}

}  // namespace pathspace
