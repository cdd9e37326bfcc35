// RenderSession (session/render_session.h): what continued renders and checkpoints rely on.
//  - run(4) + run(4) equals run(8) bit for bit (mean, variance, AOVs, counters and the integrator's
//    own statistics) for every integrator, on the built-in Cornell box at 32x32 with 2 threads;
//  - save_state() after 3 passes, restored into a fresh session with the same config and run for 5
//    more, equals one session run for 8; a state of another integrator, filter, seed or image size
//    is refused with pathspace::Error, and a damaged one too, leaving the session as it was;
//  - cancel() from another thread ends run(until_cancelled()) after the pass in flight; a cancel()
//    before run() stops that run before its first pass;
//  - snapshot() from another thread during a run shows whole passes only: the snapshot of k passes
//    equals a separate k-pass render bit for bit;
//  - a statistic that was not reported is an error to ask for (Statistics::at);
//  - pixel(x, y) is the snapshot's pixel bit for bit.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <future>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "pathspace/session/render_session.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

static_assert(sizeof(Rgb) == 3 * sizeof(float), "images are compared with memcmp");

constexpr int kSize = 32;
constexpr int kThreads = 2;
constexpr uint64_t kSeed = 7;

struct Shared {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const Accel> accel;
};

// The built-in Cornell box (spheres, one area light) and its acceleration structure, shared.
const Shared& cornell(int width = kSize, int height = kSize) {
  static std::map<std::pair<int, int>, Shared> made;
  Shared& s = made[{width, height}];
  if (!s.scene) {
    s.scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", width, height));
    s.accel = std::make_shared<const Accel>(*s.scene);
  }
  return s;
}

std::unique_ptr<RenderSession> make_session(const RenderConfig& config, int width = kSize, int height = kSize) {
  const Shared& s = cornell(width, height);
  return std::make_unique<RenderSession>(s.scene, s.accel, config);
}

RenderConfig threaded(RenderConfig c) {
  c.threads = kThreads;
  return c;
}

struct Case {
  const char* name;
  RenderConfig config;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  BptSettings bpt;
  bpt.strategy_images = 3;
  HashedFilterSettings hashed;
  hashed.debug_images = true;  // its AOVs are compared too
  HashedFilterSettings adaptive;  // each pass's choice of voxel level carries to the next (sec. 3.1.3)
  adaptive.adaptive = true;
  ConsistentFilterSettings everything;  // batches, query paths and caustic photons
  everything.aa_paths = 1;
  everything.batch_memory_mb = 0.05;
  everything.caustics.photons_per_pixel = 2.0;
  return {
      {"pt", threaded(make_render_config("pt", PtSettings{}, kSeed))},
      {"pt_hashed", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", hashed))},
      {"pt_hashed_adaptive", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", adaptive))},
      {"pt_consistent", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "consistent", ConsistentFilterSettings{}))},
      {"pt_consistent_caustics_aa", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "consistent", everything))},
      {"lt", threaded(make_render_config("lt", LtSettings{}, kSeed))},
      {"bpt_strategy_images", threaded(make_render_config("bpt", bpt, kSeed))},
      {"sppm", threaded(make_render_config("sppm", SppmSettings{}, kSeed))},
      {"pclt", threaded(make_render_config("pclt", PcltSettings{}, kSeed))},
  };
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// Statistics that depend on the passes rendered, not on how long they took or on the allocation
// history of this process (pclt.memory_*: buffer capacities, smaller in a session that ran fewer passes).
bool deterministic(const Statistic& s) {
  const std::string& n = s.name;
  return s.kind != StatKind::seconds && n.find("_ns_") == std::string::npos && n.find(".memory") == std::string::npos &&
         !(n.size() > 6 && n.compare(n.size() - 6, 6, "_per_s") == 0);
}

// Images bit for bit, AOVs, the common counters and the deterministic statistics.
void expect_same_render(const RenderSnapshot& a, const RenderSnapshot& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_TRUE(same_bits(a.mean, b.mean)) << "mean images differ";
  EXPECT_TRUE(same_bits(a.variance, b.variance)) << "variance images differ";
  ASSERT_EQ(a.aovs.size(), b.aovs.size());
  for (size_t i = 0; i < a.aovs.size(); ++i) {
    EXPECT_EQ(a.aovs[i].name, b.aovs[i].name);
    EXPECT_TRUE(same_bits(a.aovs[i].image, b.aovs[i].image)) << "AOV " << a.aovs[i].name << " differs";
  }
  EXPECT_EQ(a.stats.spp, b.stats.spp);
  EXPECT_EQ(a.stats.rays, b.stats.rays);
  EXPECT_EQ(a.stats.shadow_rays, b.stats.shadow_rays);
  EXPECT_EQ(a.stats.paths, b.stats.paths);
  EXPECT_EQ(a.stats.dropped_samples, b.stats.dropped_samples);
  for (const Statistic& s : a.stats.details.all()) {
    if (!deterministic(s)) continue;
    const Statistic* t = b.stats.details.find(s.name);
    if (!t) {
      ADD_FAILURE() << s.name << " reported by one render only";
      continue;
    }
    EXPECT_EQ(s.number, t->number) << s.name;
    EXPECT_EQ(s.bins, t->bins) << s.name;
    EXPECT_EQ(s.text, t->text) << s.name;
  }
  EXPECT_EQ(a.stats.details.all().size(), b.stats.details.all().size());
}

// Some pixel is lit: a render of nothing would make every comparison pass.
double image_sum(const Image& img) {
  double sum = 0.0;
  for (const Rgb& p : img.pixels) sum += double(p.r) + double(p.g) + double(p.b);
  return sum;
}

class SessionContinues : public ::testing::TestWithParam<Case> {};

TEST_P(SessionContinues, TwoRunsOfFourEqualOneRunOfEight) {
  const RenderConfig& config = GetParam().config;
  auto split = make_session(config);
  EXPECT_EQ(split->run(RunLimit::for_passes(4)).passes, 4u);
  const RenderSnapshot after4 = split->snapshot();
  EXPECT_EQ(after4.stats.spp, 4u);
  EXPECT_EQ(split->run(RunLimit::for_passes(4)).passes, 4u);
  EXPECT_EQ(split->passes_done(), 8u);
  auto whole = make_session(config);
  EXPECT_EQ(whole->run(RunLimit::for_passes(8)).passes, 8u);
  const RenderSnapshot a = split->snapshot(), b = whole->snapshot();
  EXPECT_EQ(a.stats.spp, 8u);
  EXPECT_GT(image_sum(a.mean), 0.0);
  // A snapshot of the mean alone (a sequence's frames) has the same mean and no variance image.
  const RenderSnapshot mean_only = split->snapshot(SnapshotImages::mean);
  EXPECT_TRUE(same_bits(mean_only.mean, a.mean));
  EXPECT_EQ(mean_only.variance.size(), 0u);
  EXPECT_EQ(a.variance.size(), a.mean.size());
  EXPECT_FALSE(same_bits(after4.mean, a.mean)) << "the second run must add to the first";
  expect_same_render(a, b, "run(4) + run(4) vs run(8)");
  // The one-call render() is the same render.
  const Shared& s = cornell();
  expect_same_render(render(*s.scene, *s.accel, config, RunLimit::for_passes(8)), b, "render() vs session");
  if (std::string(GetParam().name) == "bpt_strategy_images") {
    EXPECT_EQ(a.aovs.size(), size_t(bpt_strategy_count(3)));
  }
  if (std::string(GetParam().name) == "pt_hashed") {
    EXPECT_FALSE(a.aovs.empty());
  }
}

TEST_P(SessionContinues, RestoredIntoAFreshSessionContinuesBitForBit) {
  const RenderConfig& config = GetParam().config;
  SessionState state;
  {
    auto first = make_session(config);
    first->run(RunLimit::for_passes(3));
    state = first->save_state();
  }  // the session that saved is gone: nothing is shared with it
  ASSERT_FALSE(state.bytes.empty());
  auto restored = make_session(config);
  restored->restore_state(state);
  EXPECT_EQ(restored->passes_done(), 3u);
  EXPECT_EQ(restored->stats().spp, 3u);
  restored->run(RunLimit::for_passes(5));
  auto whole = make_session(config);
  whole->run(RunLimit::for_passes(8));
  const RenderSnapshot a = restored->snapshot(), b = whole->snapshot();
  EXPECT_GT(image_sum(a.mean), 0.0);
  expect_same_render(a, b, "3 passes, save, restore, 5 passes vs 8 passes");

  // A state saved from a restored session is the same state again.
  auto again = make_session(config);
  again->restore_state(state);
  EXPECT_EQ(again->save_state().bytes, state.bytes);
}

TEST_P(SessionContinues, DamagedStateThrowsAndLeavesTheSessionUsable) {
  const RenderConfig& config = GetParam().config;
  auto source = make_session(config);
  source->run(RunLimit::for_passes(2));
  const SessionState state = source->save_state();

  auto session = make_session(config);
  session->run(RunLimit::for_passes(3));
  for (const size_t keep : {size_t(0), size_t(7), state.bytes.size() / 2, state.bytes.size() - 1}) {
    SessionState truncated = state;
    truncated.bytes.resize(keep);
    EXPECT_THROW(session->restore_state(truncated), Error) << "kept " << keep << " of " << state.bytes.size() << " bytes";
  }
  SessionState extended = state;
  extended.bytes.push_back(0);
  EXPECT_THROW(session->restore_state(extended), Error) << "trailing bytes";
  EXPECT_EQ(session->passes_done(), 3u);
  session->run(RunLimit::for_passes(5));
  auto whole = make_session(config);
  whole->run(RunLimit::for_passes(8));
  expect_same_render(session->snapshot(), whole->snapshot(), "3 passes, failed restores, 5 passes vs 8 passes");
}

INSTANTIATE_TEST_SUITE_P(Integrators, SessionContinues, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return testing::test_name(i.param.name); });

// A state restores only into a render of the same integrator, filter, seed and image size.
TEST(SessionState, OtherIntegratorFilterOptionsSeedSceneOrSizeIsRefused) {
  const RenderConfig pt = threaded(make_render_config("pt", PtSettings{}, kSeed));
  auto source = make_session(pt);
  source->run(RunLimit::for_passes(2));
  const SessionState state = source->save_state();

  auto expect_refused = [&](std::unique_ptr<RenderSession> session, const std::string& what) {
    SCOPED_TRACE(what);
    session->run(RunLimit::for_passes(1));
    const Image before = session->snapshot().mean;
    EXPECT_THROW(session->restore_state(state), Error);
    EXPECT_EQ(session->passes_done(), 1u);
    EXPECT_TRUE(same_bits(before, session->snapshot().mean));
  };
  expect_refused(make_session(threaded(make_render_config("lt", LtSettings{}, kSeed))), "other integrator");
  expect_refused(make_session(threaded(with_filter(pt, "hashed", HashedFilterSettings{}))), "other filter");
  expect_refused(make_session(threaded(make_render_config("pt", PtSettings{}, kSeed + 1))), "other seed");
  expect_refused(make_session(pt, 16, 16), "other size");
  expect_refused(make_session(pt, 16, 64), "same pixel count, other shape");
  PtSettings no_nee;
  no_nee.nee = false;
  expect_refused(make_session(threaded(make_render_config("pt", no_nee, kSeed))), "other option values");
  auto glossy = std::make_shared<const Scene>(make_builtin_scene("cornell-glossy", kSize, kSize));
  expect_refused(std::make_unique<RenderSession>(glossy, std::make_shared<const Accel>(*glossy), pt), "other scene, same size");

  // The message says what the state was made by.
  auto lt = make_session(threaded(make_render_config("lt", LtSettings{}, kSeed)));
  try {
    lt->restore_state(state);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pt"), std::string::npos) << e.what();
  }
  // The matching session takes it.
  auto same = make_session(pt);
  EXPECT_NO_THROW(same->restore_state(state));
  EXPECT_EQ(same->passes_done(), 2u);
}

// Aborts when `done` is not ready within a minute: a run that ignores cancel() never returns, and
// the test must not hang (nor return while the run still uses the session).
template <typename T>
T wait_or_abort(std::future<T>& done, const char* what) {
  if (done.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
    std::fprintf(stderr, "FATAL: %s did not return within 60 s\n", what);
    std::fflush(stderr);
    std::abort();
  }
  return done.get();
}

TEST(SessionCancel, FromAnotherThreadStopsAfterThePassInFlight) {
  for (int repeat = 0; repeat < 5; ++repeat) {
    SCOPED_TRACE(repeat);
    auto session = make_session(threaded(make_render_config("pt", PtSettings{}, kSeed)));
    std::atomic<uint32_t> reported{0};
    std::future<RunResult> done = std::async(std::launch::async, [&] {
      return session->run(RunLimit::until_cancelled(), [&](const RenderProgress& p) {
        EXPECT_EQ(p.passes_total, 0u);
        EXPECT_EQ(p.fraction, 0.0);
        reported = p.passes_done;
      });
    });
    const uint32_t target = 3 + uint32_t(repeat);
    while (reported.load() < target) std::this_thread::sleep_for(std::chrono::microseconds(100));
    const uint32_t at_cancel = reported.load();  // passes finished; one more may be in flight
    session->cancel();
    const RunResult r = wait_or_abort(done, "run(until_cancelled()) after cancel()");
    EXPECT_TRUE(r.cancelled);
    EXPECT_GE(r.passes, at_cancel);
    EXPECT_LE(r.passes, at_cancel + 1) << "a pass was started after cancel()";
    EXPECT_EQ(session->passes_done(), r.passes);
    EXPECT_EQ(reported.load(), r.passes);
    // The cancel was consumed: the next run runs.
    EXPECT_EQ(session->run(RunLimit::for_passes(2)).passes, 2u);
    EXPECT_EQ(session->passes_done(), r.passes + 2);
  }
}

TEST(SessionCancel, BeforeRunStopsTheNextRunAtZeroPasses) {
  auto session = make_session(threaded(make_render_config("pt", PtSettings{}, kSeed)));
  session->cancel();
  const RunResult r = session->run(RunLimit::for_passes(5));
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.passes, 0u);
  EXPECT_EQ(session->passes_done(), 0u);
  EXPECT_EQ(image_sum(session->snapshot().mean), 0.0);
  // until_cancelled() too (the test would hang otherwise).
  session->cancel();
  std::future<RunResult> done = std::async(std::launch::async, [&] { return session->run(RunLimit::until_cancelled()); });
  const RunResult u = wait_or_abort(done, "run(until_cancelled()) after an earlier cancel()");
  EXPECT_TRUE(u.cancelled);
  EXPECT_EQ(u.passes, 0u);
  // Consumed: the next run renders all its passes.
  const RunResult next = session->run(RunLimit::for_passes(3));
  EXPECT_FALSE(next.cancelled);
  EXPECT_EQ(next.passes, 3u);
}

// pass_progress() from another thread: while a pass runs it names the pass and its share of the work
// done grows from 0 to 1; between passes nothing runs.
TEST(SessionRun, PassProgressIsVisibleFromAnotherThreadDuringAPass) {
  auto session = make_session(threaded(make_render_config("bpt", BptSettings{}, kSeed)), 256, 256);
  EXPECT_FALSE(session->pass_progress().running);
  std::atomic<bool> done{false};
  std::thread runner([&] {
    session->run(RunLimit::for_passes(3));
    done = true;
  });
  double lowest = 2.0, highest = -1.0;
  uint32_t last_pass = 0;
  while (!done) {
    const PassProgress p = session->pass_progress();
    if (p.running) {
      EXPECT_GE(p.pass, 1u);
      EXPECT_LE(p.pass, 3u);
      EXPECT_GE(p.seconds, 0.0);
      EXPECT_GE(p.fraction, 0.0);
      EXPECT_LE(p.fraction, 1.0);
      lowest = std::min(lowest, p.fraction);
      highest = std::max(highest, p.fraction);
      last_pass = std::max(last_pass, p.pass);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  runner.join();
  EXPECT_FALSE(session->pass_progress().running);
  EXPECT_GE(last_pass, 2u) << "the polls must have seen several passes";
  EXPECT_LT(lowest, 0.5);
  EXPECT_GT(highest, 0.5);
}

TEST(SessionRun, TimeBudgetRunsWholePassesAndAtLeastOne) {
  auto session = make_session(threaded(make_render_config("pt", PtSettings{}, kSeed)));
  const RunResult r = session->run(RunLimit::for_seconds(1e-9));
  EXPECT_EQ(r.passes, 1u);
  const RunResult t = session->run(RunLimit::for_seconds(0.05));
  EXPECT_GE(t.passes, 1u);
  EXPECT_EQ(session->passes_done(), 1u + t.passes);
  EXPECT_THROW(session->run(RunLimit{0, -1.0}), Error);
  const Shared& s = cornell();
  EXPECT_THROW(render(*s.scene, *s.accel, session->config(), RunLimit::until_cancelled()), Error)
      << "render() without an end would never return";
}

class SessionSnapshot : public ::testing::TestWithParam<Case> {};

// Snapshots taken while another thread runs hold whole passes: the stats' pass count is the number
// of passes in the film (a snapshot of k passes equals a k-pass render bit for bit). The run lets a
// waiting snapshot() go before its next pass (std::mutex alone is not fair: without that, 100
// passes of 32x32 PT could end before any snapshot got the lock), so snapshots arrive mid-run.
TEST_P(SessionSnapshot, DuringARunHoldsWholePasses) {
  constexpr uint32_t kPasses = 100;
  const RenderConfig& config = GetParam().config;
  auto session = make_session(config);
  std::future<RunResult> done = std::async(std::launch::async, [&] { return session->run(RunLimit::for_passes(kPasses)); });
  std::vector<RenderSnapshot> snaps;
  std::set<uint32_t> seen;
  while (snaps.size() < 6 && done.wait_for(std::chrono::microseconds(300)) != std::future_status::ready) {
    RenderSnapshot snap = session->snapshot();
    if (snap.stats.spp > 0 && snap.stats.spp < kPasses && seen.insert(snap.stats.spp).second) snaps.push_back(std::move(snap));
  }
  EXPECT_EQ(wait_or_abort(done, "run(for_passes(100))").passes, kPasses);
  ASSERT_FALSE(snaps.empty()) << "no snapshot was taken while the run was going on";
  const Shared& s = cornell();
  for (const RenderSnapshot& snap : snaps) {
    const RenderSnapshot reference = render(*s.scene, *s.accel, config, RunLimit::for_passes(snap.stats.spp));
    expect_same_render(snap, reference, "snapshot at " + std::to_string(snap.stats.spp) + " passes");
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, SessionSnapshot,
                         ::testing::Values(cases()[0], cases()[1], cases()[4]),  // pt, pt + hashed, sppm
                         [](const ::testing::TestParamInfo<Case>& i) { return testing::test_name(i.param.name); });

TEST(SessionStatistics, UnreportedStatisticIsAnError) {
  auto plain = make_session(threaded(make_render_config("pt", PtSettings{}, kSeed)));
  plain->run(RunLimit::for_passes(1));
  const RenderStats stats = plain->stats();
  EXPECT_EQ(stats.integrator, "pt");
  EXPECT_EQ(stats.filter, "none");
  EXPECT_EQ(stats.seed, kSeed);
  EXPECT_EQ(stats.threads, kThreads);
  EXPECT_EQ(stats.details.find("hashed.probe_limit_fallbacks"), nullptr);
  EXPECT_THROW(stats.details.at("hashed.probe_limit_fallbacks"), Error);
  EXPECT_THROW(stats.details.number("pclt.memory_bytes"), Error);
  try {
    stats.details.at("hashed.probe_limit_fallbacks");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hashed.probe_limit_fallbacks"), std::string::npos) << e.what();
  }

  // Reported ones are there, with their kinds; a name of another integrator is still an error.
  auto hashed = make_session(threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", HashedFilterSettings{})));
  hashed->run(RunLimit::for_passes(2));
  const Statistics details = hashed->stats().details;
  EXPECT_EQ(details.at("hashed.probe_limit_fallbacks").kind, StatKind::counter);
  EXPECT_EQ(details.number("hashed.passes"), 2.0);
  EXPECT_EQ(details.at("hashed.table_bytes").kind, StatKind::bytes);
  EXPECT_THROW(details.at("sppm.iterations"), Error);
  EXPECT_THROW(details.at("hashed.no_such_statistic"), Error);

  auto sppm = make_session(threaded(make_render_config("sppm", SppmSettings{}, kSeed)));
  sppm->run(RunLimit::for_passes(3));
  EXPECT_EQ(sppm->stats().details.number("sppm.iterations"), 3.0);
  EXPECT_THROW(sppm->stats().details.at("hashed.passes"), Error);
}

// Every session validates its scene before Embree sees it (scene/scene_validation.h): values out of
// range are an Error at construction, not an abort inside Embree or a silently wrong image, whether
// the scene comes from the CLI or from code (studies, tests, bindings).
TEST(SessionValidation, OutOfRangeScenesAreErrorsBeforeTheAccelIsBuilt) {
  Scene far = make_builtin_scene("cornell-empty-area", 8, 8);
  far.positions[0].x = 1e20f;  // Embree's ray.valid() assertion aborted on such values
  EXPECT_THROW(RenderSession(std::move(far), make_render_config("pt", PtSettings{})), Error);

  Scene textured = make_builtin_scene("cornell-empty-area", 8, 8);
  ImageTexture t;
  t.name = "nan.exr";
  t.width = 2;
  t.height = 1;
  t.texels = {Rgb(0.5f), Rgb(std::nanf(""), 0.f, 0.f)};
  textured.add_texture(t);
  textured.finalize();
  try {
    RenderSession session(textured, make_render_config("pt", PtSettings{}));
    ADD_FAILURE() << "a NaN texel was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("texel (1, 0)"), std::string::npos) << e.what();
  }
  textured.textures[0].texels[1] = Rgb(-0.25f, 0.f, 0.f);  // negative: used, with a warning
  const RenderSession session(textured, make_render_config("pt", PtSettings{}));
  ASSERT_EQ(session.scene_warnings().size(), 1u);
  EXPECT_NE(session.scene_warnings()[0].find("1 of its 2 texels are negative"), std::string::npos) << session.scene_warnings()[0];
}

}  // namespace
}  // namespace pathspace

namespace pathspace {
namespace {

// The scene's output colour matrix (pbrt-v4's film white balance) transforms the images a snapshot
// hands out: the same render with and without it differ by exactly that matrix.
TEST(SessionSnapshot, AppliesTheScenesOutputColorMatrix) {
  Scene plain = make_builtin_scene("cornell-box", 8, 8);
  Scene balanced = plain;
  balanced.output_color_matrix = {1.1f, 0.1f, 0.f, 0.f, 0.9f, 0.f, 0.05f, 0.f, 1.2f};
  const RenderConfig config = make_render_config("pt", PtSettings{}, 7);
  RenderSession a(std::move(plain), config), b(std::move(balanced), config);
  a.run(RunLimit::for_passes(2));
  b.run(RunLimit::for_passes(2));
  const RenderSnapshot sa = a.snapshot(), sb = b.snapshot();
  ASSERT_EQ(sa.mean.size(), sb.mean.size());
  for (size_t i = 0; i < sa.mean.size(); ++i) {
    const Rgb& c = sa.mean.pixels[i];
    const Rgb& v = sa.variance.pixels[i];
    EXPECT_FLOAT_EQ(sb.mean.pixels[i].r, 1.1f * c.r + 0.1f * c.g);
    EXPECT_FLOAT_EQ(sb.mean.pixels[i].g, 0.9f * c.g);
    EXPECT_FLOAT_EQ(sb.mean.pixels[i].b, 0.05f * c.r + 1.2f * c.b);
    EXPECT_FLOAT_EQ(sb.variance.pixels[i].r, 1.1f * 1.1f * v.r + 0.1f * 0.1f * v.g);
  }
}

}  // namespace
}  // namespace pathspace

namespace pathspace {
namespace {

// pixel(x, y), the viewer's pixel inspector: the snapshot's mean and variance at that pixel, bit for
// bit, and the pass count as its samples; a pixel outside the image is an error.
TEST(SessionPixel, IsTheSnapshotsPixel) {
  auto session = make_session(threaded(make_render_config("pt", PtSettings{}, kSeed)));
  session->run(RunLimit::for_passes(5));
  const RenderSnapshot snap = session->snapshot();
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{17, 9}, std::pair{kSize - 1, kSize - 1}}) {
    const PixelStats p = session->pixel(x, y);
    const size_t i = size_t(y) * kSize + size_t(x);
    EXPECT_EQ(std::memcmp(&p.mean, &snap.mean.pixels[i], sizeof(Rgb)), 0);
    EXPECT_EQ(std::memcmp(&p.variance_of_mean, &snap.variance.pixels[i], sizeof(Rgb)), 0);
    EXPECT_EQ(p.samples, 5u);
  }
  EXPECT_THROW(session->pixel(kSize, 0), Error);
  EXPECT_THROW(session->pixel(0, -1), Error);
}

}  // namespace
}  // namespace pathspace
