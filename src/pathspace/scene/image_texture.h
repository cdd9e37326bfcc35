// The host-side owner of one image texture in a Scene: linear RGB texels plus the uv transform.
// Loaders fill it (io/texture_loading.h reads files); Scene::view() exposes it as a TextureView.
#pragma once

#include <string>
#include <vector>

#include "pathspace/scene/texture.h"

namespace pathspace {

struct ImageTexture {
  std::string name;  // file or scene name, for messages
  int width = 0, height = 0;
  std::vector<Rgb> texels;  // linear RGB, row 0 at the top
  float uscale = 1.f, vscale = 1.f, udelta = 0.f, vdelta = 0.f;
  bool nearest = false;  // nearest-texel lookup (procedural patterns baked into a few texels, Mitsuba's filter_type nearest)
  TextureWrap wrap = TextureWrap::repeat;

  TextureView view() const { return {texels.data(), width, height, uscale, vscale, udelta, vdelta, nearest, wrap}; }
  // Mean texel value (stand-in where a texture cannot be bound, e.g. on an emitter).
  Rgb mean() const {
    Rgb sum;
    for (const Rgb& t : texels) sum += t;
    return texels.empty() ? Rgb() : sum * (1.f / float(texels.size()));
  }
};

}  // namespace pathspace
