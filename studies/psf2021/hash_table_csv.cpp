// Writes the data of figs. 7 and 8 of Binder, Fricke, Keller 2019 (the short hashed path space
// filtering paper) as CSV: psf_fig7.csv (hash collisions and occupancy vs table size) and
// psf_fig8.csv (filter time vs voxel size) on the 1920x1080 cornell-box vertex sets, into the folder
// given as argument (default docs/figures); scripts/plot-psf-figures plots them. A thin wrapper: the
// measurements are studies/psf2021/hash_table_figures.h, which `pathspace study psf` also runs for its page.
#include <cstdio>
#include <filesystem>
#include <string>

#include "studies/psf2021/hash_table_figures.h"

using namespace pathspace;

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "docs/figures";
  std::filesystem::create_directories(out);
  study::HashTableSweep sweep;
  sweep.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  study::Table t7 = study::hash_collision_table(), t8 = study::filter_time_table();
  for (const auto kind : {study::VertexSetKind::primary, study::VertexSetKind::second_bounce}) {
    const auto set = study::make_vertex_set(kind, 1920, 1080);
    study::measure_hash_collisions(*set, study::vertex_set_name(kind), sweep, &t7);
    study::measure_filter_time(*set, study::vertex_set_name(kind), sweep, &t8);
  }
  study::write_csv(out + "/psf_fig7.csv", t7);
  study::write_csv(out + "/psf_fig8.csv", t8);
  std::printf("wrote %s/psf_fig7.csv and %s/psf_fig8.csv\n", out.c_str(), out.c_str());
  return 0;
}
