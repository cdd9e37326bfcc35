// Options that several path space filters share with one contract (name, range, meaning), defined once.
#pragma once

#include "pathspace/filters/caustic_settings.h"
#include "pathspace/options/option_table.h"

namespace pathspace {

// --psf-aa-paths: extra camera paths per pixel and pass that end at their first filtered vertex and
// take its value from the filter (FilterNeeds::query_paths): anti-aliasing for the price of a
// primary ray and a query, not a path (Keller, Dahm, Binder 2014, sec. 3, fig. 7).
template <typename Settings, typename Field>
void add_aa_paths_option(OptionTable<Settings>& table, Field field) {
  table.number("psf-aa-paths", field, 0, 64,
               "Extra camera paths per pixel and pass that only query the filtered vertices (anti-aliasing); empty queries are not counted",
               "2014 paper, sec. 3, fig. 7");
}

// --psf-caustic-*: photon-mapped caustics beside the filter (FilterNeeds::caustics): the path tracer
// leaves out light -> specular+ -> diffuse paths and gathers a caustic photon map at its diffuse
// vertices instead, so caustics are not averaged over a voxel or ball into blotches (Keller, Dahm,
// Binder 2014, sec. 2.3; the 2021 paper's remark that its hashing can serve photon mapping).
template <typename Settings>
void add_caustic_options(OptionTable<Settings>& table, CausticSettings Settings::*caustics) {
  table.number("psf-caustic-photons", [caustics](Settings& s) -> double& { return (s.*caustics).photons_per_pixel; }, 0.0, 1e4,
               "Caustic photons per pixel and pass: light -> specular -> diffuse paths come from a photon map gathered at diffuse "
               "vertices, not from path tracing, and the first selected vertex's gather is not filtered (0: off)",
               "2014 paper, sec. 2.3, fig. 1");
  table.number("psf-caustic-radius", [caustics](Settings& s) -> float& { return (s.*caustics).initial_radius; }, 0.0, 1e30,
               "Caustic photon radius of the first pass in scene units (0: 1% of the scene's bounding radius)", "2014 paper, sec. 2.3");
  table.number("psf-caustic-alpha", [caustics](Settings& s) -> float& { return (s.*caustics).alpha; }, 1e-3, 1.0,
               "Caustic radius shrinking: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus-Zwicker)", "2014 paper, sec. 2.3");
  table.number("psf-caustic-roughness", [caustics](Settings& s) -> float& { return (s.*caustics).min_roughness; }, 0.0, 1.0,
               "Vertices with a layer smoother than this are links of caustic chains (photons pass them, they gather none): "
               "near-specular glossy reflections of lights come from the photon map too (Phong exponent 20 ~ 0.3)",
               "2014 paper, sec. 2.3");
  table.flag("psf-one-bounce-photons", [caustics](Settings& s) -> bool& { return (s.*caustics).one_bounce; }, true,
             "Also photons after one diffuse bounce, gathered at every rough vertex of a path, the first of which alone estimates "
             "direct light: light that reaches walls off a small lit patch (a lamp in a shade, a spot) comes from the lights' "
             "side (needs --psf-caustic-photons)",
             "2014 paper, sec. 2.3");
  table.check([caustics](const Settings& s) {
    if ((s.*caustics).one_bounce && !(s.*caustics).enabled())
      throw OptionError("--psf-one-bounce-photons are traced with the caustic photons: it needs --psf-caustic-photons above 0");
  });
}

}  // namespace pathspace
