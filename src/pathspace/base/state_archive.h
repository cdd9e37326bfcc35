// StateWriter / StateReader: the byte format of a render's serializable state (RenderSession:
// pass index, seed, film sums, each integrator's and filter's own state), so that a checkpoint is a
// thin layer that writes these bytes to a file. Sections are named and sized; reading checks every
// name and size, so a state from another integrator or build fails with a clear error instead of
// restoring garbage. Values are raw bytes of trivially copyable types (same machine and build).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace pathspace {

class StateWriter {
 public:
  StateWriter();
  // Room for this many bytes in all, so that large sections are copied once.
  void reserve(size_t bytes) { bytes_.reserve(bytes); }
  void put_bytes(std::string_view key, const void* data, size_t size);
  template <typename T>
  void put(std::string_view key, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_bytes(key, &value, sizeof(T));
  }
  template <typename T>
  void put_vector(std::string_view key, const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_bytes(key, values.data(), values.size() * sizeof(T));
  }
  void put_string(std::string_view key, std::string_view text) { put_bytes(key, text.data(), text.size()); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

class StateReader {
 public:
  // Throws pathspace::Error when the bytes do not start like a state.
  explicit StateReader(const std::vector<uint8_t>& bytes);
  // The next section must be `key`; returns its payload. Throws pathspace::Error otherwise.
  std::string_view next(std::string_view key);
  template <typename T>
  void get(std::string_view key, T* value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::string_view payload = next(key);
    check_size(key, payload.size(), sizeof(T));
    std::memcpy(value, payload.data(), sizeof(T));
  }
  template <typename T>
  void get_vector(std::string_view key, std::vector<T>* values, size_t expected_count) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::string_view payload = next(key);
    check_size(key, payload.size(), expected_count * sizeof(T));
    values->resize(expected_count);
    if (expected_count) std::memcpy(values->data(), payload.data(), payload.size());
  }
  std::string get_string(std::string_view key) { return std::string(next(key)); }
  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  static void check_size(std::string_view key, size_t got, size_t expected);
  const std::vector<uint8_t>& bytes_;
  size_t pos_ = 0;
};

}  // namespace pathspace
