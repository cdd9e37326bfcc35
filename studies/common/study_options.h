// The options of the studies (studies/): plain structs that the CLI's `pathspace study` fills
// (apps/pathspace/study_command.cpp) and the studies read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pathspace::studies {

// The options every study has.
struct StudyOptions {
  std::string out;
  std::string resolution = "128x128";
  double time_s = 5.0;            // equal-time budget per image (pclt); the references' time / 20
  double reference_time_s = 0.0;  // 0: 20 x time_s
  // A folder of references made elsewhere (e.g. long PT renders): a scene whose <name>.exr is there
  // reads it (and <name>.variance.exr when present) instead of rendering its reference.
  std::string reference_dir;
  std::vector<std::string> scenes;
  uint64_t seed = 0;
  int threads = 0;
  bool no_exr = false;
  bool quiet = false;
};

// `study psf`'s own options.
struct PsfStudyOptions {
  uint32_t max_spp = 64;                         // last checkpoint of the 2014 paper's fig. 3
  std::string vertex_set_resolution = "1920x1080";  // the hash table figures' vertex sets (2019 figs. 7, 8)
  // The hashed filter across frames (2021 sec. 3.4, studies/psf2021/temporal_figures.cpp); 0 skips that part.
  uint32_t temporal_frames = 64;     // orbit frames of sec. 3.4.1 (fig. 9 uses min(32, this))
  uint32_t eviction_frames = 10000;  // frames of the eviction flight (sec. 3.4.3)
  std::string room_scene = "scenes/textured-room/scene.pbrt";  // relative: to the working folder, else to the repository of the binary
  // The equal-time figures: one per count, each giving every method the hashed filter's time for that
  // many paths per pixel (studies/psf/equal_time.cpp).
  std::vector<uint32_t> equal_time_spp = {1, 4, 16};
  // The figures to make (ids as on the page, "equal-time" for every equal-time figure); empty: all.
  std::vector<std::string> figures;
};

// `study gallery`'s options (studies/gallery/gallery.h).
struct GalleryOptions {
  std::string dir;
  std::string out = "pathspace-out/gallery";
  double time_s = 60.0;        // per scene
  std::string integrator = "bpt";
  uint64_t seed = 0;
  int threads = 0;
  bool substitute_missing_textures = false;
  bool no_exr = false;
  bool quiet = false;
};

}  // namespace pathspace::studies
