// The checkpoint file format (checkpoint/checkpoint_file.h): the header survives a round trip; every
// truncation, every single-bit flip, trailing bytes and another format version are refused with a
// pathspace::Error naming the file; a bad write leaves the previous file in place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/checkpoint/checkpoint_file.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

CheckpointInfo sample_info() {
  CheckpointInfo info;
  info.scene = "scenes/room.pbrt";
  info.scene_hash = "fnv1a64:0123456789abcdef";
  info.integrator = "sppm";
  info.filter = "none";
  info.width = 64;
  info.height = 48;
  info.seed = 42;
  info.options = {{"scene", info.scene_hash}, {"sppm-alpha", "0.6"}, {"camera-pos", ""}};
  info.given = {{"scene", {"scenes/room.pbrt"}}, {"sppm-alpha", {"0.6"}}, {"psf-no-jitter", {}}};
  info.passes = 17;
  info.seconds = 2.5;
  info.paths = 123456789;
  return info;
}

SessionState sample_state() {
  SessionState s;
  for (int i = 0; i < 700; ++i) s.bytes.push_back(uint8_t(i * 37 + 11));
  return s;
}

std::string as_text(const std::vector<uint8_t>& bytes) { return std::string(bytes.begin(), bytes.end()); }

TEST(CheckpointFile, RoundTripKeepsHeaderAndState) {
  const std::vector<uint8_t> bytes = encode_checkpoint(sample_info(), sample_state());
  const Checkpoint c = decode_checkpoint(as_text(bytes), "x.ckpt");
  const CheckpointInfo want = sample_info();
  EXPECT_EQ(c.info.format_version, kCheckpointFormatVersion);
  EXPECT_FALSE(c.info.pathspace_version.empty());
  EXPECT_EQ(c.info.scene, want.scene);
  EXPECT_EQ(c.info.scene_hash, want.scene_hash);
  EXPECT_EQ(c.info.integrator, want.integrator);
  EXPECT_EQ(c.info.width, want.width);
  EXPECT_EQ(c.info.height, want.height);
  EXPECT_EQ(c.info.seed, want.seed);
  EXPECT_EQ(c.info.options, want.options);
  EXPECT_EQ(c.info.given, want.given);
  EXPECT_EQ(c.info.passes, want.passes);
  EXPECT_EQ(c.info.seconds, want.seconds);
  EXPECT_EQ(c.info.paths, want.paths);
  EXPECT_EQ(c.state.bytes, sample_state().bytes);
}

void expect_refused(const std::string& bytes, const std::string& part) {
  try {
    decode_checkpoint(bytes, "x.ckpt");
    ADD_FAILURE() << "accepted (" << bytes.size() << " bytes)";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("x.ckpt: not a usable checkpoint: ", 0), 0u) << what;
    EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

TEST(CheckpointFile, EveryTruncationIsRefused) {
  const std::string full = as_text(encode_checkpoint(sample_info(), sample_state()));
  for (size_t size = 0; size < full.size(); ++size)
    expect_refused(full.substr(0, size), size < 8 ? "does not start like" : "truncated");
}

TEST(CheckpointFile, EverySingleBitFlipIsRefused) {
  const std::string full = as_text(encode_checkpoint(sample_info(), sample_state()));
  for (size_t at = 0; at < full.size(); ++at)
    for (int bit = 0; bit < 8; ++bit) {
      std::string bytes = full;
      bytes[at] = char(bytes[at] ^ (1 << bit));
      expect_refused(bytes, "");
    }
}

TEST(CheckpointFile, OtherVersionAndTrailingBytesAreNamed) {
  std::string bytes = as_text(encode_checkpoint(sample_info(), sample_state()));
  expect_refused(bytes + "x", "unexpected data after the checksum");
  bytes[8] = char(kCheckpointFormatVersion + 1);
  expect_refused(bytes, "format version " + std::to_string(kCheckpointFormatVersion + 1));
}

TEST(CheckpointFile, WriteReplacesAtomicallyAndReadChecks) {
  testing::TempDir dir("ckpt");
  const std::string path = dir.file("a.ckpt");
  write_checkpoint(path, sample_info(), sample_state());
  EXPECT_EQ(read_checkpoint(path).info.passes, 17u);
  CheckpointInfo more = sample_info();
  more.passes = 18;
  write_checkpoint(path, more, sample_state());
  EXPECT_EQ(read_checkpoint(path).info.passes, 18u);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.ckpt"}) << "temporaries left behind";
  EXPECT_THROW(write_checkpoint(dir.file("missing/a.ckpt"), sample_info(), sample_state()), Error);
  EXPECT_EQ(read_checkpoint(path).info.passes, 18u);
  EXPECT_THROW(read_checkpoint(dir.file("none.ckpt")), Error);
}

TEST(CheckpointFile, SceneFileHashFollowsTheBytes) {
  testing::TempDir dir("ckpt");
  const std::string path = dir.file("s.pbrt");
  std::ofstream(path) << "WorldBegin\n";
  const std::string a = scene_file_hash(path);
  EXPECT_EQ(a.rfind("fnv1a64:", 0), 0u);
  EXPECT_EQ(a.size(), 8u + 16u);
  std::ofstream(path) << "WorldBegin \n";
  EXPECT_NE(scene_file_hash(path), a);
  EXPECT_THROW(scene_file_hash(dir.file("none.pbrt")), Error);
}

}  // namespace
}  // namespace pathspace
