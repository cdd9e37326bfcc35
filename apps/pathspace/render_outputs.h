// The files of `pathspace render` (images, variance, debug images, --stats JSON), written from one
// snapshot (and the checkpoint, when one is due) as one OutputSet (io/atomic_file.h): at any moment the folder holds the previous complete
// set or the new one. Used for the final outputs and for --write-every.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/session/render_session.h"
#include "pathspace/session/render_stats_json.h"

namespace pathspace::cli {

struct OutputPlan {
  std::vector<std::string> images;  // -o, at least one
  std::string variance;             // --variance-out, or empty
  std::string stats;                // --stats, or empty
  RenderRunInfo run;                // for the stats JSON (its outputs are filled in)
};

// Periodic sets are soon replaced: they are encoded fast (io/image_io.h, ImageEncoding).
enum class OutputKind { final, periodic };

// The image outputs: -o as given, else pathspace-out/NAME.exr and .png (the folder is created).
std::vector<std::string> image_output_paths(const std::vector<std::string>& given, const std::string& name);
// An image output given to `option`: an extension that names a format and a writable folder, or a
// UsageError. "-o" takes every word up to the next option, so a scene name after "-o a.exr" lands
// here and gets its own message instead of "unsupported extension".
void check_image_path(const std::string& option, const std::string& path);

// "out/a.exr" + "voxel" -> "out/a.aov-voxel.exr".
std::string aov_path(const std::string& first_image, const std::string& aov);

// A file written with the outputs, in the same set (the checkpoint).
struct ExtraOutput {
  std::string path;
  std::vector<uint8_t> bytes;
};

// Writes every file of `plan` from `snapshot`, then `extra`, as one set; returns the paths written.
std::vector<std::string> write_outputs(const OutputPlan& plan, const RenderSnapshot& snapshot, OutputKind kind,
                                       const ExtraOutput* extra = nullptr);

}  // namespace pathspace::cli
