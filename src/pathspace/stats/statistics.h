// Statistics: named, typed values that integrators and filters report (counters, ratios, timings,
// byte sizes, histograms), instead of human-readable text. The progress line, `--stats` JSON, the
// studies and the tests read the same values; asking for one that was not reported is an error.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pathspace {

enum class StatKind : uint8_t {
  counter,    // a count of events or items (integer)
  value,      // a plain number (e.g. a radius in scene units)
  ratio,      // a fraction, 0..1 unless it says otherwise
  seconds,    // a duration
  bytes,      // a memory size
  histogram,  // counts per bin
  text,       // a setting worth printing next to the numbers (e.g. "chained")
};

const char* stat_kind_name(StatKind kind);

struct Statistic {
  std::string name;  // "<owner>.<what>", e.g. "pclt.memory_bytes"
  StatKind kind = StatKind::value;
  double number = 0.0;         // every kind but histogram and text
  std::vector<uint64_t> bins;  // histogram
  std::string text;            // text
  std::string help;            // one short phrase, for listings
};

class Statistics {
 public:
  void counter(std::string name, uint64_t count, std::string help = {});
  void value(std::string name, double v, std::string help = {});
  void ratio(std::string name, double r, std::string help = {});
  void seconds(std::string name, double s, std::string help = {});
  void bytes(std::string name, uint64_t b, std::string help = {});
  void histogram(std::string name, std::vector<uint64_t> bins, std::string help = {});
  void text(std::string name, std::string t, std::string help = {});

  // Null when not reported.
  const Statistic* find(std::string_view name) const;
  // Throws pathspace::Error naming the statistic and what was reported instead.
  const Statistic& at(std::string_view name) const;
  double number(std::string_view name) const { return at(name).number; }

  const std::vector<Statistic>& all() const { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  void add(Statistic s);
  std::vector<Statistic> items_;  // in report order; names unique
};

// One line per statistic ("pclt.memory_bytes  1.23 MiB"), for the CLI's summary.
std::string format_statistics(const Statistics& stats);

}  // namespace pathspace
