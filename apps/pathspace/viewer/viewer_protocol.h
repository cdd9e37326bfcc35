// The messages a `pathspace view` page sends over its WebSocket (docs/viewer.md): one JSON object
// per text message, parsed and checked here before anything acts on it, so that a malformed,
// oversized or unknown message is an error to that client and nothing else.
#pragma once

#include <cstddef>
#include <string>
#include <variant>

namespace pathspace::viewer {

inline constexpr size_t kMaxMessageBytes = 4096;

// The next frame, once one newer than the last sent exists.
struct FrameRequest {};
// Camera motion in its own frame: right, up and forward steps (units of the move speed).
struct Move {
  double right = 0, up = 0, forward = 0;
};
// Camera rotation in degrees: yaw about the camera's up, pitch about its right axis.
struct Turn {
  double yaw = 0, pitch = 0;
};
// Back to the scene's camera.
struct Reset {};
// Display exposure in stops (the render is unchanged).
struct Exposure {
  double stops = 0;
};
// The display's tone curve by name: clip, reinhard or aces (display.h).
struct ToneMapChoice {
  std::string name;
};
// The options the current integrator and filter take, from the registry (with their values now).
struct OptionsRequest {};
// Gives an integrator or filter option (by name, without dashes; a flag's value is ignored), or
// "integrator" / "filter" themselves; applied as `render` would parse it, or refused with its error.
struct SetOption {
  std::string name, value;
};
// Takes an option back to its default.
struct UnsetOption {
  std::string name;
};
// Which image the frames show: "image" (the render) or one of the debug images its options asked
// for (the hashed filter's --aov: voxel, count, level, probes), by name.
struct Show {
  std::string image;
};
// Saves the newest frame as EXR (linear, as rendered) and PNG (exposure applied) in the viewer's
// output folder.
struct Save {};
// Split screen: the right half rendered by `integrator` (empty: the view's own) under `filter`
// ("none", "hashed", ...) with the view's options that apply there, or "off".
struct Split {
  std::string filter;
  std::string integrator;
};
// The pixel inspector: pixel (x, y) of the film (its mean, variance of the mean and samples, and the
// reference's value with --reference).
struct Inspect {
  int x = 0, y = 0;
};
// Starts (on) or stops recording the frames shown, as numbered PNG files and, on stop, a video.
struct Record {
  bool on = false;
};
// Plays the scene's animation (a frame of 1 / --fps seconds after each pass) or pauses it.
struct Play {
  bool on = false;
};
// Sets the animation's time in seconds (the nearest frame).
struct Seek {
  double seconds = 0;
};
using Command =
    std::variant<FrameRequest, Move, Turn, Reset, Exposure, OptionsRequest, SetOption, UnsetOption, Show, Save, Split, Record, Inspect, Play, Seek, ToneMapChoice>;

// The command of one message. Throws pathspace::Error with the reason (not JSON, too long, unknown
// "cmd", a missing or non-finite or out-of-range number, an unknown field).
Command parse_command(const std::string& message);

}  // namespace pathspace::viewer
