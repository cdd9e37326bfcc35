// Registry<Entry>: named entries (integrators, filters) that register themselves at start-up with a
// static Registrar in their own source file, so adding one touches no list, if-chain or CLI file.
// Entries are listed by name, whatever order static initialisation ran in.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "pathspace/options/option_spec.h"

namespace pathspace {

template <typename Entry>
class Registry {
 public:
  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  void add(Entry entry) {
    if (find(entry.name)) throw Error(kind_ + " '" + entry.name + "' is registered twice");
    const auto at = std::lower_bound(entries_.begin(), entries_.end(), entry.name,
                                     [](const Entry& e, const std::string& n) { return e.name < n; });
    entries_.insert(at, std::move(entry));
  }
  // Removes an entry (tests that register a toy entry clean up after themselves).
  void remove(const std::string& name) {
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; }),
                   entries_.end());
  }

  const Entry* find(const std::string& name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  // Throws OptionError listing the available names.
  const Entry& at(const std::string& name) const {
    if (const Entry* e = find(name)) return *e;
    throw OptionError("unknown " + kind_ + " '" + name + "' (available: " + joined_names() + ")");
  }

  const std::vector<Entry>& entries() const { return entries_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }
  std::string joined_names() const {
    std::string out;
    for (const Entry& e : entries_) out += (out.empty() ? "" : ", ") + e.name;
    return out;
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;  // sorted by name
};

}  // namespace pathspace
