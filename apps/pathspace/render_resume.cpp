#include "render_resume.h"

#include <cstdlib>
#include <map>

#include <fmt/format.h>

#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

namespace {

// The option's name as stored: the long name without dashes, or the positional's name.
std::string stored_name(const CLI::Option& opt) {
  if (!opt.get_lnames().empty()) return opt.get_lnames().front();
  return opt.get_name(true);
}

bool affects_image(const CLI::Option& opt) {
  return opt.get_group() != kRunOptionsGroup && stored_name(opt) != "help";
}

bool is_flag(const CLI::Option& opt) { return !opt.get_positional() && opt.get_expected_max() == 0; }

// "4.0" and "4" are one value; so are "0,1,6.8" and "0, 1.0, 6.8".
std::string normalised(const std::string& text) {
  auto number = [](const std::string& t, std::string* out) {
    const char* begin = t.c_str();
    while (*begin == ' ') ++begin;
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0') return false;
    *out = fmt::format("{:.9g}", v);
    return true;
  };
  std::string single;
  if (number(text, &single)) return single;
  std::string joined;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    std::string part;
    if (!number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), &part)) return text;
    joined += (joined.empty() ? "" : ",") + part;
    if (comma == std::string::npos) return joined;
    start = comma + 1;
  }
}

void append_tokens(const GivenOption& g, bool flag, bool positional, std::vector<std::string>* args) {
  if (positional) {
    args->insert(args->end(), g.values.begin(), g.values.end());
    return;
  }
  if (flag) {
    args->push_back("--" + g.name);
    return;
  }
  for (const std::string& v : g.values) {
    args->push_back("--" + g.name);
    args->push_back(v);
  }
}

}  // namespace

std::vector<GivenOption> given_image_options(const CLI::App& cmd) {
  std::vector<GivenOption> out;
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt->count() == 0 || !affects_image(*opt)) continue;
    GivenOption g{stored_name(*opt), {}};
    if (!is_flag(*opt)) g.values = opt->results();
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<std::string> resume_arguments(const CLI::App& cmd, const std::vector<GivenOption>& from_checkpoint) {
  std::vector<std::string> args = {"render"};
  std::map<std::string, const CLI::Option*> by_name;
  for (const CLI::Option* opt : cmd.get_options()) by_name[stored_name(*opt)] = opt;
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt->count() == 0 || stored_name(*opt) == "help") continue;
    append_tokens({stored_name(*opt), is_flag(*opt) ? std::vector<std::string>{} : opt->results()}, is_flag(*opt), opt->get_positional(), &args);
  }
  for (const GivenOption& g : from_checkpoint) {
    const auto it = by_name.find(g.name);
    if (it == by_name.end())
      throw UsageError("--resume: the checkpoint was made with --" + g.name + ", which this pathspace does not know");
    if (it->second->count() > 0 || !affects_image(*it->second)) continue;
    append_tokens(g, is_flag(*it->second), it->second->get_positional(), &args);
  }
  return args;
}

std::vector<std::pair<std::string, std::string>> canonical_image_options(const CLI::App& cmd, const std::string& scene_key,
                                                                         const RenderConfig& config) {
  std::vector<std::pair<std::string, std::string>> out = {{"scene", scene_key}};
  const IntegratorEntry& integrator = integrator_registry().at(config.integrator);
  const FilterEntry* filter = config.filter.active() ? &filter_registry().at(config.filter.name) : nullptr;
  for (const CLI::Option* opt : cmd.get_options()) {
    const std::string name = stored_name(*opt);
    if (!affects_image(*opt) || opt->get_positional()) continue;
    if (integrator.schema.find(name) || (filter && filter->schema.find(name))) continue;  // below, with their values
    bool registry_option = false;  // another integrator's or filter's option: not given, not part of this render
    for (const IntegratorEntry& e : integrator_registry().entries()) registry_option = registry_option || e.schema.find(name);
    for (const FilterEntry& e : filter_registry().entries()) registry_option = registry_option || e.schema.find(name);
    if (registry_option) continue;
    // As given, else the option's default where it shows one (--integrator pt equals no --integrator).
    std::string value;
    if (opt->count() > 0 && is_flag(*opt)) value = "on";
    else if (opt->count() > 0)
      for (const std::string& v : opt->results()) value += (value.empty() ? "" : " ") + normalised(v);
    else if (!is_flag(*opt))
      value = normalised(opt->get_default_str());
    out.emplace_back(name, value);
  }
  for (const auto& [name, value] : integrator.schema.values(config.settings)) out.emplace_back(name, value);
  if (filter)
    for (const auto& [name, value] : filter->schema.values(config.filter.settings)) out.emplace_back(name, value);
  return out;
}

void check_resume_options(const CheckpointInfo& checkpoint, const std::vector<std::pair<std::string, std::string>>& now) {
  auto shown = [](const std::string& v) { return v.empty() ? std::string("not given") : "'" + v + "'"; };
  std::map<std::string, std::string> then(checkpoint.options.begin(), checkpoint.options.end());
  const auto scene = then.find("scene");
  if (scene == then.end() || scene->second != now.front().second)
    throw UsageError("--resume: the checkpoint was made for the scene " + checkpoint.scene + " (" +
                         (scene == then.end() ? std::string("?") : scene->second) + "), this render's scene is " + now.front().second,
                     "resume with the same scene; a scene file and every file it reads (includes, meshes, textures) must have the same content");
  for (const auto& [name, value] : now) {
    const auto it = then.find(name);
    const std::string before = it == then.end() ? std::string() : it->second;
    if (before != value)
      throw UsageError(fmt::format("--resume: --{} was {} in the checkpoint, this render gives {}", name, shown(before), shown(value)),
                       "options that change the image cannot change on resume; leave them out to keep the checkpoint's");
    then.erase(name);
  }
  if (!then.empty())
    throw UsageError("--resume: the checkpoint has --" + then.begin()->first + " '" + then.begin()->second + "', which this render does not have",
                     "options that change the image cannot change on resume");
}

}  // namespace pathspace::cli
