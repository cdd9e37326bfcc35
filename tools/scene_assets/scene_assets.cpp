// Scene asset generation (see scene_assets.h). Texture colours are chosen as 8-bit sRGB values and
// stored as their exact linear decodings, so the PNG writer's sRGB encoding gives those bytes back.
#include "scene_assets.h"

#include <cmath>
#include <cstdint>

#include "pathspace/io/image_io.h"

namespace pathspace::scene_assets {

namespace {

float srgb8(int v) {
  const double c = v / 255.0;
  return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

Rgb srgb8(int r, int g, int b) { return Rgb(srgb8(r), srgb8(g), srgb8(b)); }

// A small integer hash for per-brick colour variation (deterministic, no library RNG).
uint32_t mix(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

}  // namespace

Image checkerboard() {
  Image img(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) img.at(x, y) = ((x / 8 + y / 8) % 2 == 0) ? srgb8(205, 200, 190) : srgb8(70, 75, 85);
  return img;
}

Image bricks() {
  Image img(64, 64);
  for (int y = 0; y < 64; ++y) {
    const int row = y / 8;
    for (int x = 0; x < 64; ++x) {
      const int shifted = x + (row % 2) * 8;  // running bond: every other row shifted by half a brick
      const int column = (shifted / 16) % 4;
      const bool mortar = y % 8 == 7 || shifted % 16 == 15;
      if (mortar) {
        img.at(x, y) = srgb8(190, 185, 175);
      } else {
        const int d = int(mix(uint32_t(row * 4 + column)) % 31) - 15;  // per-brick shade
        img.at(x, y) = srgb8(150 + d, 70 + d / 2, 50 + d / 3);
      }
    }
  }
  return img;
}

Image sky() {
  const int w = 64, h = 32;
  Image img(w, h);
  const double pi = 3.14159265358979323846;
  // The sun: elevation 35 degrees, centred on column 60 (just off -z in the lat-long mapping, so it shines
  // through the textured room's window onto the floor).
  const double sun_theta = (90.0 - 35.0) * pi / 180.0, sun_phi = 2.0 * pi * 60.5 / w;
  const double sx = std::sin(sun_theta) * std::cos(sun_phi), sy = std::cos(sun_theta), sz = std::sin(sun_theta) * std::sin(sun_phi);
  for (int y = 0; y < h; ++y) {
    const double theta = pi * (y + 0.5) / h;  // 0 = up
    for (int x = 0; x < w; ++x) {
      const double phi = 2.0 * pi * (x + 0.5) / w;
      const double dx = std::sin(theta) * std::cos(phi), dy = std::cos(theta), dz = std::sin(theta) * std::sin(phi);
      Rgb c;
      if (dy > 0.0) {
        const double horizon = std::pow(1.0 - dy, 3.0);  // brighter and whiter towards the horizon
        c = Rgb(float(0.25 + 0.75 * horizon), float(0.45 + 0.6 * horizon), float(1.0 + 0.3 * horizon));
        const double cos_sun = dx * sx + dy * sy + dz * sz;
        const double sun = std::exp((cos_sun - 1.0) * 40.0) * 6.0;  // a soft sun, a few texels wide
        c += Rgb(float(sun), float(sun * 0.9), float(sun * 0.7));
      } else {
        c = Rgb(0.12f, 0.1f, 0.08f);  // ground
      }
      img.at(x, y) = c;
    }
  }
  return img;
}

std::vector<Asset> all_assets() {
  return {{"textured-room/textures/checker.png", checkerboard()},
          {"textured-room/textures/bricks.png", bricks()},
          {"textured-room/textures/sky.pfm", sky()}};
}

void write_all(const std::string& scenes_folder) {
  for (const Asset& a : all_assets()) write_image(scenes_folder + "/" + a.relative_path, a.image);
}

}  // namespace pathspace::scene_assets
