// Writes the vertex buffer files the GPU filter benchmark reads (bench/cuda/cuda_filter_bench.cu,
// docs/benchmarks.md): built-in cornell-box at 1920x1080, one pass of path tracing, its primary hits
// (--psf-select first) and its second-bounce vertices (--psf-select nth --psf-nth 2), each with the
// CPU hashed filter's output (default settings) for the bit-exact check.
//   write_vertex_buffers [output folder] [width height]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/vertex_buffer_file.h"
#include "studies/psf2021/vertex_sets.h"

int main(int argc, char** argv) {
  using namespace pathspace;
  try {
    const std::string folder = argc > 1 ? argv[1] : ".";
    const int width = argc > 3 ? std::atoi(argv[2]) : 1920, height = argc > 3 ? std::atoi(argv[3]) : 1080;
    if (width < 1 || height < 1) throw Error("usage: write_vertex_buffers [folder] [width height]");
    for (const study::VertexSetKind kind : {study::VertexSetKind::primary, study::VertexSetKind::second_bounce}) {
      const auto set = study::make_vertex_set(kind, width, height);
      VertexBufferFile f;
      f.pixels = uint64_t(width) * uint64_t(height);
      f.seed = 0;
      f.pass = 0;
      HashedFilter filter(f.settings, set->scene->camera, size_t(f.pixels));
      filter.filter(set->buffer, f.seed, f.pass, &f.filtered);
      f.settings.key.pixel_angle = 2.f * set->scene->camera.tan_y / float(set->scene->camera.height);
      f.buffer = set->buffer;
      const std::string path = folder + "/" + study::vertex_set_name(kind) + ".psvb";
      write_vertex_buffer_file(path, f);
      std::printf("%s: %zu paths, %zu vertices, %llu probe-limit fallbacks\n", path.c_str(), f.buffer.paths(),
                  f.buffer.total_records(), (unsigned long long)filter.stats().probe_failures);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_vertex_buffers: %s\n", e.what());
    return 1;
  }
  return 0;
}
