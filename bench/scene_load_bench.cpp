// Scene loading (docs/results/io-and-overheads.md "Scene loading"): read_ply throughput on a generated
// 1M-triangle binary little-endian PLY, plain and gzip-compressed ("MB/s" counts the uncompressed
// PLY bytes), and the time to first pixel: load_scene + Embree build + one 1-spp PT pass at 64x64,
// the steps `pathspace render FILE` runs (render_command.cpp), with each step's share as counters.
#include <benchmark/benchmark.h>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>

#include "pathspace/accel/accel.h"
#include "pathspace/io/ply_reader.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/session/render.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

constexpr int kGrid = 709;  // vertices per side: 2 * 708^2 = 1,002,528 triangles

template <typename T>
void put(std::string* s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));  // x86-64 is little-endian, the file's byte order
  s->append(b, sizeof(T));
}

// A wavy height field, so the Embree build sees a non-degenerate surface.
std::string grid_ply() {
  const uint64_t faces = 2ull * (kGrid - 1) * (kGrid - 1);
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(kGrid * kGrid) +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
                  "\nproperty list uchar int vertex_indices\nend_header\n";
  s.reserve(s.size() + size_t(kGrid) * kGrid * 12 + faces * 13);
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const float x = float(i) / (kGrid - 1), y = float(j) / (kGrid - 1);
      put(&s, x), put(&s, y), put(&s, 0.05f * std::sin(20.f * x) * std::cos(17.f * y));
    }
  for (int j = 0; j + 1 < kGrid; ++j)
    for (int i = 0; i + 1 < kGrid; ++i) {
      const int32_t a = j * kGrid + i, b = a + 1, c = a + kGrid, d = c + 1;
      put(&s, uint8_t(3)), put(&s, a), put(&s, b), put(&s, d);
      put(&s, uint8_t(3)), put(&s, a), put(&s, d), put(&s, c);
    }
  return s;
}

// Written once per process into a private temp folder.
struct MeshFiles {
  pathspace::testing::TempDir dir{"scene-load-bench"};
  std::string ply = dir.file("grid.ply"), gz = dir.file("grid.ply.gz");
  size_t bytes = 0;
  MeshFiles() {
    const std::string data = grid_ply();
    bytes = data.size();
    std::ofstream(ply, std::ios::binary).write(data.data(), std::streamsize(data.size()));
    gzFile f = gzopen(gz.c_str(), "wb6");
    gzwrite(f, data.data(), unsigned(data.size()));
    gzclose(f);
  }
};

const MeshFiles& files() {
  static const MeshFiles f;
  return f;
}

const std::string& path_of(const benchmark::State& state) { return state.range(0) ? files().gz : files().ply; }

void BM_ReadPly(benchmark::State& state) {
  const std::string& path = path_of(state);
  size_t triangles = 0;
  for (auto _ : state) {
    const PlyMesh m = read_ply(path);
    triangles = m.indices.size() / 3;
    benchmark::DoNotOptimize(m.indices.data());
  }
  state.counters["MB/s"] = benchmark::Counter(double(files().bytes) * 1e-6 * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = double(triangles);
  state.SetLabel(state.range(0) ? "gzip" : "plain");
}
BENCHMARK(BM_ReadPly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TimeToFirstPixel(benchmark::State& state) {
  using clock = std::chrono::steady_clock;
  const std::string& path = path_of(state);
  double load_s = 0, accel_s = 0, render_s = 0;
  for (auto _ : state) {
    const auto t0 = clock::now();
    SceneLoadOptions options;
    options.width = options.height = 64;
    std::vector<std::string> warnings;
    Scene scene = load_scene(path, options, &warnings);
    scene.finalize();
    const auto t1 = clock::now();
    const Accel accel(scene);
    const auto t2 = clock::now();
    render(scene, accel, RenderConfig{}, RunLimit::for_passes(1));
    const auto t3 = clock::now();
    load_s += std::chrono::duration<double>(t1 - t0).count();
    accel_s += std::chrono::duration<double>(t2 - t1).count();
    render_s += std::chrono::duration<double>(t3 - t2).count();
  }
  const double n = double(state.iterations());
  state.counters["load_ms"] = 1e3 * load_s / n;
  state.counters["embree_ms"] = 1e3 * accel_s / n;
  state.counters["render_ms"] = 1e3 * render_s / n;
  state.SetLabel(state.range(0) ? "gzip" : "plain");
}
BENCHMARK(BM_TimeToFirstPixel)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
