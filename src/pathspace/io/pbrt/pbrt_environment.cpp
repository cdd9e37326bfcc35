#include "pathspace/io/pbrt/pbrt_environment.h"

#include "pathspace/io/environment_file.h"

namespace pathspace::pbrt {

EnvironmentImage read_pbrt_environment(const std::string& path, const Mat4& light_to_world, const FileLoc& loc,
                                       LoadWarnings* warnings) {
  const Vec3 ex = light_to_world.vector(Vec3(1, 0, 0)), ey = light_to_world.vector(Vec3(0, 1, 0)),
             ez = light_to_world.vector(Vec3(0, 0, 1));
  EnvironmentImage e = read_environment_image(path, EnvironmentMapping::equal_area, ex, ey, ez);
  if (e.width != e.height) {
    warnings->add(loc, "environment map '" + path + "' is not square (" + std::to_string(e.width) + "x" +
                           std::to_string(e.height) + "): read as a pbrt-v3 lat-long map (pbrt-v4 needs equal-area square maps)");
    // The lat-long mapping's local frame is y up (Mitsuba's); pbrt-v3's z-up direction
    // (sin t cos p, sin t sin p, cos t) is (-m.z, m.x, m.y) of the Mitsuba-frame direction m.
    e.mapping = EnvironmentMapping::lat_long;
    e.axis_x = ey;
    e.axis_y = ez;
    e.axis_z = -ex;
  }
  return e;
}

}  // namespace pathspace::pbrt
