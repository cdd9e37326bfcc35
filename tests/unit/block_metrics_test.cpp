// Unit tests of film/block_metrics.h in closed form: a uniformly brighter image, partial blocks at the
// right and bottom edges, noise that block averaging removes, the blotch threshold on both sides, and
// the errors (size mismatch, block < 1).
#include <gtest/gtest.h>

#include "pathspace/base/error.h"
#include "pathspace/film/block_metrics.h"
#include "pathspace/film/image_metrics.h"

namespace pathspace {
namespace {

Image constant(int w, int h, Rgb c) {
  Image image(w, h);
  for (Rgb& p : image.pixels) p = c;
  return image;
}

// (T - R)^2 / (R^2 + eps) from the float values the images hold.
double rel_sq(float t, float r) {
  const double d = double(t) - double(r);
  return d * d / (double(r) * double(r) + kRelMseEpsilon);
}

TEST(BlockMetrics, UniformlyBrighterImage) {
  // 20% brighter everywhere: every block and channel has (0.2 R)^2 / (R^2 + 0.01) = 0.04 R^2 / (R^2 + 0.01).
  const float r = 0.5f, t = 1.2f * r;
  const Image reference = constant(32, 24, Rgb(r)), image = constant(32, 24, Rgb(t));
  const BlockError e = block_error(image, reference, 8);
  EXPECT_EQ(e.blocks, 4 * 3);
  EXPECT_DOUBLE_EQ(e.block_rel_mse, rel_sq(t, r));
  EXPECT_NEAR(e.block_rel_mse, 0.04 * 0.25 / (0.25 + 0.01), 1e-7);
  // 0.2 Y = 0.1 is under 0.25 Y + 0.02 = 0.145: not blotched.
  EXPECT_EQ(e.blotched_share, 0.0);
  // 40% brighter: 0.4 Y = 0.2 is over 0.145, every block is blotched.
  EXPECT_EQ(block_error(constant(32, 24, Rgb(1.4f * r)), reference, 8).blotched_share, 1.0);
  // And the same for darker (the difference is taken in absolute value).
  EXPECT_EQ(block_error(constant(32, 24, Rgb(0.6f * r)), reference, 8).blotched_share, 1.0);
}

TEST(BlockMetrics, ThresholdHasAnAbsoluteFloorForDarkBlocks) {
  // Reference luminance 0.01: the threshold is 0.25 * 0.01 + 0.02 = 0.0225, so doubling (+0.01) is not
  // a blotch, +0.03 is.
  const Image reference = constant(8, 8, Rgb(0.01f));
  EXPECT_EQ(block_error(constant(8, 8, Rgb(0.02f)), reference).blotched_share, 0.0);
  EXPECT_EQ(block_error(constant(8, 8, Rgb(0.04f)), reference).blotched_share, 1.0);
  EXPECT_EQ(kBlotchRelative, 0.25);
  EXPECT_EQ(kBlotchAbsolute, 0.02);
}

TEST(BlockMetrics, LuminanceUsesRec709Weights) {
  // A pure blue block brighter by 0.5 moves luminance by 0.0722 * 0.5 = 0.0361 against a threshold
  // of 0.25 * 0.0722 * 0.5 + 0.02 = 0.029025 (blotched); pure red by 0.05 moves it 0.01063 < 0.025315.
  EXPECT_EQ(block_error(constant(4, 4, Rgb(0.f, 0.f, 1.f)), constant(4, 4, Rgb(0.f, 0.f, 0.5f)), 4).blotched_share, 1.0);
  EXPECT_EQ(block_error(constant(4, 4, Rgb(0.15f, 0.f, 0.f)), constant(4, 4, Rgb(0.1f, 0.f, 0.f)), 4).blotched_share, 0.0);
}

TEST(BlockMetrics, NoiseThatAveragesOutIsNoBlockError) {
  // A checkerboard of +-0.1 around the reference: large per-pixel relMSE, zero after 2x2 averaging.
  const Image reference = constant(6, 4, Rgb(0.5f));
  Image image(6, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) image.at(x, y) = Rgb((x + y) % 2 ? 0.625f : 0.375f);  // exact in float
  EXPECT_GT(image_error(image, reference).rel_mse, 0.05);
  const BlockError e = block_error(image, reference, 2);
  EXPECT_EQ(e.blocks, 3 * 2);
  EXPECT_EQ(e.block_rel_mse, 0.0);
  EXPECT_EQ(e.blotched_share, 0.0);
  // Block 1 is the per-pixel relMSE.
  EXPECT_DOUBLE_EQ(block_error(image, reference, 1).block_rel_mse, image_error(image, reference).rel_mse);
}

TEST(BlockMetrics, PartialEdgeBlocksAverageThePixelsTheyHave) {
  // 5x3 with block 4: blocks (0..3 x 0..2) of 12 pixels and (4 x 0..2) of 3 pixels. The image is the
  // reference (0.5) except column 4, which is 1.0: only the right block differs, by 0.5 on average
  // over its 3 pixels (a division by 16 pixels would give 0.09375).
  const Image reference = constant(5, 3, Rgb(0.5f));
  Image image = reference;
  for (int y = 0; y < 3; ++y) image.at(4, y) = Rgb(1.f);
  const BlockError e = block_error(image, reference, 4);
  EXPECT_EQ(e.blocks, 2);
  EXPECT_DOUBLE_EQ(e.block_rel_mse, 0.5 * rel_sq(1.f, 0.5f));  // one of two blocks, all channels alike
  EXPECT_EQ(e.blotched_share, 0.5);                            // |1 - 0.5| > 0.25 * 0.5 + 0.02
  // A block larger than the image is one block: the whole-image average.
  const BlockError whole = block_error(image, reference, 100);
  EXPECT_EQ(whole.blocks, 1);
  const double mean = (12 * 0.5 + 3 * 1.0) / 15.0;
  EXPECT_NEAR(whole.block_rel_mse, (mean - 0.5) * (mean - 0.5) / (0.25 + kRelMseEpsilon), 1e-15);
}

TEST(BlockMetrics, ChannelsAreAveragedSeparately) {
  // Only green differs, by 0.1: the channel mean is a third of green's term.
  const Image reference = constant(8, 8, Rgb(0.2f, 0.4f, 0.6f));
  const Image image = constant(8, 8, Rgb(0.2f, 0.5f, 0.6f));
  EXPECT_DOUBLE_EQ(block_error(image, reference).block_rel_mse, rel_sq(0.5f, 0.4f) / 3.0);
}

TEST(BlockMetrics, IdenticalImagesAndEmptyImages) {
  const Image reference = constant(9, 7, Rgb(0.3f, 0.1f, 2.f));
  const BlockError e = block_error(reference, reference, 3);
  EXPECT_EQ(e.block_rel_mse, 0.0);
  EXPECT_EQ(e.blotched_share, 0.0);
  EXPECT_EQ(e.blocks, 3 * 3);
  EXPECT_EQ(block_error(Image(), Image()).blocks, 0);
}

TEST(BlockMetrics, Errors) {
  const Image a(8, 8), b(8, 7);
  EXPECT_THROW(block_error(a, b), Error);
  EXPECT_THROW(block_error(a, a, 0), Error);
  EXPECT_THROW(block_error(a, a, -3), Error);
  EXPECT_NO_THROW(block_error(a, a, 1));
}

}  // namespace
}  // namespace pathspace
