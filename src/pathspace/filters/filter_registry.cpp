#include "pathspace/filters/filter_registry.h"

namespace pathspace {

Registry<FilterEntry>& filter_registry() {
  static Registry<FilterEntry> registry("filter");
  return registry;
}

std::unique_ptr<PathSpaceFilter> make_filter(const FilterChoice& choice, const FilterContext& context) {
  if (!choice.active()) return nullptr;
  return filter_registry().at(choice.name).create(context, choice.settings);
}

namespace {

struct NoSettings {};

const FilterRegistrar kPassthrough{make_filter_entry<NoSettings>(
    "passthrough", "every vertex keeps its own contribution: plain PT through the filter's buffers (tests)", "",
    OptionTable<NoSettings>(),
    [](const FilterContext&, const NoSettings&) -> std::unique_ptr<PathSpaceFilter> { return std::make_unique<PassthroughFilter>(); })};

}  // namespace

}  // namespace pathspace
