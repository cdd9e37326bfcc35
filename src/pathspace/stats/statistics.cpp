#include "pathspace/stats/statistics.h"

#include <algorithm>
#include <cstdio>

#include "pathspace/base/error.h"

namespace pathspace {

const char* stat_kind_name(StatKind kind) {
  switch (kind) {
    case StatKind::counter: return "counter";
    case StatKind::value: return "value";
    case StatKind::ratio: return "ratio";
    case StatKind::seconds: return "seconds";
    case StatKind::bytes: return "bytes";
    case StatKind::histogram: return "histogram";
    case StatKind::text: return "text";
  }
  return "?";
}

void Statistics::add(Statistic s) {
  for (Statistic& existing : items_)
    if (existing.name == s.name) {
      existing = std::move(s);
      return;
    }
  items_.push_back(std::move(s));
}

void Statistics::counter(std::string name, uint64_t count, std::string help) {
  add({std::move(name), StatKind::counter, double(count), {}, {}, std::move(help)});
}
void Statistics::value(std::string name, double v, std::string help) {
  add({std::move(name), StatKind::value, v, {}, {}, std::move(help)});
}
void Statistics::ratio(std::string name, double r, std::string help) {
  add({std::move(name), StatKind::ratio, r, {}, {}, std::move(help)});
}
void Statistics::seconds(std::string name, double s, std::string help) {
  add({std::move(name), StatKind::seconds, s, {}, {}, std::move(help)});
}
void Statistics::bytes(std::string name, uint64_t b, std::string help) {
  add({std::move(name), StatKind::bytes, double(b), {}, {}, std::move(help)});
}
void Statistics::histogram(std::string name, std::vector<uint64_t> bins, std::string help) {
  Statistic s{std::move(name), StatKind::histogram, 0.0, std::move(bins), {}, std::move(help)};
  for (uint64_t b : s.bins) s.number += double(b);
  add(std::move(s));
}
void Statistics::text(std::string name, std::string t, std::string help) {
  add({std::move(name), StatKind::text, 0.0, {}, std::move(t), std::move(help)});
}

const Statistic* Statistics::find(std::string_view name) const {
  for (const Statistic& s : items_)
    if (s.name == name) return &s;
  return nullptr;
}

const Statistic& Statistics::at(std::string_view name) const {
  if (const Statistic* s = find(name)) return *s;
  std::string reported;
  for (const Statistic& s : items_) reported += (reported.empty() ? "" : ", ") + s.name;
  throw Error("statistic '" + std::string(name) + "' was not reported (reported: " + (reported.empty() ? "none" : reported) + ")");
}

std::string format_statistics(const Statistics& stats) {
  size_t width = 0;
  for (const Statistic& s : stats.all()) width = std::max(width, s.name.size());
  std::string out;
  char buf[128];
  for (const Statistic& s : stats.all()) {
    switch (s.kind) {
      case StatKind::counter: std::snprintf(buf, sizeof(buf), "%.0f", s.number); break;
      case StatKind::value: std::snprintf(buf, sizeof(buf), "%.5g", s.number); break;
      case StatKind::ratio: std::snprintf(buf, sizeof(buf), "%.2f%%", 100.0 * s.number); break;
      case StatKind::seconds: std::snprintf(buf, sizeof(buf), "%.3f s", s.number); break;
      case StatKind::bytes:
        if (s.number >= 1024.0 * 1024.0)
          std::snprintf(buf, sizeof(buf), "%.2f MiB", s.number / (1024.0 * 1024.0));
        else
          std::snprintf(buf, sizeof(buf), "%.0f bytes", s.number);
        break;
      case StatKind::histogram: std::snprintf(buf, sizeof(buf), "%zu bins, %.0f total", s.bins.size(), s.number); break;
      case StatKind::text: std::snprintf(buf, sizeof(buf), "%s", s.text.c_str()); break;
    }
    out += "  " + s.name + std::string(width - s.name.size() + 2, ' ') + buf;
    if (!s.help.empty()) out += "  (" + s.help + ")";
    out += '\n';
  }
  return out;
}

}  // namespace pathspace
