// Checkpoint files: a render's whole state on disk, so that it can be continued bit for bit
// (`pathspace render --checkpoint FILE`, `--resume FILE`; docs/checkpoints.md).
//
// Layout (little-endian; docs/checkpoints.md has the table):
//   8 bytes   magic "PSCKPT\r\n"
//   4 bytes   format version (kCheckpointFormatVersion)
//   8 bytes   size H of the header
//   H bytes   header: JSON text, self-describing (pathspace version, scene and its hash, integrator,
//             filter, every option that affects the image, passes, time spent)
//   8 bytes   size S of the state
//   S bytes   the RenderSession's state (session/render_session.h, base/state_archive.h)
//   4 bytes   CRC-32 (zlib) of every byte before it
// Reading checks the magic, the version, the sizes and the checksum before anything else, so a
// truncated, damaged or foreign file is a clear pathspace::Error and never half-restored.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pathspace/base/input_file_log.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

inline constexpr uint32_t kCheckpointFormatVersion = 1;

// An option as it was given on the command line: its name without dashes and its values (none for a
// flag, several for a repeated option).
struct GivenOption {
  std::string name;
  std::vector<std::string> values;
  bool operator==(const GivenOption&) const = default;
};

// The header: what a checkpoint holds, readable without restoring it (`pathspace info FILE`).
struct CheckpointInfo {
  uint32_t format_version = kCheckpointFormatVersion;
  std::string pathspace_version;  // of the build that wrote it (set by encode_checkpoint)
  std::string scene;              // a built-in scene's name, or the scene file's path as given
  std::string scene_hash;         // "fnv1a64:<hex>" of the scene file's bytes; "builtin:<name>"
  std::string integrator, filter;
  int width = 0, height = 0;
  uint64_t seed = 0;
  // Every option that affects the image, with its value in canonical form ("psf-scale" -> "4"):
  // a resumed render must have the same list.
  std::vector<std::pair<std::string, std::string>> options;
  // The image-affecting options as they were given, so a resume need not repeat them.
  std::vector<GivenOption> given;
  uint32_t passes = 0;  // samples per pixel for the camera-path integrators, iterations otherwise
  double seconds = 0.0;  // time spent in passes, over all runs
  uint64_t paths = 0;
};

struct Checkpoint {
  CheckpointInfo info;
  SessionState state;
};

// The header as the file holds it (JSON text).
std::string checkpoint_header_json(const CheckpointInfo& info);

// The whole file's bytes.
std::vector<uint8_t> encode_checkpoint(const CheckpointInfo& info, const SessionState& state);
// Throws pathspace::Error naming `path` when the bytes are not a complete, intact checkpoint of this
// format version.
Checkpoint decode_checkpoint(std::string_view bytes, const std::string& path);

// Written atomically (io/atomic_file.h): the previous file stays until the new one is complete.
void write_checkpoint(const std::string& path, const CheckpointInfo& info, const SessionState& state);
Checkpoint read_checkpoint(const std::string& path);

// "fnv1a64:<16 hex digits>" of a file's bytes (as stored, not decompressed). Throws pathspace::Error.
std::string scene_file_hash(const std::string& path);
// The same for a scene that reads several files (base/input_file_log.h, the main file first): the
// main file's alone is scene_file_hash's, so checkpoints of one-file scenes keep their key; every
// further file (an Include, a mesh, a texture) changes it when its bytes change.
std::string scene_files_hash(const std::vector<InputFile>& files);

}  // namespace pathspace
