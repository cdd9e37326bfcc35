// The GPU's wavefront stages (gpu/wavefront_stages.h) run here from the CPU's parallel loop, stage by
// stage over queues of paths exactly as the CUDA kernels order them (every path's extension, then
// every path's shading, then every pending shadow ray), with Embree as the tracer. Each path must
// end as pt_trace_path ends it, bit for bit: the same prefix, records, throughputs and
// contributions, and the same ray counts. This is the CUDA pipeline's logic, tested without a GPU.
// Both orders run on the parallel loop's threads: the threads' floating-point modes can differ
// (denormals flushed on some; seen on glossy layers' tiny NEE values when one order ran serially).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/gpu/wavefront_stages.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

bool same_bits(const Rgb& a, const Rgb& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Traced {
  std::vector<PathSample> samples;
  PathCounters counters;
};

Traced megakernel_order(const SceneView& view, const Accel& accel, const PtSettings& settings, uint64_t seed, uint32_t pass, uint32_t n) {
  Traced t;
  t.samples.resize(n);
  std::vector<PathCounters> per_path(n);
  parallel_for(n, 256, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Sampler sampler(seed, i, pass);
      pt_trace_path(view, accel, sampler, sample_camera_ray(view.camera, sampler, uint32_t(i), 0.f), settings, &per_path[i], &t.samples[i]);
    }
  });
  for (const PathCounters& c : per_path) t.counters += c;
  return t;
}

Traced wavefront_order(const SceneView& view, const Accel& accel, const PtSettings& settings, uint64_t seed, uint32_t pass, uint32_t n) {
  Traced t;
  t.samples.resize(n);
  std::vector<PtPathState> states(n);
  std::vector<pt_detail::OpenVertex> open(size_t(n) * kMaxSelectedVertices);
  std::vector<SurfaceHit> hits(n);
  std::vector<uint8_t> found(n), ends_after_shadow(n);
  std::vector<uint32_t> current(n), next(n), shadow(n);
  uint32_t current_count = n, next_count = 0, shadow_count = 0;
  std::vector<PathCounters> per_path(n);
  parallel_for(n, 256, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      wavefront_camera(view, seed, pass, uint32_t(i), &states[i], &open[i * kMaxSelectedVertices]);
      current[i] = uint32_t(i);
    }
  });
  while (current_count > 0) {
    next_count = shadow_count = 0;
    const PathQueue next_queue{next.data(), &next_count}, shadow_queue{shadow.data(), &shadow_count};
    parallel_for(current_count, 256, [&](size_t b, size_t e) {
      for (size_t k = b; k < e; ++k) found[current[k]] = wavefront_extend(accel, states[current[k]], &hits[current[k]]) ? 1 : 0;
    });
    parallel_for(current_count, 256, [&](size_t b, size_t e) {
      for (size_t k = b; k < e; ++k) {
        const uint32_t p = current[k];
        const WavefrontAfterShade after =
            wavefront_shade(view, accel, settings, seed, pass, p, hits[p], found[p] != 0, &states[p], &per_path[p]);
        if (after == WavefrontAfterShade::extend) next_queue.push(p);
        if (after == WavefrontAfterShade::shadow_then_extend || after == WavefrontAfterShade::shadow_then_end) {
          ends_after_shadow[p] = after == WavefrontAfterShade::shadow_then_end;
          shadow_queue.push(p);
        }
        if (after == WavefrontAfterShade::ended) pt_finish(&states[p], &t.samples[p]);
      }
    });
    parallel_for(shadow_count, 256, [&](size_t b, size_t e) {
      for (size_t k = b; k < e; ++k) {
        const uint32_t p = shadow[k];
        wavefront_shadow(accel, &states[p]);
        if (ends_after_shadow[p]) {
          pt_finish(&states[p], &t.samples[p]);
        } else {
          next_queue.push(p);
        }
      }
    });
    current.swap(next);
    current_count = next_count;
  }
  for (const PathCounters& c : per_path) t.counters += c;
  return t;
}

void expect_same_paths(const std::string& scene_name, const PtSettings& with_branches) {
  const PtSettings settings = without_camera_branches(with_branches);
  const Scene scene = make_builtin_scene(scene_name, 48, 48);
  const Accel accel(scene);
  const SceneView view = scene.view();
  const uint32_t n = 48 * 48;
  for (uint32_t pass = 0; pass < 3; ++pass) {
    const Traced a = megakernel_order(view, accel, settings, 7, pass, n);
    const Traced b = wavefront_order(view, accel, settings, 7, pass, n);
    EXPECT_EQ(a.counters.rays, b.counters.rays) << scene_name;
    EXPECT_EQ(a.counters.shadow_rays, b.counters.shadow_rays) << scene_name;
    size_t differing = 0;
    for (uint32_t i = 0; i < n; ++i) {
      const PathSample &x = a.samples[i], &y = b.samples[i];
      bool same = same_bits(x.prefix, y.prefix) && x.count == y.count;
      for (int r = 0; same && r < x.count; ++r)
        same = same_bits(x.records[r].throughput, y.records[r].throughput) && same_bits(x.records[r].contribution, y.records[r].contribution) &&
               std::memcmp(&x.records[r].p, &y.records[r].p, sizeof(Vec3)) == 0 && x.records[r].layer == y.records[r].layer;
      differing += same ? 0 : 1;
    }
    EXPECT_EQ(differing, 0u) << scene_name << " pass " << pass;
  }
}

TEST(WavefrontStages, PlainPathsEqualPtTracePath) {
  PtSettings plain;  // as without a filter: no vertex split off
  plain.selection.mode = VertexSelectionMode::none;
  for (const char* s : {"cornell-box", "cornell-glossy", "cornell-glossy-point", "cornell-glossy-background", "cornell-glossy-sun"})
    expect_same_paths(s, plain);
}

TEST(WavefrontStages, FilteredPathsEqualPtTracePath) {
  PtSettings first;  // the hashed filter's default selection: the first diffuse vertex
  expect_same_paths("cornell-box", first);
  PtSettings all;
  all.selection.mode = VertexSelectionMode::all;
  expect_same_paths("cornell-glossy", all);
  PtSettings nth;
  nth.selection.mode = VertexSelectionMode::nth;
  nth.selection.n = 2;
  expect_same_paths("cornell-box", nth);
}

TEST(WavefrontStages, OneSidedTechniquesEqualPtTracePath) {
  PtSettings nee_only;
  nee_only.bsdf_sampling = false;
  expect_same_paths("cornell-box", nee_only);
  PtSettings bsdf_only;
  bsdf_only.nee = false;
  expect_same_paths("cornell-glossy", bsdf_only);
}

}  // namespace
}  // namespace pathspace
