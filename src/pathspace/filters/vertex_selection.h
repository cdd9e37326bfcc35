// Which vertices of a camera path are handed to a path space filter (Binder et al. 2021, sec. 4 and
// fig. 10): the first sufficiently diffuse vertex, the n-th one (final-gather style), or several.
// A vertex is "sufficiently diffuse" when its material is filterable (materials/bsdf_layers.h) and
// every layer is at least min_roughness rough; delta surfaces are never selected.
#pragma once

#include <cstdint>

namespace pathspace {

inline constexpr int kMaxSelectedVertices = 4;
// At most this many camera-side splits (at smooth glass, in media) per path (VertexSelection::camera_splits).
inline constexpr int kMaxCameraSplits = 3;

// none: no filter, so no vertex is split off and the path's value is summed as it goes (plain path
// tracing; not an option: integrators set it when no filter is active).
enum class VertexSelectionMode : uint8_t { first, nth, all, none };

struct VertexSelection {
  VertexSelectionMode mode = VertexSelectionMode::first;
  int n = 1;                   // nth: the n-th sufficiently diffuse vertex (1-based)
  int max_vertices = 2;        // all: at most this many per path (<= kMaxSelectedVertices)
  float min_roughness = 0.1f;  // Phong exponent 90 ~ 0.15, Lambert = 1
  bool split_layers = true;    // one average per material layer (sec. 3.1.2); false: one merged layer
  // Before its first selectable vertex a path follows both the reflected and the refracted branch
  // at smooth glass, and both the scattering and the passing one in a scattering medium
  // (media/free_flight.h), up to this many times (pt_kernel.h, pt_continue_path): each branch ends
  // in a selected vertex of its own, so what is seen in and through glass or fog is filtered, not a
  // random pick between the two per pixel. A path then holds up to 2^camera_splits branches'
  // records. Two splits: into glass and out again (one split leaves the internal reflections' dark
  // speckle).
  int camera_splits = 2;
  // Whether those splits also take place in media. In dense fog they remove most of the noise of
  // where a camera ray scatters; in thin fog around a small light they place more vertices in its
  // glow, whose fireflies the filter spreads (docs/results/media-filtering.md).
  bool medium_splits = true;
};

}  // namespace pathspace
