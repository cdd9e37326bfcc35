// `pathspace view`'s message decoder and camera motion (apps/pathspace/viewer/, docs/viewer.md): each
// command parsed with its numbers, every kind of bad message refused with its reason, and the camera
// axes unit and orthogonal after turns, with motion along them. The page itself: tests/browser.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "pathspace/base/error.h"
#include "viewer/camera_controls.h"
#include "viewer/display.h"
#include "viewer/viewer_protocol.h"

namespace pathspace::viewer {
namespace {

std::string error_of(const std::string& message) {
  try {
    parse_command(message);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ViewerProtocol, ParsesEveryCommand) {
  EXPECT_TRUE(std::holds_alternative<FrameRequest>(parse_command(R"({"cmd":"frame"})")));
  const Move m = std::get<Move>(parse_command(R"({"cmd":"move","right":1.5,"forward":-2})"));
  EXPECT_EQ(m.right, 1.5);
  EXPECT_EQ(m.up, 0.0);
  EXPECT_EQ(m.forward, -2.0);
  const Turn t = std::get<Turn>(parse_command(R"({"cmd":"turn","yaw":-5,"pitch":2.5})"));
  EXPECT_EQ(t.yaw, -5.0);
  EXPECT_EQ(t.pitch, 2.5);
  EXPECT_TRUE(std::holds_alternative<Reset>(parse_command(R"({"cmd":"reset"})")));
  EXPECT_EQ(std::get<Exposure>(parse_command(R"({"cmd":"exposure","stops":-3})")).stops, -3.0);
  EXPECT_TRUE(std::holds_alternative<OptionsRequest>(parse_command(R"({"cmd":"options"})")));
  EXPECT_TRUE(std::holds_alternative<Save>(parse_command(R"({"cmd":"save"})")));
  EXPECT_TRUE(std::get<Record>(parse_command(R"({"cmd":"record","on":true})")).on);
  EXPECT_NE(error_of(R"({"cmd":"record","on":1})").find("true or false"), std::string::npos);
  EXPECT_EQ(std::get<Split>(parse_command(R"({"cmd":"split","filter":"hashed"})")).filter, "hashed");
  EXPECT_EQ(std::get<Split>(parse_command(R"({"cmd":"split","filter":"hashed"})")).integrator, "");
  EXPECT_EQ(std::get<Split>(parse_command(R"({"cmd":"split","integrator":"bpt","filter":"none"})")).integrator, "bpt");
  EXPECT_TRUE(std::get<Play>(parse_command(R"({"cmd":"play","on":true})")).on);
  EXPECT_FALSE(std::get<Play>(parse_command(R"({"cmd":"play","on":false})")).on);
  EXPECT_EQ(std::get<Seek>(parse_command(R"({"cmd":"seek","seconds":2.5})")).seconds, 2.5);
  EXPECT_NE(error_of(R"({"cmd":"seek","seconds":-1})").find("within 0..1e6"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"play"})").find("true or false"), std::string::npos);
  EXPECT_EQ(std::get<ToneMapChoice>(parse_command(R"({"cmd":"tonemap","name":"aces"})")).name, "aces");
  EXPECT_NE(error_of(R"({"cmd":"tonemap","name":"filmic"})").find("unknown tone map"), std::string::npos);
  const Inspect inspect = std::get<Inspect>(parse_command(R"({"cmd":"inspect","x":12,"y":0})"));
  EXPECT_EQ(inspect.x, 12);
  EXPECT_EQ(inspect.y, 0);
  EXPECT_NE(error_of(R"({"cmd":"inspect","x":1.5,"y":0})").find("whole number"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"inspect","x":-1,"y":0})").find("whole number"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"inspect","x":70000,"y":0})").find("within"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"inspect","x":3})").find("\"y\" is missing"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"split","integrator":"--seed","filter":"none"})").find("option name"), std::string::npos);
  const SetOption set = std::get<SetOption>(parse_command(R"({"cmd":"set","name":"max-depth","value":"5"})"));
  EXPECT_EQ(set.name, "max-depth");
  EXPECT_EQ(set.value, "5");
  EXPECT_EQ(std::get<SetOption>(parse_command(R"({"cmd":"set","name":"no-nee"})")).value, "");  // a flag
  EXPECT_EQ(std::get<UnsetOption>(parse_command(R"({"cmd":"unset","name":"no-nee"})")).name, "no-nee");
}

// Option names reach the registry's lookup only as names: no dashes, spaces or other characters.
TEST(ViewerProtocol, RefusesOptionNamesThatAreNotNames) {
  EXPECT_NE(error_of(R"({"cmd":"set","name":"--max-depth","value":"5"})").find("option name without dashes"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","name":"max-depth 5 --seed","value":"5"})").find("option name"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","name":"","value":"5"})").find("option name"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","name":"Max","value":"5"})").find("option name"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","name":"max-depth","value":5})").find("\"value\" must be a string"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","value":"5"})").find("\"name\" must be a string"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"set","name":"a","value":")" + std::string(300, 'x') + R"("})").find("longer than 256"), std::string::npos);
}

TEST(ViewerProtocol, RefusesBadMessagesWithTheirReason) {
  EXPECT_NE(error_of("").find("one JSON object"), std::string::npos);
  EXPECT_NE(error_of("[1,2]").find("one JSON object"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"frame")").find("one JSON object"), std::string::npos);
  EXPECT_NE(error_of(R"({"move":1})").find("needs \"cmd\""), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":7})").find("needs \"cmd\""), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"fly"})").find("unknown command \"fly\""), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"move","forward":"1"})").find("must be a number"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"move","forward":1e400})").find("one JSON object"), std::string::npos);  // not JSON's range
  EXPECT_NE(error_of(R"({"cmd":"move","forward":2000})").find("within"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"turn","yaw":361})").find("within"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"exposure","stops":21})").find("within"), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"frame","extra":1})").find("unknown field \"extra\""), std::string::npos);
  EXPECT_NE(error_of(R"({"cmd":"--camera-pos"})").find("unknown command"), std::string::npos);
  EXPECT_NE(error_of(std::string(kMaxMessageBytes + 1, ' ')).find("at most 4096"), std::string::npos);
  // Deeply nested JSON is refused without recursion trouble (size limit first, then the parser).
  EXPECT_FALSE(error_of(std::string(2000, '[') + std::string(2000, ']')).empty());
}

// The fuzz target's seed corpus and findings (tests/fuzz/corpus/viewer/, fuzz_viewer.cpp): each file
// parses or is refused with pathspace::Error, nothing else.
TEST(ViewerProtocol, FuzzCorpusParsesOrIsRefused) {
  namespace fs = std::filesystem;
  int files = 0, parsed = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PATHSPACE_SOURCE_DIR) / "tests/fuzz/corpus/viewer")) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    ++files;
    try {
      parse_command(bytes.str());
      ++parsed;
    } catch (const Error&) {
    }
  }
  EXPECT_GE(files, 10);
  EXPECT_GE(parsed, 18) << "the valid seeds (every command) parse";
}

// The display's curves: clip is the exposure alone; Reinhard maps luminance L to L / (1 + L) keeping
// the hue; the ACES fit is 0 at 0, about 0.8 at 1 and below 1 for large values.
TEST(ViewerDisplay, ToneCurves) {
  Image image(3, 1);
  image.pixels = {Rgb(0.5f), Rgb(1.f, 0.5f, 0.25f), Rgb(100.f)};
  const Image clipped = displayed(image, Display{2.f, ToneMap::clip});
  EXPECT_EQ(clipped.pixels[0].r, 1.f);
  EXPECT_EQ(clipped.pixels[2].g, 200.f);
  const Image reinhard = displayed(image, Display{1.f, ToneMap::reinhard});
  EXPECT_NEAR(reinhard.pixels[0].r, 0.5f / 1.5f, 1e-6f);
  const float l = luminance(Rgb(1.f, 0.5f, 0.25f));
  EXPECT_NEAR(reinhard.pixels[1].g / reinhard.pixels[1].r, 0.5f, 1e-6f) << "the hue is kept";
  EXPECT_NEAR(luminance(reinhard.pixels[1]), l / (1.f + l), 1e-6f);
  const Image aces = displayed(image, Display{1.f, ToneMap::aces});
  EXPECT_NEAR(aces.pixels[1].r, 0.8038f, 1e-3f);
  EXPECT_LT(aces.pixels[2].r, 1.05f);
  EXPECT_GT(aces.pixels[2].r, 1.0f);
  EXPECT_EQ(displayed(Image(1, 1), Display{1.f, ToneMap::aces}).pixels[0].r, 0.f);
  EXPECT_THROW(parse_tone_map("filmic"), Error);
  for (const std::string& name : tone_map_names()) EXPECT_EQ(tone_map_name(parse_tone_map(name)), name);
}

TEST(ViewerCamera, TurnsKeepAnOrthonormalFrameAndMovesFollowIt) {
  PerspectiveCamera c = make_perspective_camera(Vec3(0, 1, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 45.f, 64, 48);
  turn_camera(&c, 90.0, 0.0);  // a quarter turn left about up: now looking along -x
  EXPECT_NEAR(c.forward.x, -1.f, 1e-5f);
  EXPECT_NEAR(c.forward.z, 0.f, 1e-5f);
  for (int i = 0; i < 100; ++i) turn_camera(&c, 7.0, 3.0);
  EXPECT_NEAR(length(c.forward), 1.f, 1e-4f);
  EXPECT_NEAR(length(c.right), 1.f, 1e-4f);
  EXPECT_NEAR(length(c.up), 1.f, 1e-4f);
  EXPECT_NEAR(dot(c.forward, c.right), 0.f, 1e-4f);
  EXPECT_NEAR(dot(c.forward, c.up), 0.f, 1e-4f);
  const Vec3 before = c.position;
  move_camera(&c, 0.0, 0.0, 2.0, 0.5f);
  EXPECT_NEAR(length(c.position - (before + c.forward)), 0.f, 1e-5f);
  const std::string options = camera_options(make_perspective_camera(Vec3(0, 1, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 45.f, 48, 48));
  EXPECT_EQ(options, "--camera-pos 0,1,5 --camera-target 0,1,4 --camera-up 0,1,0 --fov 45");
}

}  // namespace
}  // namespace pathspace::viewer
