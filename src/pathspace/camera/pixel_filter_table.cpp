#include "pathspace/camera/pixel_filter_table.h"

#include <cmath>

#include <fmt/format.h>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

// The filter's profile at |x| = a <= radius, before normalisation (negative values allowed).
double profile(const PixelFilter& f, double a) {
  switch (f.kind) {
    case PixelFilterKind::box: return 1.0;
    case PixelFilterKind::tent: return 1.0 - a / f.radius;
    case PixelFilterKind::gaussian: {  // minus its value at the radius: zero at the support's edge
      const double s2 = 2.0 * double(f.sigma) * f.sigma;
      return std::exp(-a * a / s2) - std::exp(-double(f.radius) * f.radius / s2);
    }
    case PixelFilterKind::mitchell: {  // Mitchell-Netravali 1988 on [0, 2], stretched to the radius
      const double x = 2.0 * a / f.radius, B = f.b, C = f.c;
      if (x < 1.0) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6.0;
      return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6.0;
    }
  }
  return 0.0;
}

}  // namespace

const std::vector<std::pair<std::string, PixelFilterKind>>& pixel_filter_kinds() {
  static const std::vector<std::pair<std::string, PixelFilterKind>> kinds = {
      {"box", PixelFilterKind::box}, {"tent", PixelFilterKind::tent}, {"gaussian", PixelFilterKind::gaussian}, {"mitchell", PixelFilterKind::mitchell}};
  return kinds;
}

std::vector<std::string> pixel_filter_names() {
  std::vector<std::string> names;
  for (const auto& kind : pixel_filter_kinds()) names.push_back(kind.first);
  return names;
}

std::optional<PixelFilterKind> parse_pixel_filter_kind(const std::string& name) {
  for (const auto& [n, k] : pixel_filter_kinds())
    if (n == name) return k;
  return std::nullopt;
}

const char* pixel_filter_name(PixelFilterKind kind) {
  for (const auto& [n, k] : pixel_filter_kinds())
    if (k == kind) return n.c_str();
  return "?";
}

float default_pixel_filter_radius(PixelFilterKind kind) {
  switch (kind) {
    case PixelFilterKind::box: return 0.5f;
    case PixelFilterKind::tent: return 2.f;
    case PixelFilterKind::gaussian: return 1.5f;
    case PixelFilterKind::mitchell: return 2.f;
  }
  return 0.5f;
}

PixelFilter make_pixel_filter(PixelFilterKind kind, float radius, float sigma, float b, float c) {
  if (!(radius > 0.f && radius <= kMaxPixelFilterRadius))
    throw Error(fmt::format("pixel filter radius {} must be in (0, {}] pixels", radius, kMaxPixelFilterRadius));
  if (kind == PixelFilterKind::gaussian && !(sigma > 0.f && std::isfinite(sigma)))
    throw Error(fmt::format("gaussian pixel filter: sigma {} must be positive", sigma));
  if (kind == PixelFilterKind::mitchell && !(std::isfinite(b) && std::isfinite(c)))
    throw Error("mitchell pixel filter: B and C must be finite");
  PixelFilter f;
  f.kind = kind;
  f.radius = radius;
  f.sigma = sigma;
  f.b = b;
  f.c = c;
  // Steps at their midpoints; the negative lobes are dropped (header comment).
  double steps[PixelFilter::kBins], sum = 0.0;
  const double step = double(radius) / PixelFilter::kBins;
  for (int i = 0; i < PixelFilter::kBins; ++i) {
    steps[i] = std::max(0.0, profile(f, (i + 0.5) * step));
    sum += steps[i];
  }
  if (!(sum > 0.0)) throw Error("pixel filter " + describe_pixel_filter(f) + " is zero everywhere");
  double cumulative = 0.0;
  f.cdf[0] = 0.f;
  for (int i = 0; i < PixelFilter::kBins; ++i) {
    f.value[i] = float(steps[i] / (2.0 * sum * step));
    cumulative += steps[i] / sum;
    f.cdf[i + 1] = float(cumulative);
  }
  f.cdf[PixelFilter::kBins] = 1.f;
  return f;
}

std::string describe_pixel_filter(const PixelFilter& f) {
  const std::string head = fmt::format("{} {:g}", pixel_filter_name(f.kind), f.radius);
  if (f.kind == PixelFilterKind::gaussian) return head + fmt::format(" (sigma {:g})", f.sigma);
  if (f.kind == PixelFilterKind::mitchell) return head + fmt::format(" (B {:.3g}, C {:.3g})", f.b, f.c);
  return head;
}

}  // namespace pathspace
