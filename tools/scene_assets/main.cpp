// pathspace-scene-assets [SCENES_FOLDER]: regenerates the shipped scenes' textures and environment
// map (default: ./scenes). The committed files must equal its output (unit test ShippedScenes.*).
#include <cstdio>
#include <exception>
#include <string>

#include "scene_assets.h"

int main(int argc, char** argv) {
  const std::string folder = argc > 1 ? argv[1] : "scenes";
  try {
    pathspace::scene_assets::write_all(folder);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pathspace-scene-assets: %s\n", e.what());
    return 1;
  }
  for (const auto& a : pathspace::scene_assets::all_assets()) std::printf("%s/%s\n", folder.c_str(), a.relative_path.c_str());
  return 0;
}
