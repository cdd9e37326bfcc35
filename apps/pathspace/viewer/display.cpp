#include "viewer/display.h"

#include "pathspace/base/error.h"

namespace pathspace::viewer {

const std::vector<std::string>& tone_map_names() {
  static const std::vector<std::string> names = {"clip", "reinhard", "aces"};
  return names;
}

ToneMap parse_tone_map(const std::string& name) {
  const std::vector<std::string>& names = tone_map_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return ToneMap(i);
  throw Error("unknown tone map \"" + name.substr(0, 40) + "\" (clip, reinhard, aces)");
}

const std::string& tone_map_name(ToneMap tone) { return tone_map_names()[size_t(tone)]; }

namespace {

float aces_fit(float x) { return x <= 0.f ? 0.f : x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f); }

}  // namespace

Image displayed(const Image& image, const Display& display) {
  Image shown = image;
  for (Rgb& p : shown.pixels) {
    p = p * display.scale;
    switch (display.tone) {
      case ToneMap::clip: break;
      case ToneMap::reinhard: {
        const float l = luminance(p);
        if (l > 0.f) p = p * (1.f / (1.f + l));
        break;
      }
      case ToneMap::aces: p = Rgb(aces_fit(p.r), aces_fit(p.g), aces_fit(p.b)); break;
    }
  }
  return shown;
}

}  // namespace pathspace::viewer
