// Byte-level entry points of the scene parsers, shared by the libFuzzer targets (fuzz_*.cpp, clang,
// PATHSPACE_FUZZ) and the corpus replay unit test (unit/fuzz_corpus_replay_test.cpp, any compiler),
// so a crasher saved in the corpus is replayed through exactly the code the fuzzer ran.
// Contract for every input: the loader returns a Scene or throws a pathspace::Error that names at
// least a file. Any other exception escapes these functions and counts as a finding.
#pragma once

#include <string>
#include <string_view>

#include "pathspace/base/error.h"
#include "support/temp_dir.h"

namespace pathspace::fuzz {

enum class Format { pbrt, ply, obj, mitsuba, gltf, image };

// "pbrt", "ply", "obj", "mitsuba", "gltf", "image": the corpus folder names (tests/fuzz/corpus/<name>/).
const char* format_name(Format f);
// False for mitsuba when this build has no Mitsuba loader.
bool format_available(Format f);

struct Outcome {
  bool loaded = false;  // a Scene came back
  std::string error;    // the Error's message otherwise
  FileLoc location;     // the Error's location
};

// A private folder holding small files a fuzzed scene may reference (Include "inc.pbrt", plymesh
// "mesh.ply", imagemap "tex.pfm", mtllib "scene.mtl"), so those code paths are reachable.
class InputFolder {
 public:
  InputFolder();
  const std::string& path() const { return path_; }

 private:
  pathspace::testing::TempDir dir_;
  std::string path_;
};

// Loads `bytes` as a file of the given format. OBJ input is written to scene.obj in the folder;
// glTF input to scene.gltf (JSON or GLB bytes alike: the loader looks at the content);
// bytes after a line "#--- scene.mtl ---" become scene.mtl (so one input covers OBJ and MTL).
// Image input (the readers of textures, environment maps and `compare`): the first byte picks the
// name the bytes are decoded under (fuzz.exr, fuzz.pfm, fuzz.png, fuzz.hdr: the extension chooses
// the decoder where the content does not), the rest is the file.
Outcome load_bytes(Format format, std::string_view bytes, const InputFolder& folder);

}  // namespace pathspace::fuzz
