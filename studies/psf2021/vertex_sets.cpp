#include "studies/psf2021/vertex_sets.h"

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/pt/pt_integrator.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::study {

std::unique_ptr<VertexSet> make_vertex_set(VertexSetKind kind, int width, int height) {
  auto set = std::make_unique<VertexSet>();
  set->scene = std::make_unique<Scene>(make_builtin_scene("cornell-box", width, height));
  const Accel accel(*set->scene);
  PtSettings s;
  s.selection.split_layers = false;  // one record per path
  if (kind == VertexSetKind::second_bounce) {
    s.selection.mode = VertexSelectionMode::nth;
    s.selection.n = 2;
  }
  // The passthrough filter: every path goes through the vertex buffer, filtered by nothing.
  PtIntegrator pt(*set->scene, accel, s, 0, FilterChoice{"passthrough", {}});
  Film film(width, height);
  PathCounters counters;
  pt.render_pass(0, film, counters);
  set->buffer = pt.vertex_buffer();
  return set;
}

const char* vertex_set_name(VertexSetKind kind) { return kind == VertexSetKind::primary ? "primary" : "second_bounce"; }

}  // namespace pathspace::study
