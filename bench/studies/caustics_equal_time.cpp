// Equal-time caustics (docs/benchmarks.md "Equal-time caustics"): on cornell-box (bs_c) at 128x128, a
// long BPT reference, then PT, LT, BPT, SPPM and PCLT for the same wall time each (several seeds), with the
// relMSE against the reference over the whole image and over the caustic under the glass sphere,
// where PT must hit the small light through the glass by BSDF sampling and the others trace from it.
// Usage: caustics_equal_time [OUT.csv] [REFERENCE_SECONDS] [EQUAL_SECONDS] [SEEDS] [IMAGE_DIR]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/integrators/render.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"

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

struct Run {
  Image mean, variance;
  RenderStats stats;
};

Run render_for(const Scene& scene, const Accel& accel, const std::string& integrator, double seconds, uint64_t seed) {
  Film film(kSize, kSize);
  RenderRequest req;
  req.integrator = integrator;
  req.time_limit_s = seconds;
  req.settings.seed = seed;
  Run r;
  r.stats = render(scene, accel, req, film);
  r.mean = film.mean();
  r.variance = film.variance_of_mean();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "docs/figures/caustics_equal_time.csv";
  const double reference_s = argc > 2 ? std::atof(argv[2]) : 120.0;
  const double equal_s = argc > 3 ? std::atof(argv[3]) : 10.0;
  const int seeds = argc > 4 ? std::atoi(argv[4]) : 2;
  const std::string image_dir = argc > 5 ? argv[5] : "";
  const Scene scene = make_builtin_scene("bs_c", kSize, kSize);
  const Accel accel(scene);
  const std::vector<bool> region = caustic_region(scene, accel);
  size_t region_pixels = 0;
  for (bool b : region) region_pixels += b;

  const Run ref = render_for(scene, accel, "bpt", reference_s, 1000);
  std::fprintf(stderr, "reference: bpt %u passes in %.1f s; caustic region %zu pixels, mean %.4f\n", ref.stats.spp,
               ref.stats.wall_s, region_pixels, mean_of(restrict_to(ref.mean, region)));
  if (!image_dir.empty()) write_image(image_dir + "/caustics-reference.exr", ref.mean);
  const Image ref_region = restrict_to(ref.mean, region), ref_region_var = restrict_to(ref.variance, region);

  std::string csv = fmt::format("# bs_c {}x{}, reference bpt {} passes / {:.1f} s, caustic region [{},{})x[{},{}) {} floor pixels\n",
                                kSize, kSize, ref.stats.spp, ref.stats.wall_s, kX0, kX1, kY0, kY1, region_pixels);
  csv += "integrator,seed,seconds,passes,rel_mse,rel_mse_caustic,caustic_mean,reference_caustic_mean\n";
  for (const char* integrator : {"pt", "lt", "bpt", "sppm", "pclt"})
    for (int seed = 1; seed <= seeds; ++seed) {
      const Run r = render_for(scene, accel, integrator, equal_s, uint64_t(seed));
      const ImageError all = image_error(r.mean, ref.mean, &ref.variance);
      const Image reg = restrict_to(r.mean, region);
      const ImageError caustic = image_error(reg, ref_region, &ref_region_var);
      csv += fmt::format("{},{},{:.2f},{},{:.5g},{:.5g},{:.5g},{:.5g}\n", integrator, seed, r.stats.wall_s, r.stats.spp,
                         all.rel_mse, caustic.rel_mse, mean_of(reg), mean_of(ref_region));
      std::fprintf(stderr, "%s seed %d: %u passes, relMSE %.4g, caustic relMSE %.4g, caustic mean %.4f\n", integrator, seed,
                   r.stats.spp, all.rel_mse, caustic.rel_mse, mean_of(reg));
      if (!image_dir.empty() && seed == 1) write_image(image_dir + "/caustics-" + integrator + ".exr", r.mean);
    }
  write_text_file(out, csv);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
