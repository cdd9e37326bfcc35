// The images of the shipped test scenes (scenes/), made by code so that anyone can regenerate and
// check them: a checkerboard and a brick texture (64x64 PNG) and a latitude-longitude sky
// environment map (64x32 PFM). Pure functions of nothing: the same bytes on every run.
#pragma once

#include <string>
#include <vector>

#include "pathspace/film/image.h"

namespace pathspace::scene_assets {

Image checkerboard();  // 8x8 squares of two greys, light square at the top left
Image bricks();        // running-bond bricks (16x8 texels) with 1-texel mortar joints
Image sky();           // lat-long, row 0 = up: blue sky brighter towards the horizon, a soft sun, dark ground

struct Asset {
  std::string relative_path;  // from the repository's scenes/ folder
  Image image;
};

// Every generated file of every shipped scene.
std::vector<Asset> all_assets();

// Writes all_assets() below `scenes_folder` (folders must exist).
void write_all(const std::string& scenes_folder);

}  // namespace pathspace::scene_assets
