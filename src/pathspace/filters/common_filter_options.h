// Options that several path space filters share with one contract (name, range, meaning), defined once.
#pragma once

#include "pathspace/options/option_table.h"

namespace pathspace {

// --psf-aa-paths: extra camera paths per pixel and pass that end at their first filtered vertex and
// take its value from the filter (FilterNeeds::query_paths): anti-aliasing for the price of a
// primary ray and a query, not a path (Keller, Dahm, Binder 2014, sec. 3, fig. 7).
template <typename Settings, typename Field>
void add_aa_paths_option(OptionTable<Settings>& table, Field field) {
  table.number("psf-aa-paths", field, 0, 64,
               "Extra camera paths per pixel and pass that only query the filtered vertices (anti-aliasing); empty queries are not counted",
               "2014 paper, sec. 3, fig. 7");
}

}  // namespace pathspace
