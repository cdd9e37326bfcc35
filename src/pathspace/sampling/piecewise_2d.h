// Piecewise-constant density over the unit square [0,1)^2 on a W x H grid of cells (row j covers
// v in [j/H, (j+1)/H)): a marginal CDF over rows and one conditional CDF per row. Sampling inverts
// both CDFs continuously inside the chosen cell, so `pdf(sample(u))` is the returned density.
// Used for environment-map importance sampling. Piecewise2D is the host owner; Piecewise2DView the
// device-safe view.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/sampling/warps.h"

namespace pathspace {

struct Piecewise2DView {
  const float* row_cdf = nullptr;  // H + 1 entries, row_cdf[H] = 1
  const float* cell_cdf = nullptr;  // H rows of W + 1 entries, each ending at 1
  const float* cell_pdf = nullptr;  // H * W densities over the unit square (mean 1)
  int32_t width = 0, height = 0;

  PS_HD bool valid() const { return width > 0 && height > 0; }

  // Density of uv (with respect to area on the unit square).
  PS_HD float pdf(Point2 uv) const {
    int x = int(uv.x * float(width)), y = int(uv.y * float(height));
    x = x < 0 ? 0 : (x >= width ? width - 1 : x);
    y = y < 0 ? 0 : (y >= height ? height - 1 : y);
    return cell_pdf[size_t(y) * size_t(width) + size_t(x)];
  }

  // Maps u in [0,1)^2 to uv with density *pdf (0 only if the whole grid is zero).
  PS_HD Point2 sample(Point2 u, float* pdf_out) const {
    float fy;
    const int y = invert(row_cdf, height, u.y, &fy);
    float fx;
    const int x = invert(cell_cdf + size_t(y) * size_t(width + 1), width, u.x, &fx);
    *pdf_out = cell_pdf[size_t(y) * size_t(width) + size_t(x)];
    return {(float(x) + fx) / float(width), (float(y) + fy) / float(height)};
  }

 private:
  // Largest i with cdf[i] <= u and a non-empty interval; *frac is u's position inside it.
  PS_HD static int invert(const float* cdf, int n, float u, float* frac) {
    int lo = 0, hi = n;
    while (lo + 1 < hi) {
      const int mid = (lo + hi) / 2;
      if (cdf[mid] <= u) lo = mid;
      else hi = mid;
    }
    while (cdf[lo + 1] <= cdf[lo] && lo + 1 < n) ++lo;      // skip empty cells forwards
    while (cdf[lo + 1] <= cdf[lo] && lo > 0) --lo;          // (u at the very end): backwards
    const float width = cdf[lo + 1] - cdf[lo];
    float f = width > 0.f ? (u - cdf[lo]) / width : 0.5f;
    f = f < 0.f ? 0.f : (f < 1.f ? f : 0.99999994f);
    *frac = f;
    return lo;
  }
};

class Piecewise2D {
 public:
  // weights: H rows of W non-negative cell weights. An all-zero grid becomes uniform.
  void build(const std::vector<float>& weights, int width, int height) {
    width_ = width;
    height_ = height;
    const size_t w = size_t(width), h = size_t(height);
    cell_cdf_.assign(h * (w + 1), 0.f);
    cell_pdf_.assign(h * w, 0.f);
    row_cdf_.assign(h + 1, 0.f);
    std::vector<double> row_sum(h, 0.0);
    double total = 0.0;
    for (size_t y = 0; y < h; ++y) {
      for (size_t x = 0; x < w; ++x) row_sum[y] += clamp_weight(weights[y * w + x]);
      total += row_sum[y];
    }
    const bool uniform = !(total > 0.0);
    double acc = 0.0;
    for (size_t y = 0; y < h; ++y) {
      const double rs = uniform ? double(w) : row_sum[y];
      double racc = 0.0;
      float* cdf = cell_cdf_.data() + y * (w + 1);
      for (size_t x = 0; x < w; ++x) {
        const double cw = uniform ? 1.0 : clamp_weight(weights[y * w + x]);
        racc += cw;
        cdf[x + 1] = rs > 0.0 ? float(racc / rs) : float(double(x + 1) / double(w));
        // Density over the unit square: cell probability times the cell count.
        cell_pdf_[y * w + x] = float(cw / (uniform ? double(w * h) : total) * double(w * h));
      }
      cdf[w] = 1.f;
      acc += uniform ? 1.0 / double(h) : row_sum[y] / total;
      row_cdf_[y + 1] = float(acc);
    }
    row_cdf_[h] = 1.f;
  }

  Piecewise2DView view() const {
    if (width_ <= 0) return {};
    return {row_cdf_.data(), cell_cdf_.data(), cell_pdf_.data(), width_, height_};
  }

 private:
  static double clamp_weight(float v) { return v > 0.f && v < 3.0e38f ? double(v) : 0.0; }

  int width_ = 0, height_ = 0;
  std::vector<float> row_cdf_, cell_cdf_, cell_pdf_;
};

}  // namespace pathspace
