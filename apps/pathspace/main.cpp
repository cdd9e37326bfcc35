// PLACEHOLDER CLI (being implemented): renders the default scene to check the build.
#include <cstdio>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/render.h"
#include "pathspace/scene/builtin_scenes.h"

int main() {
  using namespace pathspace;
  Scene scene = make_builtin_scene(kDefaultSceneName, 128, 128);
  Accel accel(scene);
  Film film(128, 128);
  RenderRequest req;
  req.spp = 4;
  RenderStats st = render(scene, accel, req, film);
  Image img = film.mean();
  double sum = 0;
  for (auto& p : img.pixels) sum += p.r + p.g + p.b;
  std::printf("%.3f s, %.2f Mrays/s, mean %.5f\n", st.wall_s, st.mrays_per_s(), sum / (3.0 * img.size()));
  return 0;
}
