#include "viewer/live_view.h"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/film/block_metrics.h"
#include "pathspace/film/flip.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/device_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/io/image_io.h"
#include "pathspace/session/option_catalog.h"
#include "pathspace/session/render_stats_json.h"
#include "viewer/camera_controls.h"

namespace pathspace::viewer {

LiveView::LiveView(const PerspectiveCamera& home, float step, RenderChoice choice, FrameSaver saver,
                   std::shared_ptr<const Image> reference, FlightRecorder recorder, double animation_fps)
    : home_(home),
      step_(step),
      saver_(std::move(saver)),
      recorder_(std::move(recorder)),
      reference_(std::move(reference)),
      camera_(home),
      choice_(std::move(choice)),
      applied_choice_(choice_),
      taken_choice_(choice_),
      fps_(animation_fps) {}

std::optional<Frame> LiveView::next_frame(uint64_t after, std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!frame_ready_.wait_for(lock, wait, [&] { return latest_.sequence > after; })) return std::nullopt;
  if (encoded_.sequence == latest_.sequence) return encoded_;
  const Pending pending = latest_;
  lock.unlock();  // encode without holding up the render thread (two clients may both encode it)
  const Frame frame{pending.sequence,
                    std::make_shared<const std::string>(encode_image("frame.png", displayed(*pending.image, pending.display), ImageEncoding::fast)),
                    pending.stats_json};
  lock.lock();
  if (frame.sequence > encoded_.sequence) encoded_ = frame;
  return frame;
}

std::string LiveView::options_json() const {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const CatalogOption& o : options_of(choice_.integrator, choice_.filter)) {
    nlohmann::ordered_json j = option_spec_json(o.spec);
    const std::string* value = choice_.given.find(o.spec.name);
    j["value"] = value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
    list.push_back(std::move(j));
  }
  std::vector<std::string> filters = {FilterChoice::kNone};
  for (const std::string& f : filter_registry().names()) filters.push_back(f);
  return nlohmann::ordered_json{{"options",
                                 {{"integrator", choice_.integrator},
                                  {"filter", choice_.filter},
                                  {"device", choice_.device},
                                  {"integrators", integrator_registry().names()},
                                  {"filters", filters},
                                  {"devices", device_registry().names()},
                                  {"list", list}}}}
      .dump();
}

namespace {

// configure_render is the command line's own check: the page gets the CLI's message for a bad value.
RenderConfig configured(const RenderChoice& c) {
  try {
    return configure_run(c.integrator, c.filter, c.given, c.seed, c.threads, c.device);
  } catch (const OptionError& e) {
    throw Error(e.what());
  }
}

}  // namespace

std::string LiveView::set_choice(RenderChoice next) {
  RenderConfig config = configured(next);
  choice_ = std::move(next);
  config_changed_ = std::move(config);
  return options_json();
}

std::optional<std::string> LiveView::apply(const Command& command) {
  if (std::holds_alternative<Save>(command)) {  // the files are written without holding the lock
    Pending newest;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      newest = latest_;
    }
    if (!newest.image) throw Error("no frame to save yet");
    return saver_(*newest.image, newest.display, newest.label);
  }
  if (const auto* record = std::get_if<Record>(&command)) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (record->on == recording_) throw Error(recording_ ? "already recording" : "not recording");
    if (record->on) {
      std::lock_guard<std::mutex> writing(frame_writing_);
      const std::string reply = recorder_.start();  // throws when the files cannot be written
      recording_ = true;
      return reply;
    }
    recording_ = false;
    lock.unlock();  // a frame being written finishes first (frame_writing_); later ones are ignored by the recorder
    std::lock_guard<std::mutex> writing(frame_writing_);
    return recorder_.stop();
  }
  if (const auto* inspect = std::get_if<Inspect>(&command)) {
    // Under the lock, so that the render loop replaces no session meanwhile. A view that is
    // restarting (its pass just aborted) has no image: the answer waits for its first frame.
    std::unique_lock<std::mutex> lock(mutex_);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (true) {
      if (std::optional<std::string> answer = inspect_pixel(*inspect)) return answer;
      if (frame_ready_.wait_until(lock, deadline) == std::cv_status::timeout) throw Error("the view is restarting: inspect again");
    }
  }
  std::optional<std::string> reply;
  bool restart = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (const auto* m = std::get_if<Move>(&command)) {
      move_camera(&camera_, m->right, m->up, m->forward, step_);
      camera_changed_ = restart = true;
    } else if (const auto* t = std::get_if<Turn>(&command)) {
      turn_camera(&camera_, t->yaw, t->pitch);
      camera_changed_ = restart = true;
    } else if (std::holds_alternative<Reset>(command)) {
      camera_ = home_;
      camera_changed_ = restart = true;
    } else if (const auto* split = std::get_if<Split>(&command)) {
      if (split->filter == "off") {
        split_label_.clear();
        split_changed_ = std::optional<RenderConfig>();
      } else {
        // The view's options that apply to the other integrator and filter.
        RenderChoice other = choice_;
        if (!split->integrator.empty()) other.integrator = split->integrator;
        other.filter = split->filter;
        other.given = OptionValues();
        for (const CatalogOption& o : options_of(other.integrator, other.filter))
          if (const std::string* v = choice_.given.find(o.spec.name)) other.given.set(o.spec.name, *v);
        RenderConfig config = configured(other);
        split_label_ = fmt::format("{}, filter {}", other.integrator, other.filter);
        split_changed_ = std::optional<RenderConfig>(std::move(config));
      }
      restart = true;
    } else if (const auto* play = std::get_if<Play>(&command)) {
      if (!(fps_ > 0.0)) throw Error("this scene has no animation to play");
      playing_ = play->on;
      time_changed_ = time_changed_ || play->on;  // an idle render (--max-spp) goes on with the next frame
      if (play->on) ++animation_frame_;
    } else if (const auto* seek = std::get_if<Seek>(&command)) {
      if (!(fps_ > 0.0)) throw Error("this scene has no animation to seek in");
      animation_frame_ = uint64_t(std::llround(seek->seconds * fps_));
      time_changed_ = restart = true;
    } else if (const auto* show = std::get_if<Show>(&command)) {
      shown_ = show->image;
      exposure_changed_ = true;  // shown again at once, also when the render idles
    } else if (const auto* e = std::get_if<Exposure>(&command)) {
      exposure_stops_ = e->stops;
      exposure_changed_ = true;
    } else if (const auto* t = std::get_if<ToneMapChoice>(&command)) {
      tone_ = parse_tone_map(t->name);
      exposure_changed_ = true;  // shown again at once
    } else if (std::holds_alternative<OptionsRequest>(command)) {
      reply = options_json();
    } else if (const auto* s = std::get_if<SetOption>(&command)) {
      RenderChoice next = choice_;
      if (s->name == "integrator") {
        next.integrator = s->value;
      } else if (s->name == "filter") {
        next.filter = s->value;
      } else if (s->name == "device") {
        next.device = s->value;
      } else {
        next.given.set(s->name, s->value);
      }
      reply = set_choice(std::move(next));
      restart = true;
    } else if (const auto* u = std::get_if<UnsetOption>(&command)) {
      RenderChoice next = choice_;
      next.given.erase(u->name);
      reply = set_choice(std::move(next));
      restart = true;
    }
    if (restart)
      for (RenderSession* session : sessions_) session->abort();  // the pass in flight shows the old view: stop it now
  }
  changed_.notify_all();
  return reply;
}

std::optional<std::string> LiveView::inspect_pixel(const Inspect& at) const {
  if (sessions_.empty()) throw Error("no render to inspect yet");
  const int width = home_.width, height = home_.height;
  if (at.x >= width || at.y >= height) throw Error(fmt::format("pixel ({}, {}) is outside the {}x{} image", at.x, at.y, width, height));
  const bool right = sessions_.size() > 1 && at.x >= width / 2;  // compose_split's halves
  const RenderSession& session = *sessions_[right ? 1 : 0];
  if (session.aborted()) return std::nullopt;
  const PixelStats p = session.pixel(at.x, at.y);  // no abort meanwhile: only apply() aborts, under this lock
  const auto rgb = [](const Rgb& c) { return nlohmann::ordered_json::array({c.r, c.g, c.b}); };
  const Rgb error(std::sqrt(p.variance_of_mean.r), std::sqrt(p.variance_of_mean.g), std::sqrt(p.variance_of_mean.b));
  nlohmann::ordered_json j = {{"x", at.x},
                              {"y", at.y},
                              {"half", sessions_.size() > 1 ? nlohmann::ordered_json(right ? "right" : "left") : nlohmann::ordered_json(nullptr)},
                              {"mean", rgb(p.mean)},
                              {"std_error", rgb(error)},
                              {"samples", p.samples},
                              {"luminance", luminance(p.mean)},
                              {"reference", nullptr},
                              {"rel_error", nullptr}};
  if (reference_) {
    const Rgb r = reference_->at(at.x, at.y);
    j["reference"] = rgb(r);
    j["rel_error"] = (luminance(p.mean) - luminance(r)) / std::max(luminance(r), 1e-6f);
  }
  return nlohmann::ordered_json{{"pixel", j}}.dump();
}

void LiveView::set_sessions(std::vector<RenderSession*> sessions) {
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_ = std::move(sessions);
}

PerspectiveCamera LiveView::camera() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return camera_;
}

std::optional<double> LiveView::take_time() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!time_changed_) return std::nullopt;
  time_changed_ = false;
  view_start_ = std::chrono::steady_clock::now();
  return double(animation_frame_) / fps_;
}

void LiveView::advance_if_playing() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!playing_) return;
    ++animation_frame_;
    time_changed_ = true;
  }
  changed_.notify_all();
}

std::optional<PerspectiveCamera> LiveView::take_camera() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!camera_changed_) return std::nullopt;
  camera_changed_ = false;
  view_start_ = std::chrono::steady_clock::now();
  return camera_;
}

std::optional<std::optional<RenderConfig>> LiveView::take_split() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<std::optional<RenderConfig>> split = std::move(split_changed_);
  split_changed_.reset();
  return split;
}

void LiveView::compose_split(RenderSnapshot* left, const RenderSnapshot& right) {
  Image& image = left->mean;
  const int half = image.width / 2;
  for (int y = 0; y < image.height; ++y)
    for (int x = half; x < image.width; ++x) image.pixels[size_t(y) * size_t(image.width) + size_t(x)] =
        right.mean.pixels[size_t(y) * size_t(image.width) + size_t(x)];
}

namespace {

Image scaled_up(const Image& small, int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    const size_t row = size_t(y * small.height / height) * size_t(small.width);
    for (int x = 0; x < width; ++x) image.pixels[size_t(y) * size_t(width) + size_t(x)] = small.pixels[row + size_t(x * small.width / width)];
  }
  return image;
}

}  // namespace

void LiveView::scale_up(RenderSnapshot* preview, int width, int height) {
  preview->mean = scaled_up(preview->mean, width, height);
  for (NamedImage& aov : preview->aovs) aov.image = scaled_up(aov.image, width, height);
}

std::optional<RenderConfig> LiveView::take_config() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<RenderConfig> config = std::move(config_changed_);
  config_changed_.reset();
  if (config) {
    view_start_ = std::chrono::steady_clock::now();
    taken_choice_ = choice_;
  }
  return config;
}

void LiveView::config_applied() {
  std::lock_guard<std::mutex> lock(mutex_);
  applied_choice_ = taken_choice_;
}

void LiveView::config_failed(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  choice_ = applied_choice_;
  set_error(message);
}

void LiveView::set_error(const std::string& message) {
  error_ = message;
  ++error_id_;
  error_time_ = std::chrono::steady_clock::now();
}

void LiveView::split_failed(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  split_label_.clear();
  set_error(message);
}

void LiveView::publish(RenderSnapshot snapshot, uint64_t view, int preview) {
  double stops;
  ToneMap tone;
  std::chrono::steady_clock::time_point start;
  PerspectiveCamera camera;
  std::string shown, split;
  bool recording;
  nlohmann::ordered_json animation = nullptr, error = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fps_ > 0.0) animation = {{"seconds", double(animation_frame_) / fps_}, {"playing", playing_}};
    // Frames a slow client never gets are dropped, so the message rides on every frame for 2 s.
    if (!error_.empty() && std::chrono::steady_clock::now() - error_time_ < std::chrono::seconds(2))
      error = {{"id", error_id_}, {"message", error_}};
    recording = recording_;
    camera = camera_;
    shown = shown_;
    split = split_label_;
    stops = exposure_stops_;
    tone = tone_;
    exposure_changed_ = false;
    start = view_start_;
  }
  const int width = snapshot.mean.width, height = snapshot.mean.height;
  const RenderStats& stats = snapshot.stats;
  // Against --reference: the cheap metrics every frame, FLIP (its filters cost tens of ms at 640x360)
  // at most once a second; the error map is one more image to show.
  nlohmann::ordered_json metrics = nullptr;
  const double view_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (reference_ && preview == 1) {
    const ImageError e = image_error(snapshot.mean, *reference_);
    const BlockError b = block_error(snapshot.mean, *reference_);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_flip_time_ > std::chrono::seconds(1)) {
      last_flip_ = flip(snapshot.mean, *reference_).mean;
      last_flip_time_ = now;
    }
    metrics = {{"seconds", view_seconds}, {"spp", stats.spp}, {"rel_mse", e.rel_mse}, {"block_rel_mse", b.block_rel_mse},
               {"blotched_share", b.blotched_share}, {"flip", last_flip_}};
    snapshot.aovs.push_back({"error", rel_error_map(snapshot.mean, *reference_)});
  }
  nlohmann::ordered_json images = nlohmann::ordered_json::array({"image"});
  Image* image = &snapshot.mean;
  std::string shown_found = "image";
  for (NamedImage& aov : snapshot.aovs) {
    images.push_back(aov.name);
    if (aov.name == shown) image = &aov.image, shown_found = aov.name;
  }
  auto frame_image = std::make_shared<const Image>(std::move(*image));
  if (recording) {
    std::lock_guard<std::mutex> writing(frame_writing_);
    recorder_.frame(*frame_image, Display{float(std::exp2(stops)), tone});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::ordered_json j = {{"stats",
                                     {{"width", width},
                                      {"height", height},
                                      {"integrator", stats.integrator},
                                      {"filter", stats.filter},
                                      {"spp", stats.spp},
                                      {"view", view},
                                      {"preview", preview},
                                      {"passes_per_second", seconds > 0.0 ? double(stats.spp) / seconds : 0.0},
                                      {"rays", stats.rays},
                                      {"details", statistics_json(stats.details)},
                                      {"metrics", metrics},
                                      {"images", images},
                                      {"split", split.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(split)},
                                      {"shown", shown},
                                      {"tonemap", tone_map_name(tone)},
                                      {"animation", animation},
                                      {"error", error},
                                      {"camera_options", camera_options(camera)}}}};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string label = fmt::format("view{}-{}spp{}{}", view, stats.spp, preview > 1 ? "-preview" : "",
                                          shown_found == "image" ? "" : "-" + shown_found);
    latest_ = Pending{latest_.sequence + 1, std::move(frame_image), Display{float(std::exp2(stops)), tone}, j.dump(), label};
  }
  frame_ready_.notify_all();
}

bool LiveView::wait_for_change(std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, wait, [&] { return camera_changed_ || config_changed_ || split_changed_ || exposure_changed_ || time_changed_; });
  return exposure_changed_;
}

}  // namespace pathspace::viewer
