// The integrator and filter options exist in one place, the registry; these tests check that its
// three views agree: `pathspace render --help`, `pathspace info --integrators --json` and the
// generated tables of docs/options.md (`pathspace info --integrators --markdown`).
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_process.h"

namespace {

std::string run_binary(const std::string& args) { return pathspace::testing::run_pathspace(args).out; }

std::string read_file(const std::string& path) { return pathspace::testing::read_all(path); }

// Every option name of every integrator and filter in the JSON table.
std::set<std::string> json_options(const nlohmann::json& j) {
  std::set<std::string> names;
  for (const char* kind : {"integrators", "filters"})
    for (const auto& entry : j.at(kind))
      for (const auto& option : entry.at("options")) names.insert(option.at("name").get<std::string>());
  return names;
}

nlohmann::json registry_json() { return nlohmann::json::parse(run_binary("info --integrators --json")); }

TEST(RegistryDocs, EveryRegisteredOptionIsInRenderHelp) {
  const std::string help = run_binary("render --help");
  for (const std::string& name : json_options(registry_json()))
    EXPECT_NE(help.find("--" + name + " "), std::string::npos) << "--" << name << " is registered but not in render --help";
}

TEST(RegistryDocs, EveryIntegratorHasADescriptionAndOptionsHaveHelp) {
  const nlohmann::json j = registry_json();
  ASSERT_GE(j.at("integrators").size(), 5u);
  for (const char* kind : {"integrators", "filters"})
    for (const auto& entry : j.at(kind)) {
      EXPECT_FALSE(entry.at("description").get<std::string>().empty()) << entry.at("name");
      for (const auto& option : entry.at("options")) EXPECT_FALSE(option.at("help").get<std::string>().empty()) << option.at("name");
    }
}

TEST(RegistryDocs, IntegratorsInRenderHelpAreRegistered) {
  const nlohmann::json j = registry_json();
  const std::string help = run_binary("render --help");
  for (const auto& entry : j.at("integrators")) {
    const std::string name = entry.at("name").get<std::string>();
    EXPECT_NE(help.find("(--integrator " + name + ")"), std::string::npos) << name << " has no option group in --help";
  }
}

// docs/options.md holds the generated block verbatim: regenerate it with
// `pathspace info --integrators --markdown` after changing a registration.
TEST(RegistryDocs, OptionsDocHoldsTheGeneratedTables) {
  const std::string doc = read_file(PATHSPACE_SOURCE_DIR "/docs/options.md");
  const std::string generated = run_binary("info --integrators --markdown");
  ASSERT_FALSE(generated.empty());
  EXPECT_NE(doc.find(generated), std::string::npos)
      << "docs/options.md does not contain the output of `pathspace info --integrators --markdown`; paste it between the "
         "generated-block markers";
}

}  // namespace
