// The buffers of a filtered pass travel with the filter from frame to frame (filters/filter_workspace.h):
// a frame's new integrator that takes the previous frame's filter over records into the same memory
// instead of allocating the pass's vertex records again, and its image does not depend on that.
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/pt/pt_integrator.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

Image render_pass(PtIntegrator& pt, int width, int height) {
  Film film(width, height);
  PathCounters counters;
  pt.render_pass(0, film, counters);
  return film.mean();
}

TEST(FilterWorkspace, TheNextFramesIntegratorRecordsIntoTheCarriedBuffers) {
  const int w = 48, h = 32;
  const Scene scene = make_builtin_scene("cornell-box", w, h);
  const Accel accel(scene);
  const FilterChoice passthrough{"passthrough", {}};
  PtIntegrator first(scene, accel, PtSettings{}, 7, passthrough);
  const Image a = render_pass(first, w, h);
  const Vec3* positions = first.vertex_buffer().position.data();
  ASSERT_NE(positions, nullptr);

  PtIntegrator next(scene, accel, PtSettings{}, 7, passthrough, first.carried_filter());
  const Image b = render_pass(next, w, h);
  EXPECT_EQ(next.vertex_buffer().position.data(), positions);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)), 0);

  PtIntegrator fresh(scene, accel, PtSettings{}, 7, passthrough);  // no filter carried: its own buffers
  render_pass(fresh, w, h);
  EXPECT_NE(fresh.vertex_buffer().position.data(), positions);
}

}  // namespace
}  // namespace pathspace
