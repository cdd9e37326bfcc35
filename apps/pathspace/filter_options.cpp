#include "filter_options.h"

#include "usage_error.h"

namespace pathspace::cli {

void add_filter_options(CLI::App* cmd, FilterOptions* o) {
  const char* group = "Path space filtering";
  cmd->add_option("--filter", o->filter, "Path space filter of the selected vertices")
      ->check(CLI::IsMember({"none", "hashed"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--psf-select", o->select, "Vertex selection: first / nth / all sufficiently diffuse vertices")
      ->check(CLI::IsMember({"first", "nth", "all"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--psf-nth", o->nth, "With --psf-select nth: which diffuse vertex (2 = final gather)")
      ->check(CLI::Range(1, 16))->capture_default_str()->group(group);
  cmd->add_option("--psf-max-vertices", o->max_vertices, "With --psf-select all: vertices per path")
      ->check(CLI::Range(1, kMaxSelectedVertices))->capture_default_str()->group(group);
  cmd->add_option("--psf-min-roughness", o->min_roughness, "Vertices smoother than this are not selected")
      ->check(CLI::Range(0.f, 1.f))->capture_default_str()->group(group);
  cmd->add_flag("--psf-no-layers", o->no_layers, "One average per vertex instead of one per material layer")->group(group);
  cmd->add_option("--psf-scale", o->scale, "Voxel edge in projected pixels")
      ->check(CLI::Range(0.01f, 10000.f))->capture_default_str()->group(group);
  cmd->add_flag("--psf-no-jitter", o->no_jitter, "Quantise without jittering (shows voxel blocks)")->group(group);
  cmd->add_option("--psf-normal", o->normal, "Normal in the key, only in the fingerprint, or off")
      ->check(CLI::IsMember({"key", "fingerprint", "off"}))->capture_default_str()->group(group);
  cmd->add_option("--psf-table-factor", o->table_factor, "Hash table cells per pixel (rounded up to a power of two)")
      ->check(CLI::Range(0.001f, 64.f))->capture_default_str()->group(group);
  cmd->add_option("--psf-probes", o->probes, "Linear probing limit (<= 16 stays in one cache line)")
      ->check(CLI::Range(1, 4096))->capture_default_str()->group(group);
  cmd->add_option("--psf-min-count", o->min_count, "Voxels with fewer vertices are low-count")
      ->check(CLI::Range(0, 1 << 20))->capture_default_str()->group(group);
  cmd->add_flag("--psf-neighbours", o->neighbours, "Low-count voxels add their 26 neighbours")->group(group);
  cmd->add_flag("--psf-multi-level", o->multi_level, "Low-count voxels use a voxel one level coarser")->group(group);
  cmd->add_flag("--aov", o->aovs, "Also write the filter's debug images (voxel, count, level, probes)")->group(group);
}

void apply_filter_options(const FilterOptions& o, IntegratorSettings* settings) {
  if (o.neighbours && o.multi_level) throw UsageError("--psf-neighbours and --psf-multi-level are alternatives; pick one");
  if (o.aovs && o.filter != "hashed") throw UsageError("--aov needs --filter hashed");
  VertexSelection& sel = settings->pt.selection;
  sel.mode = o.select == "nth" ? VertexSelectionMode::nth : o.select == "all" ? VertexSelectionMode::all : VertexSelectionMode::first;
  sel.n = o.nth;
  sel.max_vertices = o.max_vertices;
  sel.min_roughness = o.min_roughness;
  sel.split_layers = !o.no_layers;

  FilterSettings& f = settings->filter;
  f.kind = o.filter == "hashed" ? FilterKind::hashed : FilterKind::none;
  HashedFilterSettings& h = f.hashed;
  h.key.psf_scale = o.scale;
  h.key.jitter = !o.no_jitter;
  h.key.normal = o.normal == "off" ? NormalKeyMode::off : o.normal == "fingerprint" ? NormalKeyMode::fingerprint : NormalKeyMode::key;
  h.table_factor = o.table_factor;
  h.max_probes = o.probes;
  h.min_count = o.min_count;
  h.neighbour_search = o.neighbours;
  h.multi_level = o.multi_level;
  h.debug_images = o.aovs;
}

}  // namespace pathspace::cli
