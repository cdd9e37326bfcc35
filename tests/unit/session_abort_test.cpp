// RenderSession::abort (session/render_session.h), what `pathspace view` does when the camera moves:
//  - for every integrator and filter, a pass aborted from another thread midway is discarded and
//    leaves nothing behind: after begin_frame(), two passes equal bit for bit those of a session
//    that never ran the cut pass (the filter carried as the last whole pass left it, when the cut
//    came before the filter ran) or of a fresh session (the filter afresh, when it came later: a
//    half-updated table, e.g. the hashed filter's temporal one, is not carried);
//  - until then run(), snapshot() and save_state() refuse;
//  - the pass stops early: it traces well under half the rays of a whole pass;
//  - an abort() between runs acts as cancel(): the next run stops before its first pass, nothing
//    is discarded.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <future>
#include <memory>
#include <thread>

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

namespace pathspace {
namespace {

constexpr uint64_t kSeed = 11;

struct Shared {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const Accel> accel;
};

Shared cornell(int size) {
  Shared s;
  s.scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", size, size));
  s.accel = std::make_shared<const Accel>(*s.scene);
  return s;
}

RenderConfig threaded(RenderConfig c) {
  c.threads = 2;
  return c;
}

struct Case {
  const char* name;
  RenderConfig config;
};

std::vector<Case> cases() {
  HashedFilterSettings temporal;
  temporal.temporal.mode = TemporalMode::integrate;
  HashedFilterSettings adaptive;  // level choices carried from pass to pass (sec. 3.1.3)
  adaptive.adaptive = true;
  ConsistentFilterSettings caustics;
  caustics.caustics.photons_per_pixel = 1.0;
  return {
      {"pt", threaded(make_render_config("pt", PtSettings{}, kSeed))},
      {"pt_hashed_temporal", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", temporal))},
      {"pt_hashed", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", HashedFilterSettings{}))},
      {"pt_hashed_adaptive", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "hashed", adaptive))},
      {"pt_consistent_caustics", threaded(with_filter(make_render_config("pt", PtSettings{}, kSeed), "consistent", caustics))},
      {"lt", threaded(make_render_config("lt", LtSettings{}, kSeed))},
      {"bpt", threaded(make_render_config("bpt", BptSettings{}, kSeed))},
      {"sppm", threaded(make_render_config("sppm", SppmSettings{}, kSeed))},
      {"pclt", threaded(make_render_config("pclt", PcltSettings{}, kSeed))},
  };
}

bool same_bits(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// Waits (at most a minute) until the session's pass number `pass` has done some of its work.
void wait_until_inside(const RenderSession& session, uint32_t pass) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const PassProgress p = session.pass_progress();
    if (p.running && p.pass == pass && p.fraction > 0.0) return;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  FAIL() << "pass " << pass << " did not start within 60 s";
}

RunResult wait_for(std::future<RunResult>& done) {
  if (done.wait_for(std::chrono::seconds(120)) != std::future_status::ready) {
    std::fprintf(stderr, "FATAL: run() did not return within 120 s of abort()\n");
    std::abort();
  }
  return done.get();
}

class SessionAbort : public ::testing::TestWithParam<Case> {};

// Runs one pass, then aborts the second midway; false when that pass ended before abort() reached
// it (the run then stops after it, as after cancel()).
bool abort_second_pass(RenderSession* session) {
  EXPECT_EQ(session->run(RunLimit::for_passes(1)).passes, 1u);
  std::future<RunResult> done = std::async(std::launch::async, [&] { return session->run(RunLimit::until_cancelled()); });
  wait_until_inside(*session, 2);
  session->abort();
  const RunResult r = wait_for(done);
  EXPECT_TRUE(r.cancelled);
  if (r.aborted) {
    EXPECT_EQ(r.passes, 0u);
  }
  return r.aborted;
}

TEST_P(SessionAbort, DiscardsThePassAndLeavesNothingBehind) {
  const Shared s = cornell(160);
  std::unique_ptr<RenderSession> session;
  for (int attempt = 0; attempt < 5 && !session; ++attempt) {
    session = std::make_unique<RenderSession>(s.scene, s.accel, GetParam().config);
    if (!abort_second_pass(session.get())) session.reset();
  }
  ASSERT_TRUE(session) << "five passes ended before abort() reached them";
  EXPECT_TRUE(session->aborted());
  EXPECT_THROW(session->snapshot(), Error);
  EXPECT_THROW(session->save_state(), Error);
  EXPECT_THROW(session->run(RunLimit::for_passes(1)), Error);

  session->begin_frame(s.scene, s.accel, 1);
  EXPECT_FALSE(session->aborted());
  ASSERT_EQ(session->run(RunLimit::for_passes(2)).passes, 2u);
  const RenderSnapshot a = session->snapshot();
  const auto frame_one = [&](bool after_one_pass) {
    RenderSession other(s.scene, s.accel, GetParam().config);
    if (after_one_pass) other.run(RunLimit::for_passes(1));
    other.begin_frame(s.scene, s.accel, 1);
    other.run(RunLimit::for_passes(2));
    return other.snapshot();
  };
  const RenderSnapshot uncut = frame_one(true), fresh = frame_one(false);
  const bool as_uncut = same_bits(a.mean, uncut.mean) && same_bits(a.variance, uncut.variance);
  const bool as_fresh = same_bits(a.mean, fresh.mean) && same_bits(a.variance, fresh.variance);
  EXPECT_TRUE(as_uncut || as_fresh) << "the cut pass left something behind";
  EXPECT_EQ(a.stats.paths, fresh.stats.paths);
}

INSTANTIATE_TEST_SUITE_P(Integrators, SessionAbort, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(SessionAbortWork, StopsThePassInFlightEarly) {
  const Shared s = cornell(384);
  RenderSession session(s.scene, s.accel, threaded(make_render_config("bpt", BptSettings{}, kSeed)));
  ASSERT_EQ(session.run(RunLimit::for_passes(1)).passes, 1u);
  const uint64_t whole = session.stats().rays;  // the rays of one whole pass
  std::future<RunResult> done = std::async(std::launch::async, [&] { return session.run(RunLimit::until_cancelled()); });
  wait_until_inside(session, 2);
  session.abort();
  const RunResult r = wait_for(done);
  ASSERT_TRUE(r.aborted);
  // Counted in work, not time: a BPT pass is one loop over the pixels in small chunks, and only the
  // chunks in flight when the abort came finish.
  const uint64_t cut = session.stats().rays - whole;
  EXPECT_LT(cut, whole / 2) << "the cut pass traced " << cut << " of a whole pass's " << whole << " rays";
}

TEST(SessionAbortWork, BetweenRunsActsAsCancel) {
  const Shared s = cornell(32);
  RenderSession session(s.scene, s.accel, threaded(make_render_config("pt", PtSettings{}, kSeed)));
  session.abort();
  const RunResult r = session.run(RunLimit::for_passes(3));
  EXPECT_TRUE(r.cancelled);
  EXPECT_FALSE(r.aborted);
  EXPECT_EQ(r.passes, 0u);
  EXPECT_FALSE(session.aborted());
  EXPECT_EQ(session.run(RunLimit::for_passes(2)).passes, 2u);
}

}  // namespace
}  // namespace pathspace
