// `--integrator pt`: the options of path tracing and its registration. The vertex selection
// options say where a path is split for path space filtering (2021 paper, sec. 4 and fig. 10).
#include <fmt/format.h>

#include "pathspace/filters/path_sample.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/integrators/common/common_options.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/pt/pt_integrator.h"

namespace pathspace {

namespace {

OptionTable<PtSettings> pt_options() {
  using S = PtSettings;
  OptionTable<S> t;
  add_max_depth_option(t, &S::max_segments);
  t.flag("no-nee", &S::nee, false, "No next event estimation (BSDF sampling only)");
  t.flag("no-bsdf-sampling", &S::bsdf_sampling, false, "Emission only through next event estimation");
  add_mis_option(t, &S::mis);
  t.number("equiangular-segments", &S::equiangular_segments, 0, 64,
           "In homogeneous media: a light sample at an equiangular distance along each of a path's first N segments "
           "(1: the camera ray; 0: none), beside the one at the distance-sampled vertex: the glow around small lights "
           "in fog without fireflies",
           "Kulla and Fajardo 2012; docs/media.md");
  t.flag("texture-footprint", &S::texture_footprint, true,
         "Average the textures at a camera ray's hit over its pixel (up to 4x4 lookups): no texture aliasing at 1 spp; "
         "biased where lighting and texture vary together inside a pixel",
         "Igehy 1999 (ray differentials); docs/animation.md");
  t.choice("psf-select", [](S& s) -> VertexSelectionMode& { return s.selection.mode; },
           std::vector<std::pair<std::string, VertexSelectionMode>>{
               {"first", VertexSelectionMode::first}, {"nth", VertexSelectionMode::nth}, {"all", VertexSelectionMode::all}},
           "With --filter: vertex selection, first / nth / all sufficiently diffuse vertices", "2021 paper, sec. 4, fig. 10");
  t.number("psf-nth", [](S& s) -> int& { return s.selection.n; }, 1, 16,
           "With --psf-select nth: which diffuse vertex (2 = final gather)", "2021 paper, fig. 10");
  t.number("psf-max-vertices", [](S& s) -> int& { return s.selection.max_vertices; }, 1, kMaxSelectedVertices,
           "With --psf-select all: vertices per path");
  t.number("psf-min-roughness", [](S& s) -> float& { return s.selection.min_roughness; }, 0.0, 1.0,
           "Vertices smoother than this are not selected");
  t.flag("psf-no-layers", [](S& s) -> bool& { return s.selection.split_layers; }, false,
         "One average per vertex instead of one per material layer", "2021 paper, sec. 3.1.2");
  t.number("psf-camera-splits", [](S& s) -> int& { return s.selection.camera_splits; }, 0, kMaxCameraSplits,
           "With --filter: before the first selected vertex, follow both reflection and refraction at smooth glass, "
           "and both scattering and passing in a scattering medium, up to N times per path, each branch filtered "
           "(no speckle in and through glass or fog)",
           "docs/hashed-filter.md, camera-side branches");
  t.flag("psf-no-medium-splits", [](S& s) -> bool& { return s.selection.medium_splits; }, false,
         "Camera-side splits at glass only, not in media (thin fog around small lights)", "docs/media.md, path space filtering in media");
  t.check([](const S& s) {
    if (!s.nee && !s.bsdf_sampling) throw OptionError("--no-nee and --no-bsdf-sampling together would render black");
    const int records = records_per_path(s.selection);
    if (records > kMaxPathRecords)
      throw OptionError(fmt::format("--psf-camera-splits {} with this vertex selection needs {} records per path, more than the {} "
                                    "a path holds: lower --psf-camera-splits or --psf-max-vertices, or add --psf-no-layers",
                                    s.selection.camera_splits, records, kMaxPathRecords));
  });
  return t;
}

const IntegratorRegistrar kRegistrar{with_media(make_integrator_entry<PtSettings>(
    "pt", "path tracing with next event estimation and MIS; filters the selected vertices with --filter",
    "Veach 1997 (MIS); path split for filtering: Binder, Fricke, Keller 2021, sec. 3", pt_options(),
    {IntegratorEntry::kAllFilters},
    [](const IntegratorContext& ctx, const PtSettings& s) -> std::unique_ptr<Integrator> {
      return std::make_unique<PtIntegrator>(ctx.scene, ctx.accel, s, ctx.seed, ctx.filter, ctx.carried_filter);
    }))};

}  // namespace

}  // namespace pathspace
