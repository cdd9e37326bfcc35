// Reproduces figs. 7 and 8 of Binder, Fricke, Keller 2019 (the short hashed path space filtering
// paper) on our own vertices (bench/support/vertex_sets.h: cornell-box, 1920x1080, primary and
// second-bounce hits):
//   fig. 7: hash collisions (extra probes per insertion) and occupancy vs hash table size, for
//           several voxel sizes; local combining off, so every vertex probes the table;
//   fig. 8: filter time (accumulate + lookup, median of 5 passes, 2 threads) vs voxel size.
// Writes psf_fig7.csv and psf_fig8.csv into the folder given as argument (default docs/figures);
// scripts/plot-psf-figures turns them into PNG plots.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/filters/hashed_filter.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/parallel/parallel_for.h"
#include "support/vertex_sets.h"

using namespace pathspace;

namespace {

constexpr int kWidth = 1920, kHeight = 1080;
constexpr size_t kPixels = size_t(kWidth) * kHeight;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string fig7(const bench::VertexSet& set, const char* name) {
  std::string csv;
  for (const float scale : {1.f, 2.f, 4.f, 8.f}) {
    for (const float cells_per_pixel : {0.0625f, 0.125f, 0.25f, 0.5f, 1.f, 2.f, 4.f, 8.f}) {
      HashedFilterSettings s;
      s.key.psf_scale = scale;
      s.table_factor = cells_per_pixel;
      s.local_combining = false;
      HashedFilter filter(s, set.scene->camera, kPixels);
      std::vector<Rgb> filtered;
      filter.filter(set.buffer, 0, 0, &filtered);
      const HashedFilterStats& st = filter.stats();
      csv += fmt::format("{},{},{},{},{:.6f},{:.6f},{:.6f},{},{},{:.3e}\n", name, scale, cells_per_pixel, st.cells,
                         double(st.occupied_cells_last) / double(st.cells), st.mean_probes(), st.mean_probes() - 1.0,
                         st.probes_max, st.probe_failures, st.expected_fingerprint_collisions_last);
      std::fprintf(stderr, "fig7 %s scale %g table %g: extra probes %.4f\n", name, scale, cells_per_pixel, st.mean_probes() - 1.0);
    }
  }
  return csv;
}

std::string fig8(const bench::VertexSet& set, const char* name, int threads) {
  std::string csv;
  ThreadLimit limit(threads);
  for (const float scale : {0.5f, 1.f, 2.f, 4.f, 8.f, 16.f, 32.f}) {
    for (const bool combining : {true, false}) {
      HashedFilterSettings s;
      s.key.psf_scale = scale;
      s.local_combining = combining;
      HashedFilter filter(s, set.scene->camera, kPixels);
      std::vector<Rgb> filtered;
      filter.filter(set.buffer, 0, 0, &filtered);  // warm-up
      std::vector<double> accumulate, lookup, total;
      for (uint32_t pass = 1; pass <= 5; ++pass) {
        filter.reset_stats();
        filter.filter(set.buffer, 0, pass, &filtered);
        const HashedFilterStats& st = filter.stats();
        accumulate.push_back(st.accumulate_ms);
        lookup.push_back(st.lookup_ms);
        total.push_back(st.clear_ms + st.accumulate_ms + st.lookup_ms);
      }
      const HashedFilterStats& st = filter.stats();
      csv += fmt::format("{},{},{},{},{:.3f},{:.3f},{:.3f},{:.6f},{}\n", name, threads, scale, combining ? 1 : 0,
                         median(accumulate), median(lookup), median(total),
                         double(st.occupied_cells_last) / double(st.cells), st.vertices);
      std::fprintf(stderr, "fig8 %s scale %g combining %d: %.2f ms\n", name, scale, combining ? 1 : 0, median(total));
    }
  }
  return csv;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "docs/figures";
  std::filesystem::create_directories(out);
  std::string csv7 = "vertex_set,psf_scale,cells_per_pixel,cells,occupancy,mean_probes,extra_probes,max_probes,fallbacks,expected_fingerprint_collisions\n";
  std::string csv8 = "vertex_set,threads,psf_scale,local_combining,accumulate_ms,lookup_ms,total_ms,occupancy,vertices\n";
  for (const auto kind : {bench::VertexSetKind::primary, bench::VertexSetKind::second_bounce}) {
    const auto set = bench::make_vertex_set(kind, kWidth, kHeight);
    csv7 += fig7(*set, bench::vertex_set_name(kind));
    csv8 += fig8(*set, bench::vertex_set_name(kind), 2);
  }
  write_text_file(out + "/psf_fig7.csv", csv7);
  write_text_file(out + "/psf_fig8.csv", csv8);
  std::printf("wrote %s/psf_fig7.csv and %s/psf_fig8.csv\n", out.c_str(), out.c_str());
  return 0;
}
