// Options of the consistent path space filter (Keller, Dahm, Binder 2014) and their defaults.
#pragma once

#include <cstdint>

#include "pathspace/filters/caustic_settings.h"

namespace pathspace {

// Binary similarity weights of sec. 2.1 (bit set: the weight is on).
enum ConsistentWeight : uint32_t {
  kWeightNormal = 1u << 0,  // <n_j, n_i> >= normal_threshold ("blur across geometry")
  kWeightAlbedo = 1u << 1,  // similar stored attenuation, and on glossy layers similar directions ("blur across textures")
  kWeightVisibility = 1u << 2,  // identical visibility of each delta light, similar hemisphere-ray length ("blurred shadows")
};

struct ConsistentFilterSettings {
  float alpha = 0.25f;             // eq. 2: r(n) = r0 / n^alpha; "alpha = 1/4 is a robustly working choice" (sec. 2.2)
  // r0 from the solid angle of K x K pixels at the camera path's length (sec. 2.2). The paper's
  // example is 3 x 3; with it the filter lost to PT at equal time on every measured scene, with 8 it
  // wins on all of them (docs/results/filter-quality.md), so 8 is the default.
  float radius_pixels = 8.f;
  float radius = 0.f;              // > 0: r0 in scene units for every vertex instead
  // r0 of a vertex in a participating medium, in multiples of a surface vertex's: a ball of K x K
  // pixels around a point of a volume holds far fewer vertices than around a point of a surface
  // (docs/media.md, path space filtering in media).
  float medium_radius_scale = 1.5f;
  uint32_t weights = kWeightNormal | kWeightAlbedo | kWeightVisibility;
  float normal_threshold = 0.95f;  // sec. 2.1: "<n_j, n_i> >= 0.95 (in our implementation)"
  float albedo_threshold = 0.05f;  // largest difference of the stored attenuation per channel
  float direction_threshold = 0.9f;  // glossy layers: <wo_j, wo_i> at least this
  float visibility_threshold = 0.25f;  // hemisphere rays: largest |l_i - l_j| / max(l_i, l_j)
  int iterations = 1;              // iterated averaging, fig. 2
  int aa_paths = 0;                // extra query-only camera paths per pixel and pass (sec. 3, fig. 7)
  double batch_memory_mb = 0.0;    // memory for one batch's filtering; 0: an eighth of the physical memory
  CausticSettings caustics;        // sec. 2.3: photon-mapped caustics (off: 0 photons)
};

}  // namespace pathspace
