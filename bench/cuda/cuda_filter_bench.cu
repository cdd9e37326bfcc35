// The GPU hashed filter's benchmark (docs/benchmarks.md, "GPU filter"): reads vertex buffer files
// (bench/write_vertex_buffers.cpp), checks that CudaHashedFilter's output equals the file's CPU
// output bit for bit, then times accumulation and lookup (median of --runs after warm-up, cudaEvents)
// against two limits of the same GPU in the same run: (a) a device-to-device copy of as many bytes
// as the filter must move, (b) random 32-byte read-modify-writes into a table as large as the hash
// table, one per vertex.
//   cuda_filter_bench FILE... [--runs N] [--json OUT]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "pathspace/filters/vertex_buffer_file.h"
#include "pathspace/gpu/cuda_event_timer.h"
#include "pathspace/filters/hashed/cuda_hashed_filter.h"
#include "pathspace/filters/cuda_vertex_buffer.h"

namespace {

using namespace pathspace;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// One 32-byte read-modify-write per vertex into a random cell (no atomics: the memory system's limit
// for the access pattern of accumulation, without the cost of the atomics themselves).
__global__ void random_rmw_kernel(uint4* table, uint64_t mask, size_t n) {
  const size_t i = size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const uint64_t c = mix64(uint64_t(i) ^ 0x9e3779b97f4a7c15ull) & mask;
  uint4 x = table[2 * c], y = table[2 * c + 1];
  x.x += 1u, x.y += 2u, x.z += 3u, x.w += 4u;
  y.x += 5u, y.y += 6u, y.z += 7u, y.w += 8u;
  table[2 * c] = x;
  table[2 * c + 1] = y;
}

struct Row {
  std::string file;
  bool pass = false;
  size_t differing = 0;
  uint64_t vertices = 0, bytes = 0, cells = 0, occupied = 0;
  double clear_ms = 0, accumulate_ms = 0, lookup_ms = 0, copy_ms = 0, rmw_ms = 0;
  double total_ms() const { return accumulate_ms + lookup_ms; }
  double gbs() const { return total_ms() > 0 ? double(bytes) / (total_ms() * 1e6) : 0.0; }
};

// The bytes accumulation and lookup must move at least (each crossing DRAM once):
//   per vertex: the key inputs and contribution read (5 vectors, 2 floats, 2 bytes, 1 colour: 82 B),
//     its cell index written and read back (4 + 4 B) and its filtered colour written (12 B);
//   per path: its record count, read by both kernels (2 B);
//   per occupied cell: fingerprint and sums read and written by accumulation (2 x 36 B) and the sums
//     read by lookup (32 B).
uint64_t filter_bytes(uint64_t vertices, uint64_t paths, uint64_t occupied) {
  const uint64_t per_vertex = 5 * sizeof(Vec3) + 2 * sizeof(float) + 2 + sizeof(Rgb) + 4 + 4 + sizeof(Rgb);
  return vertices * per_vertex + paths * 2 + occupied * (2 * (sizeof(uint32_t) + sizeof(VoxelCell)) + sizeof(VoxelCell));
}

Row run_file(const std::string& path, int runs) {
  Row row;
  row.file = path;
  const VertexBufferFile f = read_vertex_buffer_file(path);
  if (f.filtered.empty()) throw Error(path + " holds no CPU output to check against");
  gpu::DeviceVertexBuffer device;
  device.upload(f.buffer);
  const VertexBufferView view = device.view();
  gpu::DeviceBuffer<Rgb> filtered(view.slots());
  gpu::CudaHashedFilter filter(f.settings, f.settings.key.pixel_angle, size_t(f.pixels));

  // Bit-exactness first (the same seed and pass as the CPU's).
  filter.filter(view, f.seed, f.pass, filtered.data());
  const std::vector<Rgb> got = filtered.download();
  const VertexBuffer& b = f.buffer;
  for (size_t p = 0; p < b.paths(); ++p)
    for (int r = 0; r < b.count[p]; ++r) {
      const size_t i = b.slot(p, r);
      if (std::memcmp(&got[i], &f.filtered[i], sizeof(Rgb)) != 0) ++row.differing;
    }
  row.pass = row.differing == 0;
  row.vertices = b.total_records();
  row.cells = filter.cells();
  row.occupied = filter.stats().occupied_cells_last;
  std::printf("%s: %s (%zu of %llu vertices differ)\n", path.c_str(), row.pass ? "PASS" : "FAIL", row.differing,
              (unsigned long long)row.vertices);

  // The filter, median of `runs` after warm-up.
  std::vector<double> clear, accumulate, lookup;
  for (int k = 0; k < 5; ++k) filter.filter(view, f.seed, f.pass, filtered.data());
  for (int k = 0; k < runs; ++k) {
    filter.filter(view, f.seed, f.pass, filtered.data());
    clear.push_back(filter.stats().clear_ms_last);
    accumulate.push_back(filter.stats().accumulate_ms_last);
    lookup.push_back(filter.stats().lookup_ms_last);
  }
  row.clear_ms = median(clear);
  row.accumulate_ms = median(accumulate);
  row.lookup_ms = median(lookup);
  row.bytes = filter_bytes(row.vertices, b.paths(), row.occupied);

  // (a) A device-to-device copy moving the same bytes (read + written: a copy of half of them).
  const size_t half = size_t(row.bytes / 2);
  gpu::DeviceBuffer<uint8_t> from(half), to(half);
  from.fill_bytes(1);
  gpu::CudaEventTimer timer;
  std::vector<double> copy, rmw;
  for (int k = 0; k < runs + 5; ++k) {
    timer.start();
    PS_CUDA_CHECK(cudaMemcpyAsync(to.data(), from.data(), half, cudaMemcpyDeviceToDevice));
    const double ms = timer.lap();
    if (k >= 5) copy.push_back(ms);
  }
  row.copy_ms = median(copy);
  // (b) One random 32-byte read-modify-write per vertex into a table of the hash table's cells.
  gpu::DeviceBuffer<uint4> table(size_t(row.cells) * 2);
  table.fill_bytes(0);
  const size_t n = size_t(row.vertices);
  for (int k = 0; k < runs + 5; ++k) {
    timer.start();
    random_rmw_kernel<<<unsigned((n + 255) / 256), 256>>>(table.data(), row.cells - 1, n);
    PS_CUDA_CHECK_LAUNCH("random_rmw_kernel");
    const double ms = timer.lap();
    if (k >= 5) rmw.push_back(ms);
  }
  row.rmw_ms = median(rmw);
  return row;
}

void write_json(const std::string& path, const std::vector<Row>& rows, int runs) {
  FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw Error("cannot write " + path);
  int device = 0;
  cudaDeviceProp p{};
  PS_CUDA_CHECK(cudaGetDevice(&device));
  PS_CUDA_CHECK(cudaGetDeviceProperties(&p, device));
  std::fprintf(out, "{\n  \"device\": \"%s\",\n  \"runs\": %d,\n  \"files\": [\n", p.name, runs);
  for (size_t k = 0; k < rows.size(); ++k) {
    const Row& r = rows[k];
    std::fprintf(out,
                 "    {\"file\": \"%s\", \"bit_exact\": %s, \"differing\": %zu, \"vertices\": %llu, \"cells\": %llu, "
                 "\"occupied\": %llu, \"bytes\": %llu, \"clear_ms\": %.6f, \"accumulate_ms\": %.6f, \"lookup_ms\": %.6f, "
                 "\"total_ms\": %.6f, \"gb_per_s\": %.3f, \"copy_ms\": %.6f, \"rmw_ms\": %.6f, \"ratio_to_copy\": %.4f, "
                 "\"ratio_to_rmw\": %.4f}%s\n",
                 r.file.c_str(), r.pass ? "true" : "false", r.differing, (unsigned long long)r.vertices,
                 (unsigned long long)r.cells, (unsigned long long)r.occupied, (unsigned long long)r.bytes, r.clear_ms,
                 r.accumulate_ms, r.lookup_ms, r.total_ms(), r.gbs(), r.copy_ms, r.rmw_ms, r.total_ms() / r.copy_ms,
                 r.total_ms() / r.rmw_ms, k + 1 < rows.size() ? "," : "");
  }
  std::fprintf(out, "  ]\n}\n");
  std::fclose(out);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  std::string json;
  int runs = 100;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::atoi(argv[++i]);
    } else if (a == "--json" && i + 1 < argc) {
      json = argv[++i];
    } else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr, "usage: cuda_filter_bench FILE... [--runs N (>= 50)] [--json OUT]\n");
      return 2;
    } else {
      files.push_back(a);
    }
  }
  if (files.empty() || runs < 50) {
    std::fprintf(stderr, "usage: cuda_filter_bench FILE... [--runs N (>= 50)] [--json OUT]\n");
    return 2;
  }
  try {
    std::vector<Row> rows;
    for (const std::string& f : files) rows.push_back(run_file(f, runs));
    std::printf("\nmedian of %d runs; bytes: what accumulation + lookup must move (cuda_filter_bench.cu, filter_bytes)\n", runs);
    std::printf("%-28s %10s %9s %9s %9s %9s %8s %8s %8s %7s %7s\n", "file", "vertices", "clear ms", "accum ms", "lookup ms",
                "total ms", "GB/s", "copy ms", "rmw ms", "/copy", "/rmw");
    bool all_pass = true;
    for (const Row& r : rows) {
      std::string name = r.file.substr(r.file.find_last_of('/') == std::string::npos ? 0 : r.file.find_last_of('/') + 1);
      std::printf("%-28s %10llu %9.4f %9.4f %9.4f %9.4f %8.1f %8.4f %8.4f %7.2f %7.2f %s\n", name.c_str(),
                  (unsigned long long)r.vertices, r.clear_ms, r.accumulate_ms, r.lookup_ms, r.total_ms(), r.gbs(), r.copy_ms,
                  r.rmw_ms, r.total_ms() / r.copy_ms, r.total_ms() / r.rmw_ms, r.pass ? "PASS" : "FAIL");
      all_pass = all_pass && r.pass;
    }
    if (!json.empty()) write_json(json, rows, runs);
    return all_pass ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cuda_filter_bench: %s\n", e.what());
    return 1;
  }
}
