// Host-side integrator interface: an integrator renders one sample pass at a time into a Film, each
// pass a pure function of (scene, settings, seed, pass index). The render driver (render.h) runs
// passes until a sample count or a time budget is reached.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/film/film.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/filters/filter_settings.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"

namespace pathspace {

class Accel;
class Scene;

struct IntegratorSettings {
  uint64_t seed = 0;
  PtSettings pt;
  LtSettings lt;
  FilterSettings filter;
  SppmSettings sppm;
  PcltSettings pclt;
  BptSettings bpt;
};

// A named debug image an integrator can provide after rendering (e.g. the filter's voxel ids).
struct NamedImage {
  std::string name;
  Image image;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual const char* name() const = 0;
  // Renders pass `pass` (one sample per pixel for PT) into film; adds to counters.
  virtual void render_pass(uint32_t pass, Film& film, PathCounters& counters) = 0;
  // Human-readable statistics beyond the common counters (e.g. hash table behaviour); may be empty.
  virtual std::string report() const { return {}; }
  // Debug images (AOVs) of the last pass.
  virtual std::vector<NamedImage> aovs() const { return {}; }
};

// The integrators selectable by name ("pt").
const std::vector<std::string>& integrator_names();
// Throws pathspace::Error for an unknown name.
std::unique_ptr<Integrator> make_integrator(const std::string& name, const Scene& scene, const Accel& accel,
                                            const IntegratorSettings& settings);

}  // namespace pathspace
