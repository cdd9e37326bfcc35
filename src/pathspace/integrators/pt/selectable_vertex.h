// Which path vertices a path space filter may take (filters/vertex_selection.h): a material without
// a delta lobe whose every layer is at least min_roughness rough. The caustic photons use the same
// test (caustic_photons.h): a photon passes every vertex that is not selectable and is stored at the
// first that is, and the path tracer leaves out exactly the paths that photons carry.
#pragma once

#include "pathspace/filters/vertex_selection.h"
#include "pathspace/materials/bsdf_layers.h"

namespace pathspace {

// Merges all layers into one when layers are not filtered separately.
PS_INLINE void merge_layers(BsdfLayers* l) {
  if (l->count < 2) return;
  l->albedo[0] += l->albedo[1];
  l->roughness[0] = fminf(l->roughness[0], l->roughness[1]);
  l->id[0] = kLayerGlossy;
  l->count = 1;
}

PS_INLINE bool is_selectable(const BsdfLayers& l, const VertexSelection& s) {
  if (l.count == 0) return false;
  for (int i = 0; i < l.count; ++i)
    if (l.roughness[i] < s.min_roughness) return false;
  return true;
}

PS_INLINE bool is_selectable_material(const Material& m, const VertexSelection& s) {
  BsdfLayers l = bsdf_layers(m);
  if (!s.split_layers) merge_layers(&l);
  return is_selectable(l, s);
}

}  // namespace pathspace
