// render for Python: one RenderSession with the options given as keyword arguments, checked
// against the registry's option catalog (session/option_catalog.h) and configured by
// configure_render exactly as the CLI is, so a render from Python equals the CLI's bit for bit.
// The GIL is released while the session runs; between passes the progress callback runs and a
// pending Ctrl-C (KeyboardInterrupt) cancels the render, keeping the passes done.
#include <algorithm>
#include <chrono>
#include <optional>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "json_values.h"
#include "py_scene.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/options/option_parse.h"
#include "pathspace/session/option_catalog.h"
#include "pathspace/session/render_config.h"
#include "pathspace/session/run_options.h"
#include "pathspace/session/render_session.h"
#include "pathspace/session/render_stats_json.h"

namespace pathspace::python {

namespace {

std::string keyword_of(const std::string& option) {
  std::string k = option;
  std::replace(k.begin(), k.end(), '-', '_');
  return k;
}

std::string keywords_of(const std::vector<CatalogOption>& options) {
  std::string out;
  for (const CatalogOption& o : options) out += (out.empty() ? "" : ", ") + keyword_of(o.spec.name);
  return out.empty() ? "none" : out;
}

// Keyword arguments (psf_scale=12) as the CLI's option texts (--psf-scale 12). Unknown keywords and
// keywords of another integrator or filter raise TypeError naming the valid ones; the values are
// checked by configure_render (ValueError with the CLI's message).
OptionValues option_values(const std::string& integrator, const std::string& filter, const py::dict& kwargs) {
  check_composition(integrator, filter);  // OptionError (ValueError) for an unknown integrator or filter
  const std::vector<CatalogOption> valid = options_of(integrator, filter);
  const std::vector<CatalogOption> all = option_catalog();
  OptionValues out;
  for (const auto& [key, value] : kwargs) {
    const std::string keyword = py::str(key);
    std::string name = keyword;
    std::replace(name.begin(), name.end(), '_', '-');
    const auto spec = std::find_if(valid.begin(), valid.end(), [&](const CatalogOption& o) { return o.spec.name == name; });
    if (keyword.find('-') != std::string::npos || spec == valid.end()) {
      const auto other = std::find_if(all.begin(), all.end(), [&](const CatalogOption& o) { return o.spec.name == name; });
      std::string where;
      if (other != all.end() && keyword.find('-') == std::string::npos) {
        std::string owners;
        for (const std::string& i : other->integrators) owners += (owners.empty() ? "integrator " : ", ") + i;
        for (const std::string& f : other->filters) owners += std::string(owners.empty() ? "" : " or ") + "filter " + f;
        where = " (it applies to " + owners + ")";
      }
      throw py::type_error("render() got an unexpected keyword argument '" + keyword + "'" + where + " for integrator '" + integrator +
                           "' with filter '" + filter + "'; valid: " + keywords_of(valid));
    }
    if (value.is_none()) continue;  // None: the option's default
    if (spec->spec.type == OptionType::flag) {
      if (!py::isinstance<py::bool_>(value)) throw py::type_error(keyword + " is a flag: True or False");
      if (value.cast<bool>()) out.set(name);
      continue;
    }
    if (py::isinstance<py::bool_>(value)) throw py::type_error(keyword + " expects a " + option_type_name(spec->spec.type) + ", not a bool");
    out.set(name, py::str(value));
  }
  return out;
}

// Whether an option's default is shown as words rather than a value ("the scene's" maximum depth).
bool default_is_a_sentinel(const OptionSpec& spec) {
  if (spec.type != OptionType::integer && spec.type != OptionType::real) return false;
  try {
    parse_double_option(spec.name, spec.default_text, -1e300, 1e300);
    return false;
  } catch (const OptionError&) {
    return true;
  }
}

// The option values a render used, typed: passing them back as keyword arguments gives the same
// render. An option left at a default shown as words (the scene's depth) is None, which means "the
// default" when given back.
py::dict options_used(const RenderConfig& config) {
  py::dict out;
  auto add = [&](const SettingsSchema& schema, const std::any& settings) {
    const auto defaults = schema.values(schema.defaults());
    for (const auto& [name, text] : schema.values(settings)) {
      const OptionSpec* spec = schema.find(name);
      const py::str key(keyword_of(name));
      const bool at_default = std::find(defaults.begin(), defaults.end(), std::pair<std::string, std::string>(name, text)) != defaults.end();
      if (at_default && default_is_a_sentinel(*spec)) out[key] = py::none();
      else if (spec->type == OptionType::flag) out[key] = py::bool_(text == "on");
      else if (spec->type == OptionType::integer) out[key] = py::int_(std::stoll(text));
      else if (spec->type == OptionType::real) out[key] = py::float_(std::stod(text));
      else out[key] = py::str(text);
    }
  };
  add(integrator_registry().at(config.integrator).schema, config.settings);
  if (config.filter.active()) add(filter_registry().at(config.filter.name).schema, config.filter.settings);
  return out;
}

struct RenderRequest {
  RenderConfig config;
  RunLimit limit;
  RenderRunInfo run;
};

RenderRequest request_of(PyScene& scene, const std::string& integrator, const std::string& filter, const py::dict& options,
                         std::optional<uint32_t> spp, std::optional<double> time, uint64_t seed, int threads, const std::string& device) {
  if (spp && time) throw py::value_error("render: give spp or time, not both");
  // Ranges and the default spp of session/run_options.h, as on the command line (OptionError: ValueError).
  const RunLimit limit = run_limit(spp ? std::optional<double>(*spp) : std::nullopt, time, scene.file_spp());
  check_threads(threads);
  const OptionValues given = option_values(integrator, filter, options);
  RenderRequest r;
  r.config = configure_run(integrator, filter, given, seed, threads, device);
  r.limit = limit;
  const std::shared_ptr<const Scene> s = scene.scene();
  r.run = RenderRunInfo{scene.label(), s->camera.width, s->camera.height, max_segments_of(given, *s), ""};
  return r;
}

py::dict render(PyScene& scene, const std::string& integrator, const std::string& filter, const py::dict& options, std::optional<uint32_t> spp,
                std::optional<double> time, uint64_t seed, int threads, const std::string& device, const py::object& on_pass) {
  const RenderRequest request = request_of(scene, integrator, filter, options, spp, time, seed, threads, device);
  const std::shared_ptr<const Scene> current = scene.scene();
  std::unique_ptr<RenderSession> session;
  std::optional<py::error_already_set> raised;  // by the callback or a signal handler, other than Ctrl-C
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    session = std::make_unique<RenderSession>(current, scene.accel(current), request.config);
    session->run(request.limit, [&](const RenderProgress& p) {
      py::gil_scoped_acquire acquire;
      if (interrupted || raised) return;
      try {
        if (!on_pass.is_none()) on_pass(p.fraction, python_of(render_stats_object(session->stats(), request.run)));
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      } catch (py::error_already_set& e) {
        if (e.matches(PyExc_KeyboardInterrupt)) interrupted = true;
        else raised = std::move(e);
        session->cancel();
      }
    });
  }
  if (raised) throw *raised;
  RenderSnapshot snapshot;
  {
    py::gil_scoped_release release;
    snapshot = session->snapshot();
  }
  py::dict result;
  result["image"] = array_of(snapshot.mean);
  result["variance"] = array_of(snapshot.variance);
  py::dict aovs;
  for (const NamedImage& aov : snapshot.aovs) aovs[py::str(aov.name)] = array_of(aov.image);
  result["aovs"] = aovs;
  result["stats"] = python_of(render_stats_object(snapshot.stats, request.run));
  result["options"] = options_used(request.config);
  result["warnings"] = session->scene_warnings();
  result["interrupted"] = interrupted;
  return result;
}

// The same render in C++ alone, `repeats` times: seconds per render, for the bindings' overhead
// benchmark (bench/python/overhead.py). Includes what render() does in C++ (session, run, snapshot).
std::vector<double> native_render_seconds(PyScene& scene, const std::string& integrator, const std::string& filter, const py::dict& options,
                                          uint32_t spp, uint64_t seed, int threads, int repeats) {
  const RenderRequest request = request_of(scene, integrator, filter, options, spp, std::nullopt, seed, threads, "cpu");
  const std::shared_ptr<const Scene> current = scene.scene();
  py::gil_scoped_release release;
  const std::shared_ptr<const Accel> accel = scene.accel(current);
  std::vector<double> seconds;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    RenderSession session(current, accel, request.config);
    session.run(request.limit);
    const RenderSnapshot snapshot = session.snapshot();
    static_cast<void>(render_stats_object(snapshot.stats, request.run));
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return seconds;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("_render", &render, py::arg("scene"), py::arg("integrator"), py::arg("filter"), py::arg("options"), py::arg("spp"), py::arg("time"),
        py::arg("seed"), py::arg("threads"), py::arg("device"), py::arg("on_pass"),
        "The render behind pathspace.render(): a dict of image, variance, aovs, stats, options, warnings, interrupted.");
  m.def("_native_render_seconds", &native_render_seconds, py::arg("scene"), py::arg("integrator"), py::arg("filter"), py::arg("options"),
        py::arg("spp"), py::arg("seed"), py::arg("threads"), py::arg("repeats"),
        "Seconds per render of the same render done in C++ alone (the overhead benchmark's baseline).");
}

}  // namespace pathspace::python
