#include "pathspace/film/block_metrics.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/math/rgb.h"

namespace pathspace {

namespace {

struct BlockMean {
  double c[3] = {0.0, 0.0, 0.0};
  double luminance() const { return luminance_of(c[0], c[1], c[2]); }  // Rec. 709, as everywhere
};

// The block averages of one image, row-major over blocks; sums in double so that a large block of
// float pixels does not lose the low bits that a small error lives in.
std::vector<BlockMean> block_means(const Image& image, int block, int bw, int bh) {
  std::vector<BlockMean> means(size_t(bw) * size_t(bh));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      BlockMean& m = means[size_t(y / block) * size_t(bw) + size_t(x / block)];
      const Rgb& p = image.at(x, y);
      for (int c = 0; c < 3; ++c) m.c[c] += p[c];
    }
  for (int by = 0; by < bh; ++by)
    for (int bx = 0; bx < bw; ++bx) {
      const int w = std::min(block, image.width - bx * block), h = std::min(block, image.height - by * block);
      BlockMean& m = means[size_t(by) * size_t(bw) + size_t(bx)];
      for (double& v : m.c) v /= double(w) * double(h);
    }
  return means;
}

}  // namespace

BlockError block_error(const Image& image, const Image& reference, int block) {
  check_same_size(image, reference);
  if (block < 1) throw Error("block size must be at least 1, not " + std::to_string(block));
  BlockError e;
  const int bw = (image.width + block - 1) / block, bh = (image.height + block - 1) / block;
  e.blocks = (long long)bw * bh;
  if (e.blocks == 0) return e;
  const std::vector<BlockMean> t = block_means(image, block, bw, bh), r = block_means(reference, block, bw, bh);
  long long blotched = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double d = t[i].c[c] - r[i].c[c];
      e.block_rel_mse += d * d / (r[i].c[c] * r[i].c[c] + kRelMseEpsilon);
    }
    const double lr = r[i].luminance();
    if (std::abs(t[i].luminance() - lr) > kBlotchRelative * lr + kBlotchAbsolute) ++blotched;
  }
  e.block_rel_mse /= 3.0 * double(e.blocks);
  e.blotched_share = double(blotched) / double(e.blocks);
  return e;
}

}  // namespace pathspace
