#include "pathspace/io/scene_pixel_filter.h"

#include "pathspace/camera/pixel_filter_table.h"

namespace pathspace {

PixelFilter scene_pixel_filter(PixelFilterKind kind, double radius, double sigma, double b, double c, const FileLoc& loc,
                               LoadWarnings* warnings) {
  PixelFilter f;
  try {
    f = make_pixel_filter(kind, float(radius), float(sigma), float(b), float(c));
  } catch (const Error& e) {
    throw Error(loc, e.what());
  }
  if (kind == PixelFilterKind::mitchell)
    warnings->add(loc, "the mitchell filter's negative lobes are dropped: pathspace's pixel filters are never negative "
                       "(camera paths sample them with weight 1)");
  return f;
}

}  // namespace pathspace
