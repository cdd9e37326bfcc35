// Filter input taken from real renders (the hashed filter's figures in `pathspace study psf`, the
// filter benchmark and bench/studies/psf_figures): the selected vertices of one pass of
// cornell-box, either the first diffuse vertex of each camera path (primary hits, coherent) or the
// second one (incoherent second-bounce hits, Binder et al. 2021 fig. 10's selection).
#pragma once

#include <memory>

#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/scene/scene.h"

namespace pathspace::study {

enum class VertexSetKind { primary = 0, second_bounce = 1 };

struct VertexSet {
  std::unique_ptr<Scene> scene;
  VertexBuffer buffer;
};

// One 1-spp pass of cornell-box at width x height, every path's selected vertex kept (one record per path).
std::unique_ptr<VertexSet> make_vertex_set(VertexSetKind kind, int width = 1920, int height = 1080);

const char* vertex_set_name(VertexSetKind kind);

}  // namespace pathspace::study
