// Equal-time caustics (docs/results/integrators.md "Equal-time caustics"): on cornell-box (bs_c) at 128x128, a
// long BPT reference, then PT, LT, BPT, SPPM and PCLT for the same wall time each (several seeds), with the
// relMSE against the reference over the whole image and over the caustic under the glass sphere,
// where PT must hit the small light through the glass by BSDF sampling and the others trace from it.
// An experiment on the harness (src/pathspace/study/); the caustic region is a custom image metric.
// Usage: caustics_equal_time [OUT.csv] [REFERENCE_SECONDS] [EQUAL_SECONDS] [SEEDS] [IMAGE_DIR]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/scene.h"
#include "pathspace/study/experiment_output.h"
#include "pathspace/study/experiment_runner.h"

using namespace pathspace;

namespace {

constexpr int kSize = 128;
// The caustic region, picked on the 128x128 reference (docs/benchmarks.md): the bright focused spot
// on the floor below and in front of the glass sphere (the right sphere), pixel rectangle
// [x0, x1) x [y0, y1), y down. Only pixels whose camera ray hits the floor at all 3x3 sub-pixel
// positions count, so the sphere's own silhouette never enters the region.
constexpr int kX0 = 78, kX1 = 100, kY0 = 104, kY1 = 118;

std::vector<bool> caustic_region(const Scene& scene, const Accel& accel) {
  const SceneView view = scene.view();
  std::vector<bool> in(size_t(kSize) * kSize, false);
  for (int y = kY0; y < kY1; ++y)
    for (int x = kX0; x < kX1; ++x) {
      bool floor = true;
      for (int k = 0; k < 9 && floor; ++k) {
        SurfaceHit hit;
        const Ray ray = view.camera.generate_ray(float(x) + 0.1f + 0.4f * float(k % 3), float(y) + 0.1f + 0.4f * float(k / 3));
        floor = accel.intersect(ray, &hit) && hit.ng.z > 0.999f && hit.p.z < -1.2f;  // the floor plane, z = -1.28
      }
      in[size_t(y) * kSize + size_t(x)] = floor;
    }
  return in;
}

Image restrict_to(const Image& img, const std::vector<bool>& keep) {
  Image out;
  out.height = 1;
  for (size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) out.pixels.push_back(img.pixels[i]);
  out.width = int(out.pixels.size());
  return out;
}

double mean_of(const Image& img) {
  double s = 0;
  for (const Rgb& p : img.pixels) s += average(p);
  return img.pixels.empty() ? 0.0 : s / double(img.pixels.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "docs/figures/caustics_equal_time.csv";
  const double reference_s = argc > 2 ? std::atof(argv[2]) : 120.0;
  const double equal_s = argc > 3 ? std::atof(argv[3]) : 10.0;
  const int seeds = argc > 4 ? std::atoi(argv[4]) : 2;
  const std::string image_dir = argc > 5 ? argv[5] : "";

  study::Experiment e;
  e.name = "caustics_equal_time";
  e.scenes = {{"bs_c", kSize, kSize}};
  e.reference.render = study::reference_render_config("bpt");
  e.reference.render.seed = 1000;
  e.reference.budget = study::Budget::for_seconds(reference_s);
  for (const char* integrator : {"pt", "lt", "bpt", "sppm", "pclt"}) {
    RenderConfig c;
    c.integrator = integrator;
    e.configurations.push_back(study::configuration(integrator, c));
  }
  e.seeds.clear();
  for (int seed = 1; seed <= seeds; ++seed) e.seeds.push_back(uint64_t(seed));
  e.budget = study::Budget::for_seconds(equal_s);
  study::check_experiment(e);

  study::RunnerOptions options;
  options.quiet = true;
  options.on_measurement = [&](const study::Measurement& m) {
    std::fprintf(stderr, "%s seed %d: %u passes, relMSE %.4g, caustic relMSE %.4g, caustic mean %.4f\n", m.integrator.c_str(),
                 int(m.seed), m.iterations, m.rel_mse_debiased, m.metrics.number("rel_mse_caustic"), m.metrics.number("caustic_mean"));
    if (!image_dir.empty() && m.seed == 1) write_image(image_dir + "/caustics-" + m.integrator + ".exr", m.image);
  };
  const study::ExperimentRunner runner(options);
  const study::PreparedScene scene = runner.prepare(e.scenes[0], e.reference);
  const std::vector<bool> region = caustic_region(*scene.scene, *scene.accel);
  size_t region_pixels = 0;
  for (bool b : region) region_pixels += b;
  const Image ref_region = restrict_to(scene.reference, region), ref_region_var = restrict_to(scene.reference_variance, region);
  const double ref_passes = scene.summary.reference.number("iterations"), ref_seconds = scene.summary.reference.number("time_s");
  std::fprintf(stderr, "reference: bpt %.0f passes in %.1f s; caustic region %zu pixels, mean %.4f\n", ref_passes, ref_seconds,
               region_pixels, mean_of(ref_region));
  if (!image_dir.empty()) write_image(image_dir + "/caustics-reference.exr", scene.reference);

  e.metrics.push_back([&](const study::MeasureContext& ctx, study::Record* metrics) {
    const Image reg = restrict_to(ctx.image, region);
    metrics->set("rel_mse_caustic", image_error(reg, ref_region, &ref_region_var).rel_mse);
    metrics->set("caustic_mean", mean_of(reg));
    metrics->set("reference_caustic_mean", mean_of(ref_region));
  });
  study::ExperimentResult result;
  result.name = e.name;
  result.scenes.push_back(scene.summary);
  result.measurements = runner.run_scene(scene, e);

  study::Table table = study::results_table(result);
  table.comments.push_back(fmt::format("bs_c {}x{}, reference bpt {:.0f} passes / {:.1f} s, caustic region [{},{})x[{},{}) {} floor pixels",
                                       kSize, kSize, ref_passes, ref_seconds, kX0, kX1, kY0, kY1, region_pixels));
  table.column("integrator").column("seed").column("seconds", "{:.2f}", "time_s").column("passes", "", "iterations");
  table.column("rel_mse", "{:.5g}", "rel_mse_debiased").column("rel_mse_caustic", "{:.5g}");
  table.column("caustic_mean", "{:.5g}").column("reference_caustic_mean", "{:.5g}");
  study::write_csv(out, table);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
