#include "pathspace/session/render_session.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/base/fnv1a.h"
#include "pathspace/base/state_archive.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace {

namespace {

// The integrator's and filter's option values: a continued render must use the options it began with.
std::string settings_fingerprint(const RenderConfig& config) {
  std::string out = integrator_registry().at(config.integrator).schema.describe(config.settings);
  if (config.filter.active()) out += " | " + filter_registry().at(config.filter.name).schema.describe(config.filter.settings);
  return out;
}

// What distinguishes one scene from another of the same image size, cheaply: its name, sizes, bounds
// and a hash of its vertex positions, at shutter close too in a scene that moves (material parameters
// are not compared). A still scene's fingerprint is what it was before motion blur.
std::string scene_fingerprint(const Scene& scene) {
  const BoundingSphere b = scene.bounds();
  const uint64_t hash = fnv1a64(scene.positions.data(), scene.positions.size() * sizeof(Vec3));  // floats: no padding
  const std::string motion =
      scene.positions_end.empty()
          ? std::string()
          : " end_position_hash=" + std::to_string(fnv1a64(scene.positions_end.data(), scene.positions_end.size() * sizeof(Vec3)));
  return "name=" + scene.name + " position_hash=" + std::to_string(hash) + motion + " positions=" + std::to_string(scene.positions.size()) + " triangles=" + std::to_string(scene.triangles.size()) +
         " spheres=" + std::to_string(scene.spheres.size()) + " materials=" + std::to_string(scene.materials.size()) +
         " lights=" + std::to_string(scene.lights.size()) + " max_segments=" + std::to_string(scene.max_path_segments) +
         " bounds=" + std::to_string(b.center.x) + "," + std::to_string(b.center.y) + "," + std::to_string(b.center.z) + "," +
         std::to_string(b.radius) + (scene.media.empty() ? std::string() : " media=" + std::to_string(scene.media.media.size()));
}

std::unique_ptr<Integrator> create_integrator(const Scene& scene, const Accel& accel, const RenderConfig& config,
                                              std::shared_ptr<PathSpaceFilter> carried = nullptr) {
  check_composition(config.integrator, config.filter.name);
  check_device(config.device, config.integrator, config.filter.name);
  check_media(scene, config.device, config.integrator);
  const IntegratorContext context{scene, accel, config.seed, config.filter, std::move(carried)};
  const DeviceEntry& device = device_registry().at(config.device);
  if (device.create) return device.create(context, config.integrator, config.settings);
  return integrator_registry().at(config.integrator).create(context, config.settings);
}

// Validates the scene before Embree sees any of its values, then builds its accel unless given one
// (reusing what does not move from `previous`, the previous frame's).
std::shared_ptr<const Accel> validated_accel(const Scene& scene, std::shared_ptr<const Accel> accel, std::vector<std::string>* warnings,
                                             const Accel* previous = nullptr) {
  validate_scene(scene, warnings);
  return accel ? std::move(accel) : std::make_shared<const Accel>(scene, previous);
}

}  // namespace

uint64_t frame_seed(uint64_t seed, uint64_t frame) { return frame == 0 ? seed : hash_combine(mix64(seed ^ 0x6672616d65ull), frame); }

RenderSession::RenderSession(std::shared_ptr<const Scene> scene, std::shared_ptr<const Accel> accel, RenderConfig config)
    : scene_(std::move(scene)),
      accel_(validated_accel(*scene_, std::move(accel), &scene_warnings_)),
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
  if (group_ && group_->size() > 1) return run_distributed(limit, on_progress);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const bool timed = limit.passes == 0 && limit.seconds > 0.0;
  const bool counted = limit.passes > 0;

  RunResult result;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (aborted_) throw Error("the session's last pass was aborted: begin a frame before rendering again");
  }
  const PathCounters at_start = counters_;
  while (true) {
    if (cancel_.exchange(false)) {
      result.cancelled = true;
      break;
    }
    if (counted && result.passes >= limit.passes) break;
    if (timed && result.passes > 0 && elapsed() >= limit.seconds) break;
    RenderProgress p;
    // std::mutex is not fair: let a waiting snapshot() in before taking the lock for the next pass.
    while (readers_waiting_.load() > 0) std::this_thread::yield();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto pass_start = std::chrono::steady_clock::now();
      if (!pass_work_.run([&] { render_tracked_pass_locked(passes_, film_); })) {
        running_pass_ = 0;
        aborted_ = result.aborted = result.cancelled = true;
        cancel_.store(false);
        break;
      }
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

void RenderSession::render_tracked_pass_locked(uint32_t pass, Film& film) {
  const WorkProgress work = work_progress();
  pass_work_started_ = work.started;
  pass_work_done_ = work.done;
  pass_start_ns_ = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  running_pass_ = pass + 1;
  integrator_->render_pass(pass, film, counters_);
  running_pass_ = 0;
}

void RenderSession::cancel() { cancel_.store(true); }

void RenderSession::abort() {
  cancel_.store(true);
  if (!distributed()) pass_work_.cancel();
}

std::shared_ptr<const Accel> RenderSession::shared_accel() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return accel_;
}

bool RenderSession::aborted() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return aborted_;
}

void RenderSession::request_gather() { gather_requested_.store(true); }

void RenderSession::join(std::shared_ptr<ProcessGroup> group, const std::string& identity) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (passes_ > 0 || in_sequence_) throw Error("a render joins a process group before its first pass");
  const std::string what = identity + " | " + config_.integrator + " " + config_.filter.name + " seed=" + std::to_string(config_.seed) +
                           " | " + settings_fingerprint(config_) + " | " + scene_fingerprint(*scene_);
  const uint64_t mine = fnv1a64(what.data(), what.size());
  const std::vector<uint64_t> all = group->all_gather(mine);
  for (size_t r = 1; r < all.size(); ++r)
    if (all[r] != all[0])
      throw Error("distributed render: rank " + std::to_string(r) + " has other options, scene or binary than rank 0 (fingerprint " +
                  std::to_string(all[r]) + ", rank 0: " + std::to_string(all[0]) +
                  "); run the same pathspace with the same options and scene files on every rank");
  const std::string limit = integrator_->distribution_limit();
  if (!limit.empty()) throw Error("distributed render: " + limit + "; render it in one process");
  group_ = std::move(group);
  exchange_ = std::make_unique<FilmExchange>(*group_, film_.pixel_count());
  pass_film_ = Film(film_.width(), film_.height());
  keep_restored_on_rank0();
}

// A restored render's counters and hand_over sums are the job's so far: rank 0 keeps them, so the
// ranks' sum counts them once.
void RenderSession::keep_restored_on_rank0() {
  if (!group_ || group_->rank() == 0) return;
  counters_ = PathCounters{};
  integrator_->forget_handed_over();
}

void RenderSession::begin_frame(std::shared_ptr<const Scene> scene, std::shared_ptr<const Accel> accel, uint64_t frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (scene->camera.width != int(film_.width()) || scene->camera.height != int(film_.height()))
    throw Error("frame " + std::to_string(frame) + " is " + std::to_string(scene->camera.width) + "x" + std::to_string(scene->camera.height) +
                ", the animation's first frame " + std::to_string(film_.width()) + "x" + std::to_string(film_.height()));
  std::vector<std::string> warnings = scene_warnings_;
  std::shared_ptr<const Accel> next_accel = accel_;
  // The session's own scene (an animation's first frame) was validated and built by the constructor.
  if (scene != scene_ || accel) {
    warnings.clear();
    next_accel = validated_accel(*scene, std::move(accel), &warnings, accel_.get());
  }
  RenderConfig frame_config = config_;
  frame_config.seed = frame_seed(config_.seed, frame);
  // The new integrator takes the filter over before the old one (and its scene) goes. After an
  // aborted pass that had reached the filter, the filter starts afresh (abort()), but with the old
  // one's buffers: a new vertex buffer is hundreds of MB to fault in, every time a viewer's camera moves.
  const std::shared_ptr<PathSpaceFilter> old = integrator_->carried_filter();
  const std::shared_ptr<PathSpaceFilter> carried = aborted_ ? integrator_->carried_filter_after_abort() : old;
  integrator_ = create_integrator(*scene, *next_accel, frame_config, carried);
  if (old && !carried)
    if (const std::shared_ptr<PathSpaceFilter> fresh = integrator_->carried_filter()) fresh->workspace() = std::move(old->workspace());
  aborted_ = false;
  scene_ = std::move(scene);
  accel_ = std::move(next_accel);
  film_.clear();  // same size (checked above): its memory is reused, not allocated and faulted in again
  counters_ = PathCounters{};
  passes_ = 0;
  wall_s_ = 0.0;
  frame_ = frame;
  in_sequence_ = true;
  scene_warnings_ = std::move(warnings);
}

uint64_t RenderSession::frame() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frame_;
}

uint32_t RenderSession::frame_warm_up() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return integrator_->frame_warm_up();
}

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
  s.frame = frame_;
  integrator_->statistics(s.details);
  if (!ranks_.empty()) {
    s.ranks = ranks_;
    s.rays = job_counters_.rays;
    s.shadow_rays = job_counters_.shadow_rays;
    s.paths = job_counters_.paths;
    s.dropped_samples = job_counters_.dropped;
  }
  return s;
}

RenderStats RenderSession::stats() const {
  const ReaderLock lock(*this);
  return stats_locked();
}

namespace {

// The scene's output colour matrix on the mean image; the variance of each output channel is
// estimated as sum_j m_ij^2 var_j, leaving out the channels' covariances, which the film does not
// keep (only white-balanced scenes have a matrix, and only comparisons read the variance).
void apply_output_color_matrix(const std::array<float, 9>& m, Image* mean, Image* variance) {
  if (m == std::array<float, 9>{1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) return;
  const auto transform = [](const std::array<float, 9>& a, const Rgb& c) {
    return Rgb(a[0] * c.r + a[1] * c.g + a[2] * c.b, a[3] * c.r + a[4] * c.g + a[5] * c.b, a[6] * c.r + a[7] * c.g + a[8] * c.b);
  };
  std::array<float, 9> squared;
  for (int i = 0; i < 9; ++i) squared[i] = m[i] * m[i];
  for (Rgb& c : mean->pixels) c = transform(m, c);
  for (Rgb& v : variance->pixels) v = transform(squared, v);
}

}  // namespace

RenderSnapshot RenderSession::snapshot(SnapshotImages images) const {
  const ReaderLock lock(*this);
  if (aborted_) throw Error("the session's last pass was aborted: it has no image until a frame begins");
  RenderSnapshot snap;
  snap.mean = film_.mean();
  if (images == SnapshotImages::mean_and_variance) snap.variance = film_.variance_of_mean();
  apply_output_color_matrix(scene_->output_color_matrix, &snap.mean, &snap.variance);
  snap.stats = stats_locked();
  snap.aovs = integrator_->aovs();
  return snap;
}

PixelStats RenderSession::pixel(int x, int y) const {
  const ReaderLock lock(*this);
  if (aborted_) throw Error("the session's last pass was aborted: it has no image until a frame begins");
  if (x < 0 || y < 0 || x >= int(film_.width()) || y >= int(film_.height()))
    throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " + std::to_string(film_.width()) + "x" +
                std::to_string(film_.height()) + " image");
  const size_t i = size_t(y) * size_t(film_.width()) + size_t(x);
  Image mean(1, 1), variance(1, 1);
  mean.pixels[0] = film_.mean(i);
  variance.pixels[0] = film_.variance_of_mean(i);
  apply_output_color_matrix(scene_->output_color_matrix, &mean, &variance);
  return {mean.pixels[0], variance.pixels[0], film_.samples(uint32_t(i))};
}

SessionState RenderSession::save_state() const {
  const ReaderLock lock(*this);
  if (in_sequence_) throw Error("the state of an animation's frame cannot be saved (its filter's table spans frames)");
  if (aborted_) throw Error("the session's last pass was aborted: it has no state to save");
  StateWriter out;
  // The film's sums, squares and counts are nearly all of it (plus a splat film for LT, BPT, PCLT).
  out.reserve(film_.pixel_count() * (2 * 3 * sizeof(double) + sizeof(uint32_t)) * 2 + (size_t(1) << 16));
  out.put_string("session.integrator", config_.integrator);
  out.put_string("session.filter", config_.filter.name);
  out.put("session.seed", config_.seed);
  out.put_string("session.settings", settings_fingerprint(config_));
  out.put_string("session.scene", scene_fingerprint(*scene_));
  out.put("session.passes", passes_);
  // After a distributed run's gather, rank 0 saves the job's counters (rank 0 keeps them on resume).
  out.put("session.counters", ranks_.empty() ? counters_ : job_counters_);
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
  const std::string settings = in.get_string("session.settings");
  if (settings != settings_fingerprint(config_))
    throw Error("render state: made with the options '" + settings + "', this render has '" + settings_fingerprint(config_) + "'");
  const std::string scene = in.get_string("session.scene");
  if (scene != scene_fingerprint(*scene_))
    throw Error("render state: made for another scene (" + scene + "; this one: " + scene_fingerprint(*scene_) + ")");
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
  keep_restored_on_rank0();
}

PassProgress RenderSession::pass_progress() const {
  PassProgress p;
  p.pass = running_pass_.load();
  if (p.pass == 0) return p;
  p.running = true;
  const int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  p.seconds = double(now - pass_start_ns_.load()) * 1e-9;
  const WorkProgress w = work_progress();
  const uint64_t started = w.started - pass_work_started_.load(), done = w.done - pass_work_done_.load();
  p.fraction = started > 0 ? std::min(1.0, double(done) / double(started)) : 0.0;
  return p;
}

}  // namespace pathspace
