// The hashed filter's per-vertex steps (filters/hashed/hashed_filter_steps.h), the code the GPU filter runs,
// run here on the CPU with parallel_for over real vertex buffers, one vertex at a time with plain
// atomics (no local combining, no batched keys): the filtered values must equal HashedFilter::filter's
// bit for bit (memcmp), so the GPU's arithmetic and its overflow settling are checked in CI without
// a GPU. Also the vertex buffer view, the resolve step and the vertex buffer files.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>

#include <gtest/gtest.h>

#include "pathspace/base/error.h"
#include "pathspace/filters/filter_resolve.h"
#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/hashed/hashed_filter_steps.h"
#include "pathspace/filters/hashed/overflow_settling.h"
#include "pathspace/filters/vertex_buffer_file.h"
#include "pathspace/filters/hashed/voxel_hash_table.h"
#include "pathspace/parallel/parallel_for.h"
#include "support/filter_pass_buffers.h"

namespace pathspace {
namespace {

using testing::FilterCase;
using testing::PassBuffer;

constexpr int kWidth = 160, kHeight = 120;

// The GPU filter's algorithm (filters/hashed/cuda_hashed_filter.cu) on the CPU: accumulate, settle, look up.
struct StepsResult {
  SlotValues filtered;
  uint64_t failures = 0;
  bool settled = false;
};

StepsResult filter_with_steps(const HashedFilterSettings& settings, const PassBuffer& pb, uint64_t seed, uint32_t pass) {
  HashedFilterSettings fs = settings;
  fs.key.pixel_angle = 2.f * pb.scene->camera.tan_y / float(pb.scene->camera.height);
  const HashedStepSettings s = step_settings(fs);
  const uint64_t cells = uint64_t(std::max(1.0, double(fs.table_factor) * double(pb.pixels)));
  VoxelHashTable table(cells, fs.max_probes), coarse_table(cells, fs.max_probes);
  const VoxelHashTableView view = table.view(), coarse = coarse_table.view();
  const VertexBuffer& b = pb.buffer;
  const VertexBufferView bv = b.view();
  const uint64_t pass_hash = pass_jitter_hash(seed, pass);
  const size_t slots = bv.slots();
  std::vector<int32_t> slot_of(slots, kSlotProbeFailed), coarse_of(slots, kSlotProbeFailed);
  parallel_for(b.paths(), 64, [&](size_t begin, size_t end) {
    for (size_t path = begin; path < end; ++path)
      for (int r = 0; r < b.count[path]; ++r) {
        const size_t i = b.slot(path, r);
        const AccumulatedVertex a = accumulate_vertex(s, bv, i, pass_hash, view, coarse);
        slot_of[i] = a.slot;
        coarse_of[i] = a.coarse_slot;
      }
  });
  StepsResult out;
  // Settling as the GPU does it: list the failed vertices, the shared decision, then apply.
  std::map<uint64_t, std::vector<uint32_t>> failed_keys;
  std::vector<std::pair<size_t, uint32_t>> failed;
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) {
      const size_t i = b.slot(path, r);
      if (slot_of[i] != kSlotProbeFailed) continue;
      const VoxelHash h = hash_voxel_key(key_for_pass(s.key, bv, i, pass_hash), s.key.normal);
      failed_keys[(h.index & view.mask) / kFingerprintsPerLine].push_back(view.stored_fingerprint(h));
      failed.push_back({i, view.stored_fingerprint(h)});
    }
  out.failures = failed.size();
  if (!failed.empty() && fs.max_probes <= kFingerprintsPerLine) {
    const OverflowDecision d = decide_overflows(failed_keys, view.key_mask, [&](uint64_t c) { return view.fingerprints[c]; },
                                                [](uint64_t) { return true; });
    if (!d.assigned.empty()) {
      out.settled = true;
      std::vector<uint8_t> reassigned(size_t(table.cells()), 0);
      for (const auto& [cell, key] : d.assigned) {
        view.fingerprints[cell] = key;
        view.cells[cell] = VoxelCell{};
        reassigned[cell] = 1;
      }
      for (size_t path = 0; path < b.paths(); ++path)
        for (int r = 0; r < b.count[path]; ++r) {
          const size_t i = b.slot(path, r);
          if (slot_of[i] >= 0 && reassigned[size_t(slot_of[i])]) slot_of[i] = kSlotProbeFailed;
        }
      for (const auto& [i, key] : failed) {
        const auto it = d.cell_of_key.find(key);
        if (it == d.cell_of_key.end()) continue;
        uint64_t fixed[3];
        if (!accumulated_fixed_point(s, b.contribution[i], fixed)) continue;
        add_to_cell(view, it->second, fixed, 1);
        slot_of[i] = int32_t(it->second);
      }
    }
  }
  out.filtered.assign(slots, Rgb());
  parallel_for(b.paths(), 64, [&](size_t begin, size_t end) {
    LookupCounters c;
    for (size_t path = begin; path < end; ++path)
      for (int r = 0; r < b.count[path]; ++r) {
        const size_t i = b.slot(path, r);
        out.filtered[i] = lookup_vertex(s, bv, i, pass_hash, view, coarse, slot_of[i], coarse_of[i], &c);
      }
  });
  return out;
}

const PassBuffer& pass_buffer(const std::string& scene, int nth) {
  static std::map<std::pair<std::string, int>, PassBuffer> buffers;
  auto it = buffers.find({scene, nth});
  if (it == buffers.end()) it = buffers.emplace(std::make_pair(scene, nth), testing::make_pass_buffer(scene, kWidth, kHeight, nth)).first;
  return it->second;
}

class HashedFilterSteps : public ::testing::TestWithParam<FilterCase> {};

TEST_P(HashedFilterSteps, EqualTheCpuFilterBitForBit) {
  const FilterCase& c = GetParam();
  const PassBuffer& pb = pass_buffer(c.scene, c.nth);
  ASSERT_GT(pb.buffer.total_records(), 1000u);
  for (const uint32_t pass : {0u, 3u}) {
    HashedFilter cpu(c.settings, pb.scene->camera, pb.pixels);
    SlotValues expected;
    cpu.filter(pb.buffer, 7, pass, &expected);
    const StepsResult steps = filter_with_steps(c.settings, pb, 7, pass);
    size_t differing = 0;
    EXPECT_TRUE(testing::same_filtered_bits(pb.buffer, expected, steps.filtered, &differing))
        << c.name << " pass " << pass << ": " << differing << " of " << pb.buffer.total_records() << " vertices differ";
    EXPECT_EQ(cpu.stats().settled_passes > 0, steps.settled) << c.name;
    if (c.overflows) {
      EXPECT_TRUE(steps.settled) << c.name << ": the table was meant to overflow";
      EXPECT_GT(cpu.stats().probe_failures, 0u);
    } else {
      EXPECT_EQ(steps.failures, 0u) << c.name;
    }
    if (c.settings.neighbour_search) {
      EXPECT_GT(cpu.stats().neighbour_lookups, 0u);
    }
    if (c.settings.multi_level) {
      EXPECT_GT(cpu.stats().multi_level_used, 0u);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, HashedFilterSteps, ::testing::ValuesIn(testing::filter_cases()),
                         [](const ::testing::TestParamInfo<FilterCase>& i) { return i.param.name; });

TEST(HashedFilterSteps, ResolveMatchesResolveFilteredPass) {
  const PassBuffer& pb = pass_buffer("cornell-box", 2);
  HashedFilter cpu(HashedFilterSettings{}, pb.scene->camera, pb.pixels);
  SlotValues filtered;
  cpu.filter(pb.buffer, 1, 0, &filtered);
  filtered[pb.buffer.slot(0, 0)] = Rgb(std::numeric_limits<float>::infinity());  // one dropped path
  Film film(kWidth, kHeight);
  PathCounters counters;
  resolve_filtered_pass(pb.buffer, filtered, film, &counters);
  Film manual(kWidth, kHeight);
  uint64_t dropped = 0;
  const VertexBufferView v = pb.buffer.view();
  for (size_t path = 0; path < pb.buffer.paths(); ++path) {
    const ResolvedPath r = resolved_path_value(v, path, filtered.data());
    dropped += r.dropped;
    manual.add_sample(pb.buffer.pixel[path], r.value);
  }
  EXPECT_EQ(counters.dropped, dropped);
  const Image a = film.mean(), m = manual.mean();
  ASSERT_EQ(a.size(), m.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), m.pixels.data(), a.size() * sizeof(Rgb)), 0);
}

TEST(HashedFilterSteps, ViewStoreEqualsVertexBufferStore) {
  const PassBuffer& pb = pass_buffer("cornell-glossy", 2);
  VertexBuffer copy;
  copy.resize(pb.buffer.paths(), pb.buffer.records_per_path());
  for (size_t path = 0; path < pb.buffer.paths(); ++path) {
    PathSample s;
    s.prefix = pb.buffer.prefix[path];
    s.count = pb.buffer.count[path];
    for (int r = 0; r < s.count; ++r) s.records[r] = pb.buffer.record(pb.buffer.slot(path, r));
    copy.view().store(path, pb.buffer.pixel[path], s);
  }
  EXPECT_EQ(copy.count, pb.buffer.count);
  EXPECT_EQ(copy.pixel, pb.buffer.pixel);
  for (size_t path = 0; path < pb.buffer.paths(); ++path)
    for (int r = 0; r < pb.buffer.count[path]; ++r) {
      const size_t i = pb.buffer.slot(path, r);
      const FilterVertex x = copy.record(i), y = pb.buffer.record(i);
      ASSERT_EQ(std::memcmp(&x.p, &y.p, sizeof(Vec3)), 0);
      ASSERT_EQ(std::memcmp(&x.contribution, &y.contribution, sizeof(Rgb)), 0);
      ASSERT_EQ(x.layer, y.layer);
      ASSERT_EQ(x.selected, y.selected);
    }
}

std::string temp_path(const char* name) { return ::testing::TempDir() + name; }

TEST(VertexBufferFile, RoundTrips) {
  const PassBuffer& pb = pass_buffer("cornell-box", 0);
  VertexBufferFile f;
  f.buffer = pb.buffer;
  f.settings.neighbour_search = true;
  f.settings.key.pixel_angle = 0.25f;
  f.pixels = pb.pixels;
  f.seed = 11;
  f.pass = 5;
  HashedFilter cpu(f.settings, pb.scene->camera, pb.pixels);
  cpu.filter(pb.buffer, f.seed, f.pass, &f.filtered);
  const std::string path = temp_path("round_trip.psvb");
  write_vertex_buffer_file(path, f);
  const VertexBufferFile g = read_vertex_buffer_file(path);
  EXPECT_EQ(g.buffer.paths(), f.buffer.paths());
  EXPECT_EQ(g.buffer.records_per_path(), f.buffer.records_per_path());
  EXPECT_EQ(g.buffer.count, f.buffer.count);
  EXPECT_EQ(g.buffer.total_records(), f.buffer.total_records());
  // The records, bit for bit (slots that hold none are not part of the buffer's contents).
  for (size_t path = 0; path < f.buffer.paths(); ++path)
    for (int r = 0; r < f.buffer.count[path]; ++r) {
      const size_t i = f.buffer.slot(path, r);
      ASSERT_EQ(std::memcmp(&g.buffer.position[i], &f.buffer.position[i], sizeof(Vec3)), 0) << path << " " << r;
      ASSERT_EQ(std::memcmp(&g.buffer.contribution[i], &f.buffer.contribution[i], sizeof(Rgb)), 0) << path << " " << r;
    }
  EXPECT_EQ(std::memcmp(g.filtered.data(), f.filtered.data(), f.filtered.size() * sizeof(Rgb)), 0);
  EXPECT_TRUE(g.settings.neighbour_search);
  EXPECT_EQ(g.settings.key.pixel_angle, 0.25f);
  EXPECT_EQ(g.seed, 11u);
  EXPECT_EQ(g.pass, 5u);
  EXPECT_EQ(g.pixels, f.pixels);
  std::remove(path.c_str());
}

TEST(VertexBufferFile, BadFilesAreErrors) {
  const PassBuffer& pb = pass_buffer("cornell-box", 0);
  VertexBufferFile f;
  f.buffer = pb.buffer;
  const std::string path = temp_path("bad.psvb");
  write_vertex_buffer_file(path, f);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto write = [&](const std::string& s) { std::ofstream(path, std::ios::binary | std::ios::trunc) << s; };
  const auto expect_error = [&](const std::string& s, const char* what) {
    write(s);
    try {
      read_vertex_buffer_file(path);
      ADD_FAILURE() << what << ": read without an error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("vertex buffer file"), std::string::npos) << e.what();
    }
  };
  expect_error(bytes.substr(0, bytes.size() - 7), "truncated");
  expect_error(bytes + "x", "trailing data");
  std::string magic = bytes;
  magic[0] = 'X';
  expect_error(magic, "magic");
  std::string version = bytes;
  version[8] = 9;
  expect_error(version, "version");
  std::string paths = bytes;
  paths[19] = char(0x7f);  // a huge path count: refused before anything is allocated
  expect_error(paths, "path count");
  expect_error("", "empty");
  EXPECT_THROW(read_vertex_buffer_file(temp_path("missing.psvb")), Error);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace pathspace
