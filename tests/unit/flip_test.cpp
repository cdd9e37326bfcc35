// Unit tests of film/flip.h (LDR FLIP, Andersson et al. HPG 2020): closed-form values on uniform images
// (identical images, black against white, two greys: no features, so FLIP is the remapped HyAB colour
// difference), the [0, 1] clamp, symmetry, the map, errors, and the published mean FLIP of an example
// pair when its images are there (PATHSPACE_FLIP_EXAMPLE_DIR; skipped otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "pathspace/base/error.h"
#include "pathspace/film/flip.h"
#include "pathspace/io/image_io.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

Image constant(int w, int h, Rgb c) {
  Image image(w, h);
  for (Rgb& p : image.pixels) p = c;
  return image;
}

Image random_image(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  Image image(w, h);
  for (Rgb& p : image.pixels) p = Rgb(u(rng), u(rng), u(rng));
  return image;
}

// Uniform images have no edges or points, and the CSF filters (normalised to sum 1) keep them
// uniform, so FLIP is the colour term everywhere: HyAB between the two Hunt-adjusted CIELab colours,
// raised to q_c = 0.7 and remapped against cmax (eq. 3). cmax^(1/0.7) is HyAB between Hunt-adjusted
// green (L 87.7355, a -86.1816, b 83.1866 -> a' = 0.01 L a = -75.6119, b' = 72.9842) and blue
// (L 32.3009, a 79.1953, b -107.8555 -> a' 25.5808, b' -34.8383): 55.4346 + hypot(101.1927, 107.8225)
// = 203.3050, so cmax = 203.3050^0.7 = 41.27657 and p_c cmax = 16.51063.
constexpr double kCmax = 41.27657043967204;

TEST(Flip, IdenticalImagesAreZero) {
  const Image a = random_image(23, 17, 1);
  const FlipResult f = flip(a, a, kFlipPixelsPerDegree, true);
  EXPECT_EQ(f.mean, 0.0);
  for (const Rgb& p : f.map.pixels) ASSERT_EQ(p.r, 0.f);
}

TEST(Flip, BlackAgainstWhite) {
  // White is L = 100, a = b = 0 (the reference white is linear RGB (1, 1, 1)), black L = 0: HyAB = 100,
  // 100^0.7 = 25.11886 > p_c cmax, the upper branch of eq. 3:
  // 0.95 + (25.11886 - 16.51063) / (41.27657 - 16.51063) * 0.05 = 0.967379. Not 1: the largest
  // difference FLIP knows is green against blue, not black against white.
  const double expected = 0.95 + (std::pow(100.0, 0.7) - 0.4 * kCmax) / (0.6 * kCmax) * 0.05;
  EXPECT_NEAR(expected, 0.967379, 1e-6);
  const FlipResult f = flip(constant(16, 12, Rgb(0.f)), constant(16, 12, Rgb(1.f)), kFlipPixelsPerDegree, true);
  EXPECT_NEAR(f.mean, expected, 1e-9);
  for (const Rgb& p : f.map.pixels) ASSERT_NEAR(p.r, expected, 1e-6);
}

TEST(Flip, TwoGreys) {
  // Linear 0.5 and 0.25: L = 116 cbrt(Y) - 16 = 76.06926 and 57.07542, a = b = 0; HyAB^0.7 =
  // 18.99384^0.7 = 7.852880 < p_c cmax, the lower branch: 7.852880 * 0.95 / 16.51063 = 0.451844.
  const double l1 = 116.0 * std::cbrt(0.5) - 16.0, l2 = 116.0 * std::cbrt(0.25) - 16.0;
  const double expected = std::pow(l1 - l2, 0.7) * 0.95 / (0.4 * kCmax);
  EXPECT_NEAR(expected, 0.451844, 1e-6);
  EXPECT_NEAR(flip(constant(10, 10, Rgb(0.5f)), constant(10, 10, Rgb(0.25f))).mean, expected, 1e-9);
}

TEST(Flip, SeesTheImageAsADisplayShowsIt) {
  // Linear values are clamped to [0, 1] first: above 1 is white, below 0 (and NaN) black.
  EXPECT_EQ(flip(constant(8, 8, Rgb(3.f)), constant(8, 8, Rgb(1.f))).mean, 0.0);
  EXPECT_EQ(flip(constant(8, 8, Rgb(-1.f)), constant(8, 8, Rgb(0.f))).mean, 0.0);
  EXPECT_EQ(flip(constant(8, 8, Rgb(std::numeric_limits<float>::quiet_NaN())), constant(8, 8, Rgb(0.f))).mean, 0.0);
}

TEST(Flip, SymmetricAndInTheUnitInterval) {
  const Image a = random_image(31, 20, 2), b = random_image(31, 20, 3);
  const FlipResult ab = flip(a, b, kFlipPixelsPerDegree, true), ba = flip(b, a, kFlipPixelsPerDegree, true);
  EXPECT_EQ(ab.mean, ba.mean);
  ASSERT_EQ(ab.map.width, 31);
  ASSERT_EQ(ab.map.height, 20);
  double sum = 0.0;
  for (const Rgb& p : ab.map.pixels) {
    ASSERT_GE(p.r, 0.f);
    ASSERT_LE(p.r, 1.f);
    sum += p.r;
  }
  EXPECT_NEAR(sum / double(ab.map.size()), ab.mean, 1e-6);
  EXPECT_TRUE(flip(a, b).map.pixels.empty());  // no map unless asked for
}

TEST(Flip, AFireflyFadesWithViewingDistance) {
  // One white pixel on grey. A viewer farther away (more pixels per degree) has it blurred by a wider
  // CSF, so sees less of it at its pixel, and more around it.
  const Image reference = constant(33, 33, Rgb(0.2f));
  Image test = reference;
  test.at(16, 16) = Rgb(1.f);
  const FlipResult near = flip(test, reference, 20.0, true), mid = flip(test, reference, 67.0, true),
                   far = flip(test, reference, 120.0, true);
  EXPECT_GT(near.map.at(16, 16).r, 0.9f);
  EXPECT_GT(near.map.at(16, 16).r, mid.map.at(16, 16).r);
  EXPECT_GT(mid.map.at(16, 16).r, far.map.at(16, 16).r);
  EXPECT_LT(mid.map.at(19, 16).r, far.map.at(19, 16).r);
  // At 20 pixels per degree both the CSF (radius ceil(3 sqrt(0.04 / (2 pi^2)) 20) = 3) and the feature
  // detectors (sigma = 0.041 * 20 px, radius 3) end 3 pixels out: beyond, nothing differs.
  EXPECT_EQ(near.map.at(22, 16).r, 0.f);
  EXPECT_EQ(near.map.at(16, 12).r, 0.f);
  EXPECT_EQ(near.map.at(0, 0).r, 0.f);
}

TEST(Flip, Errors) {
  const Image a(8, 8), b(7, 8);
  EXPECT_THROW(flip(a, b), Error);
  EXPECT_THROW(flip(a, a, 0.0), Error);
  EXPECT_THROW(flip(a, a, -67.0), Error);
  EXPECT_THROW(flip(a, a, std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_THROW(flip(a, a, std::numeric_limits<double>::infinity()), Error);
  EXPECT_EQ(flip(Image(), Image()).mean, 0.0);
}

// Published values: the images are not in this repository (their licences are not ours to take
// in), so the test reads them from PATHSPACE_FLIP_EXAMPLE_DIR and skips without it.
fs::path example_dir() {
  const char* dir = std::getenv("PATHSPACE_FLIP_EXAMPLE_DIR");
  return dir ? fs::path(dir) : fs::path();
}

TEST(Flip, PublishedMeanOfTheTreePair) {
  // gfx-rs/nv-flip-rs (Rust bindings of NVIDIA's FLIP C++ code), files etc/tree-ref.png and
  // etc/tree-test.png (640x960, Unsplash licence); nv-flip/src/lib.rs, test `end_to_end`, publishes
  // mean 0.133285 and max 0.983044 at 67 pixels per degree ("pulled directly from the command line
  // tool", asserted there to 1e-4). Ours (double precision) gave mean 0.1332854 and max 0.9830427.
  const fs::path dir = example_dir();
  if (dir.empty() || !fs::exists(dir / "tree-ref.png") || !fs::exists(dir / "tree-test.png"))
    GTEST_SKIP() << "set PATHSPACE_FLIP_EXAMPLE_DIR to a folder with tree-ref.png and tree-test.png from "
                    "github.com/gfx-rs/nv-flip-rs (etc/) to check the published mean FLIP";
  const Image reference = read_image((dir / "tree-ref.png").string()), test = read_image((dir / "tree-test.png").string());
  const FlipResult f = flip(test, reference, 67.0, true);
  EXPECT_NEAR(f.mean, 0.133285, 2e-6);
  float max = 0.f;
  for (const Rgb& p : f.map.pixels) max = std::max(max, p.r);
  EXPECT_NEAR(max, 0.983044, 5e-6);
}

TEST(Flip, PublishedMeanOfNvidiasExamplePair) {
  // NVlabs/flip, images/reference.png and images/test.png; src/tests/test.py expects the LDR mean
  // 0.159691 at the tool's default 0.7 m · 3840 px / 0.7 m · pi / 180 = 67.0206 pixels per degree.
  // Not checked here yet: images/test.png (over 4 MiB) could not be fetched when this was written.
  const fs::path dir = example_dir();
  if (dir.empty() || !fs::exists(dir / "reference.png") || !fs::exists(dir / "test.png"))
    GTEST_SKIP() << "set PATHSPACE_FLIP_EXAMPLE_DIR to a folder with reference.png and test.png from "
                    "github.com/NVlabs/flip (images/) to check the published mean FLIP";
  const Image reference = read_image((dir / "reference.png").string()), test = read_image((dir / "test.png").string());
  EXPECT_NEAR(flip(test, reference, 0.7 * 3840.0 / 0.7 * std::numbers::pi / 180.0).mean, 0.159691, 5e-6);
}

}  // namespace
}  // namespace pathspace
