// The GPU hashed filter (filters/hashed/cuda_hashed_filter.h) against the CPU's HashedFilter on real vertex
// buffers: the filtered values must be the same bits (primary hits, second bounce, neighbour search,
// multi-level, a table so small that windows overflow), and DeviceVertexBuffer must round-trip.
// Label cuda; builds wherever CUDA is built, and skips (a pass for ctest) where no GPU is present.
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "pathspace/base/error.h"
#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/hashed/cuda_hashed_filter.h"
#include "pathspace/filters/cuda_vertex_buffer.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/stats/statistics.h"
#include "gpu_comparison.h"
#include "support/filter_pass_buffers.h"

namespace pathspace {
namespace {

using testing::FilterCase;
using testing::PassBuffer;

constexpr int kWidth = 320, kHeight = 240;

const PassBuffer& pass_buffer(const std::string& scene, int nth) {
  static std::map<std::pair<std::string, int>, PassBuffer> buffers;
  auto it = buffers.find({scene, nth});
  if (it == buffers.end()) it = buffers.emplace(std::make_pair(scene, nth), testing::make_pass_buffer(scene, kWidth, kHeight, nth)).first;
  return it->second;
}

TEST(CudaVertexBuffer, UploadDownloadRoundTrips) {
  PATHSPACE_REQUIRE_GPU();
  const PassBuffer& pb = pass_buffer("cornell-glossy", 2);
  gpu::DeviceVertexBuffer device;
  device.upload(pb.buffer);
  EXPECT_EQ(device.paths(), pb.buffer.paths());
  EXPECT_EQ(device.view().slots(), pb.buffer.paths() * size_t(pb.buffer.records_per_path()));
  VertexBuffer back;
  device.download(&back);
  EXPECT_EQ(back.records_per_path(), pb.buffer.records_per_path());
  EXPECT_EQ(back.count, pb.buffer.count);
  EXPECT_EQ(back.pixel, pb.buffer.pixel);
  const auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
  };
  EXPECT_TRUE(same(back.prefix, pb.buffer.prefix));
  EXPECT_TRUE(same(back.position, pb.buffer.position));
  EXPECT_TRUE(same(back.geometric_normal, pb.buffer.geometric_normal));
  EXPECT_TRUE(same(back.shading_normal, pb.buffer.shading_normal));
  EXPECT_TRUE(same(back.incident, pb.buffer.incident));
  EXPECT_TRUE(same(back.previous_position, pb.buffer.previous_position));
  EXPECT_TRUE(same(back.prefix_distance, pb.buffer.prefix_distance));
  EXPECT_TRUE(same(back.roughness, pb.buffer.roughness));
  EXPECT_TRUE(same(back.throughput, pb.buffer.throughput));
  EXPECT_TRUE(same(back.contribution, pb.buffer.contribution));
  EXPECT_EQ(back.layer, pb.buffer.layer);
  EXPECT_EQ(back.segments, pb.buffer.segments);
  EXPECT_EQ(back.selected, pb.buffer.selected);
  EXPECT_EQ(back.visible_lights, pb.buffer.visible_lights);
  EXPECT_TRUE(same(back.open_distance, pb.buffer.open_distance));
}

class CudaHashedFilterTest : public ::testing::TestWithParam<FilterCase> {};

TEST_P(CudaHashedFilterTest, EqualsTheCpuFilterBitForBit) {
  PATHSPACE_REQUIRE_GPU();
  const FilterCase& c = GetParam();
  const PassBuffer& pb = pass_buffer(c.scene, c.nth);
  gpu::DeviceVertexBuffer device;
  device.upload(pb.buffer);
  const size_t slots = device.view().slots();
  gpu::DeviceBuffer<Rgb> filtered_device(slots);
  gpu::CudaHashedFilter gpu_filter(c.settings, pb.scene->camera, pb.pixels);
  for (const uint32_t pass : {0u, 3u}) {
    HashedFilter cpu(c.settings, pb.scene->camera, pb.pixels);
    SlotValues expected;
    cpu.filter(pb.buffer, 7, pass, &expected);
    gpu_filter.filter(device.view(), 7, pass, filtered_device.data());
    const std::vector<Rgb> got = filtered_device.download();
    size_t differing = 0;
    EXPECT_TRUE(testing::same_filtered_bits(pb.buffer, expected, got, &differing))
        << c.name << " pass " << pass << ": " << differing << " of " << pb.buffer.total_records() << " vertices differ";
    EXPECT_EQ(gpu_filter.stats().settled_passes > 0, cpu.stats().settled_passes > 0) << c.name;
    if (c.overflows) {
      EXPECT_GT(gpu_filter.stats().settled_passes, 0u) << c.name;
    }
  }
  const HashedFilterStats& s = gpu_filter.stats();
  EXPECT_EQ(s.passes, 2u);
  EXPECT_EQ(s.vertices, 2 * pb.buffer.total_records());
  EXPECT_LE(s.insertions, s.vertices - s.not_accumulated);
  EXPECT_GT(s.accumulate_ms, 0.0);
  EXPECT_GT(s.lookup_ms, 0.0);
  Statistics stats;
  gpu_filter.statistics(stats);
  std::printf("%s: %llu vertices/pass, %.1f%% warp-aggregated, mean probes %.2f, fallbacks %llu, "
              "accumulate %.3f ms, lookup %.3f ms (last pass)\n",
              c.name.c_str(), (unsigned long long)(s.vertices / s.passes),
              100.0 * (1.0 - double(s.insertions) / double(std::max<uint64_t>(1, s.vertices))), s.mean_probes(),
              (unsigned long long)s.probe_failures, s.accumulate_ms_last, s.lookup_ms_last);
}

INSTANTIATE_TEST_SUITE_P(Cases, CudaHashedFilterTest, ::testing::ValuesIn(testing::filter_cases()),
                         [](const ::testing::TestParamInfo<FilterCase>& i) { return i.param.name; });

// Refused in the constructor, before anything touches the device: runs without a GPU too.
// (--temporal integrate and ema run on the GPU: cuda_temporal_filter_test.cpp.)
TEST(CudaHashedFilter, RefusesWhatTheGpuDoesNotDo) {
  const PassBuffer& pb = pass_buffer("cornell-box", 0);
  const auto expect_refused = [&](const HashedFilterSettings& settings, const char* option) {
    try {
      gpu::CudaHashedFilter f(settings, pb.scene->camera, pb.pixels);
      ADD_FAILURE() << option << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  };
  HashedFilterSettings hybrid;
  hybrid.temporal.mode = TemporalMode::hybrid;
  expect_refused(hybrid, "--temporal hybrid");
  HashedFilterSettings aov;
  aov.debug_images = true;
  expect_refused(aov, "--aov");
  HashedFilterSettings adaptive;
  adaptive.adaptive = true;
  expect_refused(adaptive, "--psf-adaptive");
  HashedFilterSettings queries;
  queries.aa_paths = 2;
  expect_refused(queries, "--psf-aa-paths");
}

}  // namespace
}  // namespace pathspace
