#include "studies/gallery/gallery.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/session/render.h"
#include "pathspace/study/error_colormap.h"
#include "pathspace/study/image_files.h"
#include "pathspace/study/markup_escape.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::studies {

namespace {

namespace fs = std::filesystem;

constexpr const char* kReferenceName = "TungstenRender.exr";
// Scene files preferred in a folder holding several forms of one scene (Bitterli's: pbrt-v4 and
// Mitsuba 3), then any file of a format the loader reads, by name.
constexpr std::array<const char*, 4> kPreferredScenes = {"scene-v4.pbrt", "scene.pbrt", "scene.xml", "scene.gltf"};
constexpr std::array<const char*, 4> kSceneExtensions = {".pbrt", ".xml", ".gltf", ".glb"};

struct GalleryEntry {
  std::string name;          // the folder's name relative to DIR ("." for DIR itself)
  fs::path scene, reference;
  std::string error;         // set when it could not be rendered
  std::vector<std::string> warnings;
  int width = 0, height = 0;
  uint32_t passes = 0;
  double seconds = 0.0;
  std::array<double, 3> mean{}, reference_mean{};
  std::array<double, 3> mean_error{};  // standard error of our channel means (the film's variance of the mean)
  double rel_mse = 0.0;
  size_t non_finite_pixels = 0;  // of the reference (or the render): left out of every number
  study::ImageFiles images, reference_images;
};

fs::path scene_file_in(const fs::path& folder) {
  for (const char* name : kPreferredScenes)
    if (fs::is_regular_file(folder / name)) return folder / name;
  std::vector<fs::path> candidates;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && std::find(kSceneExtensions.begin(), kSceneExtensions.end(), ext) != kSceneExtensions.end())
      candidates.push_back(e.path());
  }
  std::sort(candidates.begin(), candidates.end());
  return candidates.empty() ? fs::path() : candidates.front();
}

// DIR itself and its subfolders (sorted), each that holds a reference image.
std::vector<GalleryEntry> find_entries(const fs::path& dir) {
  std::vector<fs::path> folders = {dir};
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_directory()) folders.push_back(e.path());
  std::sort(folders.begin() + 1, folders.end());
  std::vector<GalleryEntry> entries;
  for (const fs::path& folder : folders) {
    if (!fs::is_regular_file(folder / kReferenceName)) continue;
    GalleryEntry e;
    e.name = folder == dir ? dir.filename().string() : folder.filename().string();
    e.reference = folder / kReferenceName;
    e.scene = scene_file_in(folder);
    if (e.scene.empty()) e.error = "no scene file (.pbrt, .xml, .gltf, .glb) beside the reference";
    entries.push_back(std::move(e));
  }
  return entries;
}

std::array<double, 3> channel_means(const Image& image) {
  std::array<double, 3> m{};
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) m[size_t(c)] += double(p[c]);
  for (double& v : m) v /= double(std::max<size_t>(1, image.size()));
  return m;
}

// Sets the pixels that are not finite in either image to 0 in both (Tungsten's references hold a
// few NaN pixels); returns how many.
size_t clear_non_finite(Image* a, Image* b) {
  size_t n = 0;
  for (size_t i = 0; i < a->size(); ++i)
    if (!all_finite(a->pixels[i]) || !all_finite(b->pixels[i])) {
      a->pixels[i] = b->pixels[i] = Rgb();
      ++n;
    }
  return n;
}

// The standard error of each channel's image mean: sqrt(sum of the pixels' variances of the mean) / N.
std::array<double, 3> channel_mean_errors(const Image& variance, const Image& mean) {
  std::array<double, 3> s{};
  for (size_t i = 0; i < variance.size(); ++i)
    if (all_finite(mean.pixels[i]))
      for (int c = 0; c < 3; ++c) s[size_t(c)] += double(variance.pixels[i][c]);
  for (double& v : s) v = std::sqrt(v) / double(std::max<size_t>(1, variance.size()));
  return s;
}

double ratio(const GalleryEntry& e, int c) {
  return e.reference_mean[size_t(c)] != 0.0 ? e.mean[size_t(c)] / e.reference_mean[size_t(c)] : 0.0;
}

void render_entry(const GalleryOptions& o, GalleryEntry* e) {
  Image reference = read_image(e->reference.string());
  e->width = reference.width;
  e->height = reference.height;
  SceneLoadOptions load;
  load.width = reference.width;
  load.height = reference.height;
  load.substitute_missing_textures = o.substitute_missing_textures;
  const Scene scene = load_scene(e->scene.string(), load, &e->warnings);
  const Accel accel(scene);
  RenderConfig config;
  config.integrator = o.integrator;
  config.seed = o.seed;
  config.threads = o.threads;
  RenderSnapshot r = render(scene, accel, config, RunLimit::for_seconds(o.time_s));
  e->passes = r.stats.spp;
  e->seconds = r.stats.wall_s;
  e->non_finite_pixels = clear_non_finite(&r.mean, &reference);
  e->mean_error = channel_mean_errors(r.variance, r.mean);
  e->mean = channel_means(r.mean);
  e->reference_mean = channel_means(reference);
  e->rel_mse = image_error(r.mean, reference).rel_mse;
  const std::string base = "images/" + study::slug(e->name);
  e->images = study::write_images(o.out, base, r.mean, reference, !o.no_exr);
  e->reference_images = study::write_images(o.out, base + "-reference", reference, Image(), false);
}

double ratio_error(const GalleryEntry& e, int c) {
  return e.reference_mean[size_t(c)] != 0.0 ? e.mean_error[size_t(c)] / e.reference_mean[size_t(c)] : 0.0;
}

nlohmann::ordered_json to_json(const GalleryEntry& e) {
  nlohmann::ordered_json j;
  j["name"] = e.name;
  j["scene"] = e.scene.string();
  j["reference"] = e.reference.string();
  if (!e.error.empty()) {
    j["error"] = e.error;
  } else {
    j["width"] = e.width;
    j["height"] = e.height;
    j["passes"] = e.passes;
    j["seconds"] = e.seconds;
    j["mean"] = e.mean;
    j["reference_mean"] = e.reference_mean;
    j["mean_ratio"] = {ratio(e, 0), ratio(e, 1), ratio(e, 2)};
    j["mean_ratio_standard_error"] = {ratio_error(e, 0), ratio_error(e, 1), ratio_error(e, 2)};
    j["rel_mse"] = e.rel_mse;
    j["non_finite_pixels"] = e.non_finite_pixels;
    j["image"] = e.images.png;
    j["error_map"] = e.images.error_png;
    j["reference_image"] = e.reference_images.png;
  }
  j["warnings"] = e.warnings;
  return j;
}

std::string html_page(const GalleryOptions& o, const std::vector<GalleryEntry>& entries) {
  using study::escape_markup;
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>pathspace gallery</title>\n"
                  "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}td,th{border:1px solid #ccc;"
                  "padding:4px 8px;text-align:right}td:first-child{text-align:left}img{max-width:32%;margin-right:1%}"
                  ".off{color:#b00}.ramp{display:inline-block;width:200px;height:12px;vertical-align:middle}</style></head><body>\n";
  h += fmt::format("<h1>Gallery: {}</h1>\n<p>{} for {} s per scene at the reference's resolution, seed {}, against each "
                   "folder's {}. Mean ratio: our channel mean over the reference's (1 = equal brightness), &plusmn; the "
                   "standard error of our mean (from the render's own variance); cells off by more than 5% are red. "
                   "relMSE includes our remaining noise.</p>\n",
                   escape_markup(o.dir), escape_markup(o.integrator), o.time_s, o.seed, kReferenceName);
  h += "<table><tr><th>scene</th><th>size</th><th>passes</th><th>mean ratio R</th><th>G</th><th>B</th><th>relMSE</th>"
       "<th>pixels left out (not finite)</th><th>warnings</th></tr>\n";
  for (const GalleryEntry& e : entries) {
    if (!e.error.empty()) {
      h += fmt::format("<tr><td>{}</td><td colspan=\"8\" class=\"off\" style=\"text-align:left\">{}</td></tr>\n",
                       escape_markup(e.name), escape_markup(e.error));
      continue;
    }
    h += fmt::format("<tr><td><a href=\"#{}\">{}</a></td><td>{}&times;{}</td><td>{}</td>", study::slug(e.name),
                     escape_markup(e.name), e.width, e.height, e.passes);
    for (int c = 0; c < 3; ++c)
      h += fmt::format("<td{}>{:.3f} &plusmn; {:.3f}</td>", std::abs(ratio(e, c) - 1.0) > 0.05 ? " class=\"off\"" : "", ratio(e, c),
                       ratio_error(e, c));
    h += fmt::format("<td>{:.4g}</td><td>{}</td><td>{}</td></tr>\n", e.rel_mse, e.non_finite_pixels, e.warnings.size());
  }
  h += "</table>\n<p>Error maps: relative squared error per pixel, <span class=\"ramp\" style=\"background:" +
       study::error_ramp_css_gradient() + "\"></span></p>\n";
  for (const GalleryEntry& e : entries) {
    if (!e.error.empty()) continue;
    h += fmt::format("<h2 id=\"{}\">{}</h2>\n<p>{}</p>\n<p>", study::slug(e.name), escape_markup(e.name), escape_markup(e.scene.string()));
    h += fmt::format("<img src=\"{}\" alt=\"pathspace\" title=\"pathspace\"><img src=\"{}\" alt=\"reference\" title=\"reference\">"
                     "<img src=\"{}\" alt=\"error map\" title=\"relative error\"></p>\n",
                     escape_markup(e.images.png), escape_markup(e.reference_images.png), escape_markup(e.images.error_png));
    if (!e.warnings.empty()) {
      h += "<details><summary>loader warnings</summary><ul>\n";
      for (const std::string& w : e.warnings) h += "<li>" + escape_markup(w) + "</li>\n";
      h += "</ul></details>\n";
    }
  }
  return h + "</body></html>\n";
}

}  // namespace

int run_gallery_study(const GalleryOptions& o) {
  if (!fs::is_directory(o.dir)) throw UsageError("'" + o.dir + "' is not a folder", "give the folder of scenes, e.g. ../shared/scenes/bitterli");
  if (!integrator_registry().find(o.integrator))
    throw UsageError("unknown integrator '" + o.integrator + "'", "run 'pathspace info --integrators' for the list");
  if (o.out.empty()) throw UsageError("--out must name a folder");
  std::vector<GalleryEntry> entries = find_entries(fs::path(o.dir));
  if (entries.empty()) throw UsageError("no folder under '" + o.dir + "' holds a " + kReferenceName);
  study::create_image_folder(o.out);
  check_output_writable(o.out + "/gallery.json");
  for (GalleryEntry& e : entries) {
    if (!e.error.empty()) continue;
    if (!o.quiet) fmt::print("{}: {} for {} s ...\n", e.name, e.scene.string(), o.time_s);
    std::fflush(stdout);
    try {
      render_entry(o, &e);
    } catch (const std::exception& ex) {  // one broken scene does not stop the gallery
      e.error = ex.what();
    }
    if (!o.quiet) {
      if (e.error.empty()) {
        fmt::print("  {} passes, mean ratio {:.3f} {:.3f} {:.3f} (standard error {:.3f} {:.3f} {:.3f}), relMSE {:.4g}\n", e.passes,
                   ratio(e, 0), ratio(e, 1), ratio(e, 2), ratio_error(e, 0), ratio_error(e, 1), ratio_error(e, 2), e.rel_mse);
      } else {
        fmt::print("  not rendered: {}\n", e.error);
      }
    }
  }
  nlohmann::ordered_json doc;
  doc["dir"] = o.dir;
  doc["integrator"] = o.integrator;
  doc["time_s"] = o.time_s;
  doc["seed"] = o.seed;
  doc["scenes"] = nlohmann::ordered_json::array();
  for (const GalleryEntry& e : entries) doc["scenes"].push_back(to_json(e));
  write_text_file(o.out + "/gallery.json", doc.dump(2) + "\n");
  write_text_file(o.out + "/gallery.html", html_page(o, entries));
  if (!o.quiet) fmt::print("wrote {0}/gallery.html, {0}/gallery.json and {0}/images/\n", o.out);
  return 0;
}

}  // namespace pathspace::studies
