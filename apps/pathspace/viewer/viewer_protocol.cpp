#include "viewer/viewer_protocol.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "viewer/display.h"

namespace pathspace::viewer {

namespace {

using json = nlohmann::json;

// A finite number within [-limit, limit] under `key` (0 when absent).
double number(const json& j, const char* key, double limit) {
  if (!j.contains(key)) return 0.0;
  const json& v = j.at(key);
  if (!v.is_number()) throw Error(fmt::format("\"{}\" must be a number", key));
  const double x = v.get<double>();
  if (!std::isfinite(x) || std::fabs(x) > limit) throw Error(fmt::format("\"{}\" must be a finite number within +-{}", key, limit));
  return x;
}

// A pixel coordinate under `key`: a whole number in [0, 65535].
int pixel_index(const json& j, const char* key) {
  if (!j.contains(key)) throw Error(fmt::format("\"{}\" is missing", key));
  const double x = number(j, key, 65535.0);
  if (x < 0.0 || x != std::floor(x)) throw Error(fmt::format("\"{}\" must be a whole number within 0..65535", key));
  return int(x);
}

// A string under `key` of at most `limit` bytes; `name_like`: a lower-case letter, then lower-case
// letters, digits and '-'.
std::string text(const json& j, const char* key, size_t limit, bool name_like) {
  if (!j.contains(key) || !j.at(key).is_string()) throw Error(fmt::format("\"{}\" must be a string", key));
  const std::string s = j.at(key).get<std::string>();
  if (s.size() > limit) throw Error(fmt::format("\"{}\" is longer than {} bytes", key, limit));
  if (name_like && (s.empty() || !(s[0] >= 'a' && s[0] <= 'z') || !std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; })))
    throw Error(fmt::format("\"{}\" is an option name without dashes: a lower-case letter, then lower-case letters, digits and '-'", key));
  return s;
}

void only_fields(const json& j, const std::set<std::string>& allowed) {
  for (const auto& item : j.items())
    if (!allowed.count(item.key())) throw Error(fmt::format("unknown field \"{}\"", item.key()));
}

}  // namespace

Command parse_command(const std::string& message) {
  if (message.size() > kMaxMessageBytes) throw Error(fmt::format("message of {} bytes (at most {})", message.size(), kMaxMessageBytes));
  const json j = json::parse(message, nullptr, false, true);
  if (j.is_discarded() || !j.is_object()) throw Error("a message is one JSON object");
  if (!j.contains("cmd") || !j.at("cmd").is_string()) throw Error("a message needs \"cmd\": a string");
  const std::string cmd = j.at("cmd").get<std::string>();
  if (cmd == "frame") {
    only_fields(j, {"cmd"});
    return FrameRequest{};
  }
  if (cmd == "move") {
    only_fields(j, {"cmd", "right", "up", "forward"});
    return Move{number(j, "right", 1e3), number(j, "up", 1e3), number(j, "forward", 1e3)};
  }
  if (cmd == "turn") {
    only_fields(j, {"cmd", "yaw", "pitch"});
    return Turn{number(j, "yaw", 360.0), number(j, "pitch", 360.0)};
  }
  if (cmd == "reset") {
    only_fields(j, {"cmd"});
    return Reset{};
  }
  if (cmd == "exposure") {
    only_fields(j, {"cmd", "stops"});
    return Exposure{number(j, "stops", 20.0)};
  }
  if (cmd == "tonemap") {
    only_fields(j, {"cmd", "name"});
    const std::string name = text(j, "name", 64, true);
    parse_tone_map(name);  // an unknown curve is refused here, before anything acts
    return ToneMapChoice{name};
  }
  if (cmd == "options") {
    only_fields(j, {"cmd"});
    return OptionsRequest{};
  }
  if (cmd == "set") {
    only_fields(j, {"cmd", "name", "value"});
    return SetOption{text(j, "name", 64, true), j.contains("value") ? text(j, "value", 256, false) : std::string()};
  }
  if (cmd == "unset") {
    only_fields(j, {"cmd", "name"});
    return UnsetOption{text(j, "name", 64, true)};
  }
  if (cmd == "show") {
    only_fields(j, {"cmd", "image"});
    return Show{text(j, "image", 64, true)};
  }
  if (cmd == "save") {
    only_fields(j, {"cmd"});
    return Save{};
  }
  if (cmd == "split") {
    only_fields(j, {"cmd", "filter", "integrator"});
    return Split{text(j, "filter", 64, true), j.contains("integrator") ? text(j, "integrator", 64, true) : std::string()};
  }
  if (cmd == "inspect") {
    only_fields(j, {"cmd", "x", "y"});
    return Inspect{pixel_index(j, "x"), pixel_index(j, "y")};
  }
  if (cmd == "record" || cmd == "play") {
    only_fields(j, {"cmd", "on"});
    if (!j.contains("on") || !j.at("on").is_boolean()) throw Error("\"on\" must be true or false");
    const bool on = j.at("on").get<bool>();
    return cmd == "record" ? Command(Record{on}) : Command(Play{on});
  }
  if (cmd == "seek") {
    only_fields(j, {"cmd", "seconds"});
    const double seconds = number(j, "seconds", 1e6);
    if (seconds < 0.0) throw Error("\"seconds\" must be a finite number within 0..1e6");
    return Seek{seconds};
  }
  throw Error(fmt::format("unknown command \"{}\" (frame, move, turn, reset, exposure, options, set, unset, show, save, split, record, inspect, play, seek, tonemap)",
                          cmd.substr(0, 40)));
}

}  // namespace pathspace::viewer
