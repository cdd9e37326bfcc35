// Escaping text for HTML and SVG (XML) markup: the page writer (html_report.h) and the plots
// (svg_plot.h) share it, so every text that reaches a page is escaped the same way.
#pragma once

#include <string>

namespace pathspace::study {

// &, <, > and " as entities; everything else unchanged (UTF-8 passes through).
std::string escape_markup(const std::string& text);

}  // namespace pathspace::study
