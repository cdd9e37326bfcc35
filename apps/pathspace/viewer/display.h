// How the page shows a linear image: the display exposure, then a tone curve, then (in the PNG
// encoder) the sRGB transfer function and 8 bits. Saved EXR files stay as rendered.
#pragma once

#include <string>
#include <vector>

#include "pathspace/film/image.h"

namespace pathspace::viewer {

enum class ToneMap {
  clip,      // linear: values above 1 clip (what `render -o x.png` writes)
  reinhard,  // L / (1 + L) on the luminance, the hue kept (Reinhard et al. 2002, eq. 3)
  aces,      // a fit of the ACES filmic curve per channel (Narkowicz 2015)
};

const std::vector<std::string>& tone_map_names();  // "clip", "reinhard", "aces"
// Throws pathspace::Error naming the choices.
ToneMap parse_tone_map(const std::string& name);
const std::string& tone_map_name(ToneMap tone);

struct Display {
  float scale = 1.f;  // 2^stops of the exposure
  ToneMap tone = ToneMap::clip;
};

// The image as the page shows it (before sRGB encoding).
Image displayed(const Image& image, const Display& display);

}  // namespace pathspace::viewer
