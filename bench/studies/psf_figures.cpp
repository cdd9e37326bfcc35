// Reproduces figs. 7 and 8 of Binder, Fricke, Keller 2019 (the short hashed path space filtering
// paper) on our own vertices (bench/support/vertex_sets.h: cornell-box, 1920x1080, primary and
// second-bounce hits):
//   fig. 7: hash collisions (extra probes per insertion) and occupancy vs hash table size, for
//           several voxel sizes; local combining off, so every vertex probes the table;
//   fig. 8: filter time (accumulate + lookup, median of 5 passes, 2 threads) vs voxel size.
// Writes psf_fig7.csv and psf_fig8.csv into the folder given as argument (default docs/figures) with
// the experiment harness's table writer (src/pathspace/study/table.h); scripts/plot-psf-figures turns
// them into PNG plots.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "pathspace/filters/hashed_filter.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/study/table.h"
#include "support/vertex_sets.h"

using namespace pathspace;
using study::Record;
using study::Table;

namespace {

constexpr int kWidth = 1920, kHeight = 1080;
constexpr size_t kPixels = size_t(kWidth) * kHeight;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Table fig7_table() {
  Table t;
  t.column("vertex_set").column("psf_scale").column("cells_per_pixel").column("cells").column("occupancy", "{:.6f}");
  t.column("mean_probes", "{:.6f}").column("extra_probes", "{:.6f}").column("max_probes").column("fallbacks");
  t.column("expected_fingerprint_collisions", "{:.3e}");
  return t;
}

void fig7(const bench::VertexSet& set, const char* name, Table* table) {
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
      Record r;
      r.set("vertex_set", name).set("psf_scale", scale).set("cells_per_pixel", cells_per_pixel).set("cells", st.cells);
      r.set("occupancy", double(st.occupied_cells_last) / double(st.cells)).set("mean_probes", st.mean_probes());
      r.set("extra_probes", st.mean_probes() - 1.0).set("max_probes", st.probes_max).set("fallbacks", st.probe_failures);
      r.set("expected_fingerprint_collisions", st.expected_fingerprint_collisions_last);
      table->rows.push_back(std::move(r));
      std::fprintf(stderr, "fig7 %s scale %g table %g: extra probes %.4f\n", name, scale, cells_per_pixel, st.mean_probes() - 1.0);
    }
  }
}

Table fig8_table() {
  Table t;
  t.column("vertex_set").column("threads").column("psf_scale").column("local_combining").column("accumulate_ms", "{:.3f}");
  t.column("lookup_ms", "{:.3f}").column("total_ms", "{:.3f}").column("occupancy", "{:.6f}").column("vertices");
  return t;
}

void fig8(const bench::VertexSet& set, const char* name, int threads, Table* table) {
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
      Record r;
      r.set("vertex_set", name).set("threads", threads).set("psf_scale", scale).set("local_combining", combining ? 1 : 0);
      r.set("accumulate_ms", median(accumulate)).set("lookup_ms", median(lookup)).set("total_ms", median(total));
      r.set("occupancy", double(st.occupied_cells_last) / double(st.cells)).set("vertices", st.vertices);
      table->rows.push_back(std::move(r));
      std::fprintf(stderr, "fig8 %s scale %g combining %d: %.2f ms\n", name, scale, combining ? 1 : 0, median(total));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "docs/figures";
  std::filesystem::create_directories(out);
  Table t7 = fig7_table(), t8 = fig8_table();
  for (const auto kind : {bench::VertexSetKind::primary, bench::VertexSetKind::second_bounce}) {
    const auto set = bench::make_vertex_set(kind, kWidth, kHeight);
    fig7(*set, bench::vertex_set_name(kind), &t7);
    fig8(*set, bench::vertex_set_name(kind), 2, &t8);
  }
  study::write_csv(out + "/psf_fig7.csv", t7);
  study::write_csv(out + "/psf_fig8.csv", t8);
  std::printf("wrote %s/psf_fig7.csv and %s/psf_fig8.csv\n", out.c_str(), out.c_str());
  return 0;
}
