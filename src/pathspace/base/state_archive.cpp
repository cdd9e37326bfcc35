#include "pathspace/base/state_archive.h"

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

constexpr char kMagic[8] = {'P', 'S', 'S', 'T', 'A', 'T', 'E', '1'};

// resize + memcpy: GCC 12 warns falsely (-Wstringop-overflow) about vector::insert of a range here.
void append(std::vector<uint8_t>* out, const void* data, size_t size) {
  if (size == 0) return;
  const size_t at = out->size();
  out->resize(at + size);
  std::memcpy(out->data() + at, data, size);
}

template <typename T>
void append(std::vector<uint8_t>* out, const T& v) {
  append(out, &v, sizeof(T));
}

}  // namespace

StateWriter::StateWriter() { append(&bytes_, kMagic, sizeof(kMagic)); }

void StateWriter::put_bytes(std::string_view key, const void* data, size_t size) {
  append(&bytes_, uint32_t(key.size()));
  append(&bytes_, key.data(), key.size());
  append(&bytes_, uint64_t(size));
  append(&bytes_, data, size);
}

StateReader::StateReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw Error("render state: not a pathspace render state (bad header)");
  pos_ = sizeof(kMagic);
}

std::string_view StateReader::next(std::string_view key) {
  auto fail = [&](const std::string& why) { throw Error("render state: section '" + std::string(key) + "': " + why); };
  uint32_t key_size = 0;
  uint64_t size = 0;
  if (bytes_.size() - pos_ < sizeof(key_size)) fail("truncated");
  std::memcpy(&key_size, bytes_.data() + pos_, sizeof(key_size));
  pos_ += sizeof(key_size);
  if (bytes_.size() - pos_ < uint64_t(key_size) + sizeof(size)) fail("truncated");
  const std::string_view found(reinterpret_cast<const char*>(bytes_.data() + pos_), key_size);
  if (found != key) fail("found '" + std::string(found) + "' instead");
  pos_ += key_size;
  std::memcpy(&size, bytes_.data() + pos_, sizeof(size));
  pos_ += sizeof(size);
  if (bytes_.size() - pos_ < size) fail("truncated");
  const std::string_view payload(reinterpret_cast<const char*>(bytes_.data() + pos_), size);
  pos_ += size;
  return payload;
}

void StateReader::check_size(std::string_view key, size_t got, size_t expected) {
  if (got != expected)
    throw Error("render state: section '" + std::string(key) + "' has " + std::to_string(got) + " bytes, expected " +
                std::to_string(expected));
}

}  // namespace pathspace
