#include "pathspace/io/environment_file.h"

#include <cmath>
#include <utility>

#include "pathspace/io/image_io.h"

namespace pathspace {

EnvironmentImage read_environment_image(const std::string& path, EnvironmentMapping mapping, const Vec3& axis_x,
                                        const Vec3& axis_y, const Vec3& axis_z) {
  Image image = read_image(path);
  EnvironmentImage e;
  e.name = path;
  e.width = image.width;
  e.height = image.height;
  e.texels = std::move(image.pixels);
  e.mapping = mapping;
  e.axis_x = axis_x;
  e.axis_y = axis_y;
  e.axis_z = axis_z;
  return e;
}

double pbrt_map_illuminance(const EnvironmentImage& image) {
  double sum = 0.0, solid_angle = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Point2 uv{(float(x) + 0.5f) / float(image.width), (float(y) + 0.5f) / float(image.height)};
      const Vec3 d = envmap_uv_to_direction(image.mapping, uv);
      // The local "up" of the map: z for equal-area; for lat-long (pbrt's z-up frame is the map's
      // y) the texel's solid angle is proportional to sin(theta).
      const double up = image.mapping == EnvironmentMapping::equal_area ? d.z : d.y;
      const double dw = image.mapping == EnvironmentMapping::equal_area ? 1.0 : std::sin(M_PI * (y + 0.5) / image.height);
      solid_angle += dw;
      if (up <= 0.0) continue;
      sum += double(luminance(image.texels[size_t(y) * size_t(image.width) + size_t(x)])) * up * dw;
    }
  // Equal-area: sum * 2 pi / N. Lat-long: its texels' solid angles normalised to the same total.
  return solid_angle > 0.0 ? sum * 2.0 * M_PI / solid_angle : 0.0;
}

}  // namespace pathspace
