// Options that several integrators share with one contract (name, range, default), defined once.
#pragma once

#include "pathspace/options/option_table.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/sampling/mis.h"

namespace pathspace {

// --max-depth: the path length limit in segments, camera ray included; -1 in the settings means
// the scene's own limit.
template <typename Settings, typename Field>
void add_max_depth_option(OptionTable<Settings>& table, Field field) {
  table.number("max-depth", field, 1, 1024, "Path length limit in segments, camera ray included").shows_default("the scene's");
}

// --mis: the multiple importance sampling heuristic (Veach 1997, ch. 9).
template <typename Settings, typename Field>
void add_mis_option(OptionTable<Settings>& table, Field field) {
  table.choice("mis", field, std::vector<std::pair<std::string, MisHeuristic>>{{"power", MisHeuristic::power}, {"balance", MisHeuristic::balance}},
               "MIS heuristic", "Veach 1997, sec. 9.2");
}

}  // namespace pathspace
