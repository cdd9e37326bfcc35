#include "fuzz/checkpoint_input.h"

#include <memory>
#include <vector>

#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace::fuzz {

namespace {

constexpr std::string_view kStateMagic = "PSSTATE1";

std::vector<std::unique_ptr<RenderSession>>& sessions() {
  static std::vector<std::unique_ptr<RenderSession>> made = [] {
    const auto scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", 8, 8));
    std::vector<RenderConfig> configs;
    for (const char* name : {"pt", "lt", "bpt", "sppm", "pclt"}) {
      RenderConfig c;
      c.integrator = name;
      configs.push_back(c);
    }
    configs.push_back(with_filter(make_render_config("pt", PtSettings{}), "hashed", HashedFilterSettings{}));
    configs.push_back(with_filter(make_render_config("pt", PtSettings{}), "consistent", ConsistentFilterSettings{}));
    HashedFilterSettings temporal;  // its state holds the table's keys and histories
    temporal.temporal.mode = TemporalMode::integrate;
    configs.push_back(with_filter(make_render_config("pt", PtSettings{}), "hashed", temporal));
    std::vector<std::unique_ptr<RenderSession>> out;
    for (RenderConfig& c : configs) {
      c.threads = 1;
      out.push_back(std::make_unique<RenderSession>(scene, nullptr, c));
    }
    return out;
  }();
  return made;
}

// Restores into the session of the state's integrator and filter; true when one accepted it.
bool restore_state(const SessionState& state) {
  Error last("no reference session");
  for (const std::unique_ptr<RenderSession>& s : sessions()) {
    try {
      s->restore_state(state);
      return true;
    } catch (const Error& e) {
      last = e;
    }
  }
  throw last;
}

}  // namespace

bool restore_checkpoint_bytes(std::string_view bytes) {
  if (bytes.substr(0, kStateMagic.size()) == kStateMagic) return restore_state(SessionState{{bytes.begin(), bytes.end()}});
  return restore_state(decode_checkpoint(bytes, "fuzz.ckpt").state);
}

}  // namespace pathspace::fuzz
