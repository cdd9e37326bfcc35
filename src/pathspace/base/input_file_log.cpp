#include "pathspace/base/input_file_log.h"

#include <algorithm>
#include <mutex>

#include "pathspace/base/fnv1a.h"
#include "pathspace/base/regular_file.h"

namespace pathspace {

namespace {

std::mutex& logs_mutex() {
  static std::mutex m;
  return m;
}
std::vector<InputFileLog*>& open_logs() {
  static std::vector<InputFileLog*> logs;
  return logs;
}

}  // namespace

InputFileLog::InputFileLog() {
  const std::lock_guard<std::mutex> lock(logs_mutex());
  open_logs().push_back(this);
}

InputFileLog::~InputFileLog() {
  const std::lock_guard<std::mutex> lock(logs_mutex());
  auto& logs = open_logs();
  logs.erase(std::remove(logs.begin(), logs.end(), this), logs.end());
}

std::vector<InputFile> InputFileLog::files() const {
  std::vector<Entry> entries;
  {
    const std::lock_guard<std::mutex> lock(logs_mutex());
    entries = entries_;
  }
  std::vector<InputFile> files;
  for (const Entry& e : entries) {
    if (e.fnv1a64) {
      files.push_back({e.path, *e.fnv1a64});
      continue;
    }
    const std::string bytes = read_file_as_stored_unlogged(e.path);  // a stream reader's file
    files.push_back({e.path, fnv1a64(bytes.data(), bytes.size())});
  }
  return files;
}

void InputFileLog::add(const std::string& path, std::optional<uint64_t> hash) {
  for (Entry& e : entries_)
    if (e.path == path) {
      if (!e.fnv1a64) e.fnv1a64 = hash;
      return;
    }
  entries_.push_back({path, hash});
}

void InputFileLog::note(const std::string& path, const std::string* bytes) {
  {
    const std::lock_guard<std::mutex> lock(logs_mutex());
    if (open_logs().empty()) return;  // no log open: no fingerprint to take
  }
  const std::optional<uint64_t> hash = bytes ? std::optional<uint64_t>(fnv1a64(bytes->data(), bytes->size())) : std::nullopt;
  const std::lock_guard<std::mutex> lock(logs_mutex());
  for (InputFileLog* log : open_logs()) log->add(path, hash);
}

}  // namespace pathspace
