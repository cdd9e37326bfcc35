#include "studies/psf2021/hash_table_figures.h"

#include <algorithm>

#include <fmt/format.h>

#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace::study {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

size_t pixels_of(const VertexSet& set) { return size_t(set.scene->camera.width) * size_t(set.scene->camera.height); }

}  // namespace

Table hash_collision_table() {
  Table t;
  t.column("vertex_set").column("psf_scale").column("cells_per_pixel").column("cells").column("occupancy", "{:.6f}");
  t.column("mean_probes", "{:.6f}").column("extra_probes", "{:.6f}").column("max_probes").column("fallbacks");
  t.column("expected_fingerprint_collisions", "{:.3e}");
  return t;
}

Table filter_time_table() {
  Table t;
  t.column("vertex_set").column("threads").column("psf_scale").column("local_combining").column("accumulate_ms", "{:.3f}");
  t.column("lookup_ms", "{:.3f}").column("total_ms", "{:.3f}").column("occupancy", "{:.6f}").column("vertices");
  return t;
}

void measure_hash_collisions(const VertexSet& set, const char* name, const HashTableSweep& sweep, Table* table) {
  for (const float scale : sweep.fig7_scales) {
    for (const float cells_per_pixel : sweep.fig7_cells_per_pixel) {
      HashedFilterSettings s;
      s.key.psf_scale = scale;
      s.table_factor = cells_per_pixel;
      s.local_combining = false;  // every vertex probes the table
      HashedFilter filter(s, set.scene->camera, pixels_of(set));
      SlotValues filtered;
      filter.filter(set.buffer, 0, 0, &filtered);
      const HashedFilterStats& st = filter.stats();
      Record r;
      r.set("vertex_set", name).set("psf_scale", scale).set("cells_per_pixel", cells_per_pixel).set("cells", st.cells);
      r.set("occupancy", double(st.occupied_cells_last) / double(st.cells)).set("mean_probes", st.mean_probes());
      r.set("extra_probes", st.mean_probes() - 1.0).set("max_probes", st.probes_max).set("fallbacks", st.probe_failures);
      r.set("expected_fingerprint_collisions", st.expected_fingerprint_collisions_last);
      table->rows.push_back(std::move(r));
      if (sweep.progress)
        sweep.progress(fmt::format("fig7 {} scale {:g} table {:g}: extra probes {:.4f}", name, scale, cells_per_pixel, st.mean_probes() - 1.0));
    }
  }
}

void measure_filter_time(const VertexSet& set, const char* name, const HashTableSweep& sweep, Table* table) {
  ThreadLimit limit(sweep.fig8_threads);
  for (const float scale : sweep.fig8_scales) {
    for (const bool combining : {true, false}) {
      HashedFilterSettings s;
      s.key.psf_scale = scale;
      s.local_combining = combining;
      HashedFilter filter(s, set.scene->camera, pixels_of(set));
      SlotValues filtered;
      filter.filter(set.buffer, 0, 0, &filtered);  // warm-up
      std::vector<double> accumulate, lookup, total;
      for (int pass = 1; pass <= std::max(1, sweep.fig8_passes); ++pass) {
        filter.reset_stats();
        filter.filter(set.buffer, 0, uint32_t(pass), &filtered);
        const HashedFilterStats& st = filter.stats();
        accumulate.push_back(st.accumulate_ms);
        lookup.push_back(st.lookup_ms);
        total.push_back(st.clear_ms + st.accumulate_ms + st.lookup_ms);
      }
      const HashedFilterStats& st = filter.stats();
      Record r;
      r.set("vertex_set", name).set("threads", sweep.fig8_threads).set("psf_scale", scale).set("local_combining", combining ? 1 : 0);
      r.set("accumulate_ms", median(accumulate)).set("lookup_ms", median(lookup)).set("total_ms", median(total));
      r.set("occupancy", double(st.occupied_cells_last) / double(st.cells)).set("vertices", st.vertices);
      table->rows.push_back(std::move(r));
      if (sweep.progress)
        sweep.progress(fmt::format("fig8 {} scale {:g} combining {}: {:.2f} ms", name, scale, combining ? 1 : 0, median(total)));
    }
  }
}

}  // namespace pathspace::study
