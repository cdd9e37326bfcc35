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
  const std::lock_guard<std::mutex> lock(logs_mutex());
  return files_;
}

void InputFileLog::add(const std::string& path, uint64_t hash) {
  for (const InputFile& f : files_)
    if (f.path == path) return;
  files_.push_back({path, hash});
}

void InputFileLog::note(const std::string& path, const std::string* bytes) {
  {
    const std::lock_guard<std::mutex> lock(logs_mutex());
    if (open_logs().empty()) return;
  }
  // A stream reader's file: its stored bytes, read here (outside the lock: this read notes nothing).
  const std::string stored = bytes ? std::string() : read_file_as_stored_unlogged(path);
  const std::string& b = bytes ? *bytes : stored;
  const uint64_t hash = fnv1a64(b.data(), b.size());
  const std::lock_guard<std::mutex> lock(logs_mutex());
  for (InputFileLog* log : open_logs()) log->add(path, hash);
}

}  // namespace pathspace
