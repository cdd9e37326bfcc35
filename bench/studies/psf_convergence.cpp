// Error vs samples per pixel with and without hashed path space filtering (Binder et al. 2021,
// sec. 4 / fig. 1: 1 path per pixel filtered vs a 1024 spp reference). Renders cornell-box at
// 512x512 progressively (each pass filtered, then accumulated) and records the relMSE and MSE
// against a reference image after 1, 2, 4, ..., 64 spp, for several seeds. The filtered error at
// high spp is the bias the filter leaves (it no longer falls with 1/spp).
// Usage: psf_convergence REFERENCE.exr [REFERENCE_VARIANCE.exr] [OUT.csv]
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/integrators/render.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"

using namespace pathspace;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: psf_convergence REFERENCE.exr [REFERENCE_VARIANCE.exr] [OUT.csv]\n");
    return 2;
  }
  const Image reference = read_image(argv[1]);
  Image variance;
  const bool has_variance = argc > 2 && std::string(argv[2]) != "-";
  if (has_variance) variance = read_image(argv[2]);
  const std::string out = argc > 3 ? argv[3] : "docs/figures/psf_convergence.csv";
  const Scene scene = make_builtin_scene("cornell-box", reference.width, reference.height);
  const Accel accel(scene);

  std::string csv = "filter,psf_scale,seed,spp,rel_mse,mse,seconds\n";
  struct Config {
    const char* name;
    FilterKind kind;
    float scale;
  };
  const Config configs[] = {{"none", FilterKind::none, 0.f}, {"hashed", FilterKind::hashed, 6.f},
                            {"hashed", FilterKind::hashed, 12.f}, {"hashed", FilterKind::hashed, 20.f}};
  for (const Config& c : configs) {
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      Film film(reference.width, reference.height);
      RenderRequest req;
      req.settings.seed = seed;
      req.settings.filter.kind = c.kind;
      if (c.scale > 0.f) req.settings.filter.hashed.key.psf_scale = c.scale;
      double seconds = 0;
      uint32_t done = 0;
      for (uint32_t spp = 1; spp <= 64; spp *= 2) {
        // Passes continue the same sequence: pass indices done..spp-1 (render() starts at pass 0,
        // so each chunk uses a distinct seed offset to stay independent).
        req.spp = spp - done;
        req.settings.seed = seed * 1000 + done;
        seconds += render(scene, accel, req, film).wall_s;
        done = spp;
        const ImageError e = image_error(film.mean(), reference, has_variance ? &variance : nullptr);
        csv += fmt::format("{},{},{},{},{:.6g},{:.6g},{:.3f}\n", c.name, c.scale, seed, spp, e.rel_mse, e.mse, seconds);
        std::fprintf(stderr, "%s scale %g seed %d spp %u: relMSE %.4g\n", c.name, double(c.scale), int(seed), spp, e.rel_mse);
      }
    }
  }
  write_text_file(out, csv);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
