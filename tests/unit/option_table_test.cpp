// Options as data (options/option_table.h, session/render_config.h):
//  - OptionTable parses integer, real, choice and flag options strictly: NaN, infinities,
//    overflow, wrap-around, values outside the range, trailing characters and empty text are
//    OptionErrors naming the option; defaults are read from the settings struct (shows_default for
//    sentinels); check() rules run on the finished settings;
//  - configure_render() refuses unknown options, options of another integrator or filter (naming
//    where they apply), and filters the integrator does not compose with; --max-depth reaches
//    every integrator's own field;
//  - every registered integrator and filter has a description and every option a help text, and
//    options of one name in several tables have the same contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pathspace/filters/filter_registry.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/options/option_table.h"
#include "pathspace/session/render_config.h"

namespace pathspace {
namespace {

enum class Mode { fast, exact };

struct TestSettings {
  int count = 7;
  uint32_t slots = 16;
  float ratio = 0.25f;
  double scale = 1.5;
  Mode mode = Mode::exact;
  bool enabled = true;
  bool extra = false;
  int depth = -1;  // sentinel: "the scene's"
};

OptionTable<TestSettings> test_table() {
  using S = TestSettings;
  OptionTable<S> t;
  t.number("count", &S::count, 1, 100, "How many");
  t.number("slots", &S::slots, 0, double(1u << 31), "A 32-bit field with a smaller range");
  t.number("ratio", &S::ratio, 0.0, 1.0, "A float in [0, 1]", "eq. 1");
  t.number("scale", &S::scale, 1e-3, 1e3, "A double");
  t.choice("mode", &S::mode, std::vector<std::pair<std::string, Mode>>{{"fast", Mode::fast}, {"exact", Mode::exact}}, "Which mode");
  t.flag("no-enabled", &S::enabled, false, "Switch it off");
  t.flag("extra", &S::extra, true, "Switch the extra on");
  t.number("depth", &S::depth, 1, 1024, "A limit").shows_default("the scene's");
  t.check([](const S& s) {
    if (s.extra && !s.enabled) throw OptionError("--extra needs it enabled (no --no-enabled)");
  });
  return t;
}

OptionValues values(std::initializer_list<std::pair<std::string, std::string>> items) {
  OptionValues v;
  for (const auto& [name, value] : items) v.set(name, value);
  return v;
}

const OptionSpec& spec(const std::vector<OptionSpec>& specs, const std::string& name) {
  for (const OptionSpec& s : specs)
    if (s.name == name) return s;
  throw Error("no option " + name);
}

// The OptionError message of applying {name: text}, or "" when it was accepted.
std::string error_of(const std::string& name, const std::string& text) {
  TestSettings s;
  try {
    test_table().apply(values({{name, text}}), &s);
  } catch (const OptionError& e) {
    return e.what();
  }
  return {};
}

TEST(OptionTable, DefaultsComeFromTheStruct) {
  const std::vector<OptionSpec> specs = test_table().specs();
  ASSERT_EQ(specs.size(), 8u);
  EXPECT_EQ(spec(specs, "count").type, OptionType::integer);
  EXPECT_EQ(spec(specs, "count").default_text, "7");
  EXPECT_EQ(spec(specs, "count").min, 1.0);
  EXPECT_EQ(spec(specs, "count").max, 100.0);
  EXPECT_EQ(spec(specs, "slots").type, OptionType::integer);
  EXPECT_EQ(spec(specs, "slots").default_text, "16");
  EXPECT_EQ(spec(specs, "ratio").type, OptionType::real);
  EXPECT_EQ(spec(specs, "ratio").default_text, "0.25");
  EXPECT_EQ(spec(specs, "ratio").paper, "eq. 1");
  EXPECT_EQ(spec(specs, "scale").default_text, "1.5");
  EXPECT_EQ(spec(specs, "mode").type, OptionType::choice);
  EXPECT_EQ(spec(specs, "mode").default_text, "exact");
  EXPECT_EQ(spec(specs, "mode").choices, (std::vector<std::string>{"fast", "exact"}));
  EXPECT_EQ(spec(specs, "no-enabled").type, OptionType::flag);
  EXPECT_EQ(spec(specs, "no-enabled").default_text, "off");
  EXPECT_EQ(spec(specs, "extra").default_text, "off");
  EXPECT_EQ(spec(specs, "depth").default_text, "the scene's") << "shows_default replaces the sentinel";
  EXPECT_EQ(spec(specs, "ratio").help, "A float in [0, 1]");

  // A float default is shown as the shortest text that reads back as the same float.
  struct F {
    float third = 2.f / 3.f;
  };
  OptionTable<F> f;
  f.number("third", &F::third, 0.0, 1.0, "two thirds");
  const std::string text = f.specs()[0].default_text;
  EXPECT_EQ(parse_float_option("third", text, 0.0, 1.0), 2.f / 3.f) << text;
}

TEST(OptionTable, ParsesEveryType) {
  TestSettings s;
  test_table().apply(values({{"count", "42"}, {"slots", "2147483648"}, {"ratio", "0.5"}, {"scale", "2e2"}, {"mode", "fast"},
                             {"extra", ""}, {"depth", "+5"}, {"not-ours", "whatever"}}),
                     &s);
  EXPECT_EQ(s.count, 42);
  EXPECT_EQ(s.slots, 2147483648u);
  EXPECT_EQ(s.ratio, 0.5f);
  EXPECT_EQ(s.scale, 200.0);
  EXPECT_EQ(s.mode, Mode::fast);
  EXPECT_TRUE(s.extra);
  EXPECT_TRUE(s.enabled);
  EXPECT_EQ(s.depth, 5);
  test_table().apply(values({{"no-enabled", ""}}), &(s = TestSettings{}));
  EXPECT_FALSE(s.enabled);
  // Nothing given: the struct stays as it was.
  TestSettings untouched;
  untouched.count = 99;
  test_table().apply(OptionValues{}, &untouched);
  EXPECT_EQ(untouched.count, 99);
}

TEST(OptionTable, BadValuesAreOptionErrorsNamingTheOption) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"ratio", "nan"},         {"ratio", "NaN"},        {"ratio", "inf"},  {"scale", "-inf"},     {"scale", "infinity"},
      {"ratio", "1e999"},       {"scale", "1e999"},      {"scale", "-1e999"},
      {"slots", "4294967297"},  // 2^32 + 1: would wrap to 1 in a 32-bit field
      {"slots", "2147483649"},  // above the maximum 2^31
      {"slots", "99999999999999999999999"},  // beyond 64 bits
      {"count", "-1"},          {"count", "0"},          {"count", "101"},  {"ratio", "-0.5"},     {"ratio", "1.5"},
      {"scale", "0"},           {"count", "3x"},         {"count", "3.5"},  {"count", "1e2"},      {"count", " 3"},
      {"ratio", "0.5x"},        {"ratio", "0.5 "},       {"count", ""},     {"ratio", ""},         {"scale", ""},
      {"mode", "slow"},         {"mode", ""},            {"mode", "FAST"},  {"depth", "0"},        {"count", "0x10"},
  };
  for (const auto& [name, text] : bad) {
    const std::string message = error_of(name, text);
    EXPECT_NE(message.find("--" + name), std::string::npos) << name << " '" << text << "': " << (message.empty() ? "accepted" : message);
  }
  EXPECT_NE(error_of("mode", "slow").find("fast, exact"), std::string::npos) << "the choices are listed";
  EXPECT_NE(error_of("count", "101").find("between 1 and 100"), std::string::npos) << error_of("count", "101");
  // The edges of the ranges are accepted.
  for (const auto& [name, text] :
       std::vector<std::pair<std::string, std::string>>{{"count", "1"}, {"count", "100"}, {"slots", "0"}, {"slots", "2147483648"},
                                                        {"ratio", "0"}, {"ratio", "1"}, {"scale", "1e-3"}, {"scale", "1000"}})
    EXPECT_EQ(error_of(name, text), "") << name << " " << text;
}

TEST(OptionTable, CheckRulesRunOnTheFinishedSettings) {
  TestSettings s;
  EXPECT_THROW(test_table().apply(values({{"extra", ""}, {"no-enabled", ""}}), &s), OptionError);
  EXPECT_NO_THROW(test_table().apply(values({{"extra", ""}}), &(s = TestSettings{})));
  // The rule sees options given in any order.
  EXPECT_THROW(test_table().apply(values({{"no-enabled", ""}, {"extra", ""}}), &(s = TestSettings{})), OptionError);
  // Through the registry: pt's rule and the hashed filter's rule.
  EXPECT_THROW(configure_render("pt", "none", values({{"no-nee", ""}, {"no-bsdf-sampling", ""}})), OptionError);
  EXPECT_THROW(configure_render("pt", "hashed", values({{"psf-neighbours", ""}, {"psf-multi-level", ""}})), OptionError);
}

TEST(OptionTable, AnOptionIsDefinedOnce) {
  OptionTable<TestSettings> t;
  t.number("count", &TestSettings::count, 1, 100, "How many");
  EXPECT_THROW(t.number("count", &TestSettings::count, 1, 10, "Again"), OptionError);
}

TEST(OptionTable, SameContract) {
  const std::vector<OptionSpec> specs = test_table().specs();
  OptionSpec a = spec(specs, "count");
  OptionSpec b = a;
  b.help = "other words";
  b.paper = "elsewhere";
  EXPECT_TRUE(a.same_contract(b)) << "help and paper may differ";
  for (int change = 0; change < 5; ++change) {
    OptionSpec c = a;
    if (change == 0) c.max = 1000;
    if (change == 1) c.min = 0;
    if (change == 2) c.default_text = "8";
    if (change == 3) c.type = OptionType::real;
    if (change == 4) c.name = "counts";
    EXPECT_FALSE(a.same_contract(c)) << "change " << change;
  }
  OptionSpec m = spec(specs, "mode");
  m.choices.push_back("slow");
  EXPECT_FALSE(spec(specs, "mode").same_contract(m));
}

std::string configure_error(const std::string& integrator, const std::string& filter, const OptionValues& given) {
  try {
    configure_render(integrator, filter, given);
  } catch (const OptionError& e) {
    return e.what();
  }
  return {};
}

TEST(ConfigureRender, UnknownOptionIntegratorOrFilter) {
  const std::string unknown = configure_error("pt", "none", values({{"no-such-option", "1"}}));
  EXPECT_NE(unknown.find("unknown option --no-such-option"), std::string::npos) << unknown;
  const std::string integrator = configure_error("no-such-integrator", "none", {});
  EXPECT_NE(integrator.find("no-such-integrator"), std::string::npos) << integrator;
  EXPECT_NE(integrator.find("pt"), std::string::npos) << "the available ones are listed: " << integrator;
  const std::string filter = configure_error("pt", "no-such-filter", {});
  EXPECT_NE(filter.find("no-such-filter"), std::string::npos) << filter;
}

TEST(ConfigureRender, OptionOfAnotherIntegratorNamesIt) {
  const std::string pclt = configure_error("lt", "none", values({{"pclt-alpha", "0.5"}}));
  EXPECT_NE(pclt.find("--pclt-alpha applies to --integrator pclt"), std::string::npos) << pclt;
  const std::string sppm = configure_error("pt", "none", values({{"sppm-alpha", "0.5"}}));
  EXPECT_NE(sppm.find("--sppm-alpha applies to --integrator sppm"), std::string::npos) << sppm;
  // A filter option without the filter.
  const std::string psf = configure_error("pt", "none", values({{"psf-scale", "2"}}));
  EXPECT_NE(psf.find("--psf-scale applies to --filter hashed"), std::string::npos) << psf;
  // With it, it reaches the filter's settings.
  const RenderConfig c = configure_render("pt", "hashed", values({{"psf-scale", "2"}}));
  EXPECT_EQ(c.filter.name, "hashed");
  EXPECT_EQ(std::any_cast<HashedFilterSettings>(c.filter.settings).key.psf_scale, 2.f);
  // A bad value through the registry is an OptionError naming the option.
  const std::string range = configure_error("pt", "none", values({{"max-depth", "0"}}));
  EXPECT_NE(range.find("--max-depth"), std::string::npos) << range;
}

TEST(ConfigureRender, FilterThatDoesNotCompose) {
  const std::string lt = configure_error("lt", "hashed", {});
  EXPECT_NE(lt.find("--filter hashed applies to --integrator pt"), std::string::npos) << lt;
  EXPECT_NE(lt.find("not lt"), std::string::npos) << lt;
  for (const char* integrator : {"lt", "bpt", "sppm", "pclt"}) EXPECT_THROW(check_composition(integrator, "hashed"), OptionError) << integrator;
  EXPECT_NO_THROW(check_composition("pt", "hashed"));
  EXPECT_NO_THROW(check_composition("pt", "passthrough"));
  for (const IntegratorEntry& e : integrator_registry().entries()) EXPECT_NO_THROW(check_composition(e.name, "none")) << e.name;
}

// --max-depth is one option in five tables; each stores it in its own struct's field.
TEST(ConfigureRender, MaxDepthReachesEveryIntegratorsOwnField) {
  const OptionValues depth = values({{"max-depth", "5"}});
  EXPECT_EQ(std::any_cast<PtSettings>(configure_render("pt", "none", depth).settings).max_segments, 5);
  EXPECT_EQ(std::any_cast<LtSettings>(configure_render("lt", "none", depth).settings).max_segments, 5);
  EXPECT_EQ(std::any_cast<BptSettings>(configure_render("bpt", "none", depth).settings).max_segments, 5);
  EXPECT_EQ(std::any_cast<SppmSettings>(configure_render("sppm", "none", depth).settings).max_segments, 5);
  EXPECT_EQ(std::any_cast<PcltSettings>(configure_render("pclt", "none", depth).settings).max_segments, 5);
  // Not given: each struct's default (the scene's limit).
  EXPECT_EQ(std::any_cast<PtSettings>(configure_render("pt", "none", {}).settings).max_segments, -1);
  EXPECT_EQ(std::any_cast<PcltSettings>(configure_render("pclt", "none", {}).settings).max_segments, -1);
  // And the other options of one integrator do not leak into it.
  const RenderConfig sppm = configure_render("sppm", "none", values({{"max-depth", "5"}, {"sppm-alpha", "0.5"}}));
  EXPECT_EQ(std::any_cast<SppmSettings>(sppm.settings).alpha, 0.5f);
  EXPECT_EQ(std::any_cast<SppmSettings>(sppm.settings).photons, SppmSettings{}.photons);
}

TEST(Registries, EveryEntryAndOptionIsDescribed) {
  std::vector<std::string> integrators = integrator_registry().names();
  for (const char* name : {"pt", "lt", "bpt", "sppm", "pclt"})
    EXPECT_NE(std::find(integrators.begin(), integrators.end(), name), integrators.end()) << name;
  const std::vector<std::string> filters = filter_registry().names();
  for (const char* name : {"hashed", "passthrough"}) EXPECT_NE(std::find(filters.begin(), filters.end(), name), filters.end()) << name;

  for (const IntegratorEntry& e : integrator_registry().entries()) {
    EXPECT_FALSE(e.description.empty()) << "integrator " << e.name;
    EXPECT_TRUE(e.create) << "integrator " << e.name;
    ASSERT_TRUE(e.schema.defaults) << e.name;
    EXPECT_TRUE(e.schema.defaults().has_value()) << e.name;
    for (const OptionSpec& o : e.schema.options) EXPECT_FALSE(o.help.empty()) << "--" << o.name << " of " << e.name;
  }
  for (const FilterEntry& e : filter_registry().entries()) {
    EXPECT_FALSE(e.description.empty()) << "filter " << e.name;
    EXPECT_TRUE(e.create) << "filter " << e.name;
    for (const OptionSpec& o : e.schema.options) EXPECT_FALSE(o.help.empty()) << "--" << o.name << " of filter " << e.name;
  }
}

// Options of one name in several tables (--max-depth, --mis, ...) mean the same to the user.
TEST(Registries, SharedOptionsHaveOneContract) {
  std::map<std::string, std::vector<std::pair<std::string, OptionSpec>>> by_name;
  for (const IntegratorEntry& e : integrator_registry().entries())
    for (const OptionSpec& o : e.schema.options) by_name[o.name].push_back({"integrator " + e.name, o});
  for (const FilterEntry& e : filter_registry().entries())
    for (const OptionSpec& o : e.schema.options) by_name[o.name].push_back({"filter " + e.name, o});
  ASSERT_GE(by_name["max-depth"].size(), 5u);
  size_t shared = 0;
  for (const auto& [name, owners] : by_name) {
    shared += owners.size() > 1;
    for (size_t i = 1; i < owners.size(); ++i)
      EXPECT_TRUE(owners[0].second.same_contract(owners[i].second))
          << "--" << name << ": " << owners[0].first << " (" << option_type_name(owners[0].second.type) << ", default "
          << owners[0].second.default_text << ", " << owners[0].second.min << ".." << owners[0].second.max << ") vs " << owners[i].first
          << " (" << option_type_name(owners[i].second.type) << ", default " << owners[i].second.default_text << ", "
          << owners[i].second.min << ".." << owners[i].second.max << ")";
  }
  EXPECT_GE(shared, 1u);
}

}  // namespace
}  // namespace pathspace
