// The edge-avoiding à-trous baseline of `pathspace study psf` (studies/psf/atrous_filter.h):
// a constant image stays constant whatever the guides; an edge in the normal or albedo guide stops
// blur across it; independent noise on one surface loses most of its variance.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/base/error.h"
#include "pathspace/sampling/rng.h"
#include "studies/psf/atrous_filter.h"

namespace {

using namespace pathspace;
using study::AtrousSettings;
using study::GuideBuffers;

constexpr int kSize = 64;

Image constant_image(Rgb c) {
  Image im(kSize, kSize);
  for (Rgb& p : im.pixels) p = c;
  return im;
}

// Left half one normal, right half another (a corner seen face on).
GuideBuffers split_normals() {
  GuideBuffers g = GuideBuffers::uniform(kSize, kSize, Vec3{0, 0, 1}, Rgb{0.5f, 0.5f, 0.5f});
  for (int y = 0; y < kSize; ++y)
    for (int x = kSize / 2; x < kSize; ++x) g.normal[size_t(y) * kSize + x] = Vec3{1, 0, 0};
  return g;
}

TEST(AtrousFilter, ConstantImageStaysConstant) {
  GuideBuffers g = split_normals();
  for (int i = 0; i < kSize; ++i) g.albedo[size_t(i) * kSize + 7] = Rgb{0.9f, 0.1f, 0.1f};  // an albedo stripe too
  g.hit[5] = 0;  // and a pixel that missed
  const Image out = study::atrous_filter(constant_image(Rgb{0.25f, 0.5f, 2.f}), g);
  for (const Rgb& p : out.pixels) {
    EXPECT_NEAR(p.r, 0.25f, 1e-6f);
    EXPECT_NEAR(p.g, 0.5f, 1e-6f);
    EXPECT_NEAR(p.b, 2.f, 2e-6f);
  }
}

TEST(AtrousFilter, EdgeInTheGuideStopsBlur) {
  // Dark left, bright right, split exactly where the normals change. Without guides the columns next
  // to the edge would receive about half the other side's value.
  Image im(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) im.at(x, y) = x < kSize / 2 ? Rgb{0, 0, 0} : Rgb{1, 1, 1};
  AtrousSettings s;
  s.sigma_colour = 100.f;  // colour alone would not stop anything
  const Image out = study::atrous_filter(im, split_normals(), s);
  for (int y = 0; y < kSize; ++y) {
    EXPECT_LT(out.at(kSize / 2 - 1, y).r, 0.02f) << "row " << y;
    EXPECT_GT(out.at(kSize / 2, y).r, 0.98f) << "row " << y;
  }
  // The same image with uniform guides does blur across: the test can see blur.
  const Image blurred = study::atrous_filter(im, GuideBuffers::uniform(kSize, kSize, Vec3{0, 0, 1}, Rgb{0.5f, 0.5f, 0.5f}), s);
  EXPECT_GT(blurred.at(kSize / 2 - 1, kSize / 2).r, 0.2f);
}

TEST(AtrousFilter, AlbedoEdgeStopsBlur) {
  GuideBuffers g = GuideBuffers::uniform(kSize, kSize, Vec3{0, 0, 1}, Rgb{0.8f, 0.8f, 0.8f});
  Image im(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool dark = x < kSize / 2;
      if (dark) g.albedo[size_t(y) * kSize + x] = Rgb{0.1f, 0.1f, 0.1f};
      im.at(x, y) = dark ? Rgb{0.1f, 0.1f, 0.1f} : Rgb{0.8f, 0.8f, 0.8f};
    }
  AtrousSettings s;
  s.sigma_colour = 100.f;
  const Image out = study::atrous_filter(im, g, s);
  EXPECT_LT(out.at(kSize / 2 - 1, kSize / 2).r, 0.12f);
  EXPECT_GT(out.at(kSize / 2, kSize / 2).r, 0.78f);
}

TEST(AtrousFilter, NoiseVarianceFalls) {
  Pcg32 rng(7, 0);
  Image im(kSize, kSize);
  for (Rgb& p : im.pixels) {
    const float v = 0.5f + (rng.next_float() - 0.5f) * 0.4f;  // sd 0.4 / sqrt(12) = 0.115
    p = Rgb{v, v, v};
  }
  auto variance = [](const Image& image) {
    double sum = 0, sum2 = 0;
    for (const Rgb& p : image.pixels) sum += p.r, sum2 += double(p.r) * p.r;
    const double n = double(image.size()), mean = sum / n;
    return sum2 / n - mean * mean;
  };
  const Image out = study::atrous_filter(im, GuideBuffers::uniform(kSize, kSize, Vec3{0, 0, 1}, Rgb{0.5f, 0.5f, 0.5f}));
  EXPECT_LT(variance(out), 0.1 * variance(im)) << variance(im) << " -> " << variance(out);
}

TEST(AtrousFilter, RejectsMismatchedSizes) {
  EXPECT_THROW(study::atrous_filter(Image(8, 8), GuideBuffers::uniform(4, 4, Vec3{0, 0, 1}, Rgb{})), Error);
}

}  // namespace
