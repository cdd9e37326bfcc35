// Path tracing without a filter sums each path as it goes (VertexSelectionMode::none) instead of
// splitting it at its first diffuse vertex and recombining prefix + throughput x contribution. Both
// are the same estimator: the same rays, and values equal up to the rounding of the split's
// demodulation (throughput x albedo times contribution / albedo).
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

TEST(PtUnsplitPaths, SameRaysAndValuesAsTheSplitPath) {
  for (const char* name : {"cornell-box", "cornell-glossy", "cornell-glossy-point", "cornell-glossy-sun", "filter-fence"}) {
    const Scene scene = make_builtin_scene(name, 32, 32);
    const Accel accel(scene);
    const SceneView view = scene.view();
    PtSettings split;  // the hashed filter's default: split at the first diffuse vertex
    split.selection.camera_splits = 0;  // one path, not its branches (camera_branches_test.cpp)
    PtSettings plain;
    plain.selection.mode = VertexSelectionMode::none;
    double largest = 0.0;
    for (uint32_t pass = 0; pass < 4; ++pass)
      for (uint32_t pixel = 0; pixel < 32 * 32; ++pixel) {
        const Sampler sampler(3, pixel, pass);
        const Ray ray = sample_camera_ray(view.camera, sampler, pixel, 0.f);
        PathCounters a, b;
        PathSample whole;
        pt_trace_path(view, accel, sampler, ray, plain, &a, &whole);
        EXPECT_EQ(whole.count, 0) << name;  // nothing split off
        const Rgb unsplit = whole.value();
        const Rgb recombined = pt_trace_path(view, accel, sampler, ray, split, &b);
        ASSERT_EQ(a.rays, b.rays) << name << " pixel " << pixel;
        ASSERT_EQ(a.shadow_rays, b.shadow_rays) << name << " pixel " << pixel;
        for (int c = 0; c < 3; ++c) {
          const double d = std::fabs(double(unsplit[c]) - double(recombined[c]));
          const double scale = std::fmax(1e-6, std::fabs(double(recombined[c])));
          largest = std::fmax(largest, d / scale);
        }
      }
    // Float rounding of a few multiplications and one division per channel.
    EXPECT_LT(largest, 1e-5) << name;
  }
}

}  // namespace
}  // namespace pathspace
