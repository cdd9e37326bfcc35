// Block metrics between an image and a reference: relMSE of B×B block averages, and the share of
// "blotched" blocks. Per-pixel relMSE is dominated by noise that a viewer averages away; low-frequency
// blotches (what filters leave behind) survive block averaging, so these two numbers rank filtered
// renders the way a viewer does (docs/cli.md, `compare`).
#pragma once

#include "pathspace/film/image.h"

namespace pathspace {

struct BlockError {
  double block_rel_mse = 0.0;   // mean over blocks and channels of (T - R)^2 / (R^2 + kRelMseEpsilon)
  double blotched_share = 0.0;  // blotched blocks / all blocks
  long long blocks = 0;         // ceil(width / block) * ceil(height / block)
};

inline constexpr int kDefaultMetricBlock = 8;
// A block is blotched when its mean luminance is off the reference block's by more than
// kBlotchRelative * reference + kBlotchAbsolute: relative for bright blocks, and an absolute floor so
// that near-black blocks do not count noise as blotches.
inline constexpr double kBlotchRelative = 0.25;
inline constexpr double kBlotchAbsolute = 0.02;

// Averages both images over non-overlapping block × block squares from the top left (the blocks at the
// right and bottom edges average the pixels they have). Throws pathspace::Error when the sizes differ
// or block < 1.
BlockError block_error(const Image& image, const Image& reference, int block = kDefaultMetricBlock);

}  // namespace pathspace
