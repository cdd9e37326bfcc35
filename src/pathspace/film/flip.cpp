#include "pathspace/film/flip.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper's constants (sec. 3): colour power q_c and the remapping's p_c, p_t (eq. 3); the feature
// detector's width w in degrees and power q_f (sec. 3.2).
constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;
constexpr double kFeatureWidthDegrees = 0.082, kQf = 0.5;

// Contrast sensitivity functions as sums of two Gaussians in the spatial domain (sec. 3.1, the
// table of a_i, b_i): S(x) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i), x in degrees.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsf[3] = {
    {1.0, 0.0047, 0.0, 1e-5},    // achromatic (Y)
    {1.0, 0.0053, 0.0, 1e-5},    // red-green (Cx)
    {34.1, 0.04, 13.5, 0.025},   // blue-yellow (Cz)
};
constexpr double kCsfWidestB = 0.04;  // the largest b_i sets the kernel radius (3 standard deviations)

// Linear sRGB <-> CIE XYZ, derived from the sRGB primaries (0.64, 0.33), (0.30, 0.60), (0.15, 0.06) and
// the D65 white (0.3127, 0.3290) of IEC 61966-2-1; the inverse to 12 digits.
constexpr double kRgbToXyz[3][3] = {{0.4123907992659595, 0.35758433938387796, 0.1804807884018343},
                                    {0.21263900587151036, 0.7151686787677559, 0.07219231536073371},
                                    {0.01933081871559185, 0.11919477979462599, 0.9505321522496606}};
constexpr double kXyzToRgb[3][3] = {{3.240969941905, -1.537383177570, -0.498610760293},
                                    {-0.969243636281, 1.875967501508, 0.041555057407},
                                    {0.055630079697, -0.203976958889, 1.056971514243}};
// The reference white of YCxCz and CIELab: XYZ of linear RGB (1, 1, 1), so that white is L = 100, a = b = 0.
constexpr double kWhite[3] = {kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2],
                              kRgbToXyz[1][0] + kRgbToXyz[1][1] + kRgbToXyz[1][2],
                              kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};

// Three doubles: a colour in linear RGB, XYZ or CIELab.
struct Triple {
  double v[3];
};

Triple multiply(const double (&m)[3][3], const Triple& x) {
  Triple y{};
  for (int i = 0; i < 3; ++i) y.v[i] = m[i][0] * x.v[0] + m[i][1] * x.v[1] + m[i][2] * x.v[2];
  return y;
}

// NaN goes to 0 with the rest of what a display cannot show.
double clamp01(double x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// Linear RGB -> CIELab, then the Hunt adjustment (sec. 3.1): chroma scaled by 0.01 L, since colour
// differences are less visible in dark regions.
Triple hunt_lab(const Triple& rgb) {
  const Triple xyz = multiply(kRgbToXyz, rgb);
  const double fx = lab_f(xyz.v[0] / kWhite[0]), fy = lab_f(xyz.v[1] / kWhite[1]), fz = lab_f(xyz.v[2] / kWhite[2]);
  const double l = 116.0 * fy - 16.0;
  return {{l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)}};
}

// HyAB (Abasi et al. 2020): city-block in lightness, Euclidean in chroma; suits large differences
// better than the Euclidean CIELab distance (sec. 3.1).
double hyab(const Triple& p, const Triple& q) {
  return std::abs(p.v[0] - q.v[0]) + std::hypot(p.v[1] - q.v[1], p.v[2] - q.v[2]);
}

// A w × h plane of doubles.
struct Plane {
  int w = 0, h = 0;
  std::vector<double> v;
  Plane(int w_, int h_) : w(w_), h(h_), v(size_t(w_) * size_t(h_)) {}
  double& at(int x, int y) { return v[size_t(y) * size_t(w) + size_t(x)]; }
  double at(int x, int y) const { return v[size_t(y) * size_t(w) + size_t(x)]; }
};

// Separable convolution, kernel kx along rows then ky along columns, with the image's border pixels
// repeated outside it (so that a constant image stays constant). A zero-sum kernel (the feature
// detectors' derivatives) is applied to differences from the centre pixel: the same value in exact
// arithmetic, but a flat region gives exactly 0 instead of a rounding residue that q_f = 0.5 would
// raise from 1e-17 to 3e-9.
double tap_sum(const std::vector<double>& k, bool zero_sum, int n, int at, auto&& value) {
  const int r = int(k.size() / 2);
  const double centre = zero_sum ? value(at) : 0.0;
  double s = 0.0;
  for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * (value(std::clamp(at + i, 0, n - 1)) - centre);
  return s;
}

bool is_zero_sum(const std::vector<double>& k) {
  double s = 0.0, magnitude = 0.0;
  for (double v : k) s += v, magnitude += std::abs(v);
  return std::abs(s) < 1e-9 * magnitude;
}

Plane convolve(const Plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
  const bool zx = is_zero_sum(kx), zy = is_zero_sum(ky);
  Plane tmp(in.w, in.h), out(in.w, in.h);
  parallel_for(size_t(in.h), 8, [&](size_t begin, size_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < in.w; ++x) tmp.at(x, y) = tap_sum(kx, zx, in.w, x, [&](int xx) { return in.at(xx, y); });
  });
  parallel_for(size_t(in.h), 8, [&](size_t begin, size_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < in.w; ++x) out.at(x, y) = tap_sum(ky, zy, in.h, y, [&](int yy) { return tmp.at(x, yy); });
  });
  return out;
}

// The 2D CSF filter of one channel is the radial S(r), r^2 = x^2 + y^2, which splits into one separable
// term per Gaussian: a sqrt(pi/b) exp(-pi^2 (x^2 + y^2) / b) = k(x) k(y) with k = sqrt(a sqrt(pi/b))
// exp(-pi^2 x^2 / b). Both 1D kernels are scaled so that the 2D filter sums to 1 (a uniform
// image keeps its colour).
struct CsfKernels {
  std::vector<double> k1, k2;  // k2 empty when a2 = 0
};

CsfKernels csf_kernels(const Csf& csf, double ppd) {
  const int radius = int(std::ceil(3.0 * std::sqrt(kCsfWidestB / (2.0 * kPi * kPi)) * ppd));
  auto kernel = [&](double a, double b) {
    std::vector<double> k(size_t(2 * radius + 1));
    for (int i = -radius; i <= radius; ++i) {
      const double x = double(i) / ppd;  // degrees
      k[size_t(i + radius)] = std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
    }
    return k;
  };
  CsfKernels k{kernel(csf.a1, csf.b1), csf.a2 > 0.0 ? kernel(csf.a2, csf.b2) : std::vector<double>{}};
  double sum2d = 0.0;
  for (const std::vector<double>* kernel_i : {&k.k1, &k.k2}) {
    double s = 0.0;
    for (double v : *kernel_i) s += v;
    sum2d += s * s;
  }
  const double scale = 1.0 / std::sqrt(sum2d);
  for (double& v : k.k1) v *= scale;
  for (double& v : k.k2) v *= scale;
  return k;
}

Plane csf_filter(const Plane& channel, const CsfKernels& k) {
  Plane out = convolve(channel, k.k1, k.k1);
  if (!k.k2.empty()) {
    const Plane second = convolve(channel, k.k2, k.k2);
    for (size_t i = 0; i < out.v.size(); ++i) out.v[i] += second.v[i];
  }
  return out;
}

// Colour pipeline of one image (sec. 3.1): linear RGB clamped to [0, 1] -> YCxCz (the opponent space
// that is linear in XYZ, so filtering there is filtering light) -> CSF filtering -> back to linear RGB,
// clamped -> Hunt-adjusted CIELab.
std::vector<Triple> filtered_hunt_lab(const Image& image, double ppd, Plane* achromatic) {
  const int w = image.width, h = image.height;
  Plane ycxcz[3] = {Plane(w, h), Plane(w, h), Plane(w, h)};
  for (size_t i = 0; i < image.size(); ++i) {
    const Rgb& p = image.pixels[i];
    const Triple xyz = multiply(kRgbToXyz, Triple{{clamp01(p.r), clamp01(p.g), clamp01(p.b)}});
    const double xn = xyz.v[0] / kWhite[0], yn = xyz.v[1] / kWhite[1], zn = xyz.v[2] / kWhite[2];
    ycxcz[0].v[i] = 116.0 * yn - 16.0;
    ycxcz[1].v[i] = 500.0 * (xn - yn);
    ycxcz[2].v[i] = 200.0 * (yn - zn);
    achromatic->v[i] = yn;  // (Y + 16) / 116: the [0, 1] achromatic channel the features are found on
  }
  for (int c = 0; c < 3; ++c) ycxcz[c] = csf_filter(ycxcz[c], csf_kernels(kCsf[c], ppd));
  std::vector<Triple> lab(image.size());
  for (size_t i = 0; i < lab.size(); ++i) {
    const double yn = (ycxcz[0].v[i] + 16.0) / 116.0;
    const Triple xyz{{(yn + ycxcz[1].v[i] / 500.0) * kWhite[0], yn * kWhite[1], (yn - ycxcz[2].v[i] / 200.0) * kWhite[2]}};
    Triple rgb = multiply(kXyzToRgb, xyz);
    for (double& v : rgb.v) v = clamp01(v);
    lab[i] = hunt_lab(rgb);
  }
  return lab;
}

// Feature detectors (sec. 3.2): first (edges) and second (points) derivatives of a Gaussian with
// sigma = w/2 degrees, radius 3 sigma. Each derivative kernel is scaled so that its positive weights
// sum to 1 and its negative ones to -1, the Gaussian so that it sums to 1.
struct FeatureKernels {
  std::vector<double> g, dg, ddg;
};

FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;  // pixels
  const int radius = int(std::ceil(3.0 * sigma));
  FeatureKernels k;
  for (int i = -radius; i <= radius; ++i) {
    const double x = double(i), g = std::exp(-x * x / (2.0 * sigma * sigma));
    k.g.push_back(g);
    k.dg.push_back(-x * g);
    k.ddg.push_back((x * x / (sigma * sigma) - 1.0) * g);
  }
  auto balance = [](std::vector<double>& kernel) {
    double positive = 0.0, negative = 0.0;
    for (double v : kernel) (v > 0.0 ? positive : negative) += std::abs(v);
    for (double& v : kernel) v /= v > 0.0 ? positive : negative;
  };
  double sum = 0.0;
  for (double v : k.g) sum += v;
  for (double& v : k.g) v /= sum;
  balance(k.dg);
  balance(k.ddg);
  return k;
}

// Edge and point strength per pixel: the gradient magnitudes of the two detectors.
void feature_strengths(const Plane& achromatic, const FeatureKernels& k, Plane* edges, Plane* points) {
  const Plane ex = convolve(achromatic, k.dg, k.g), ey = convolve(achromatic, k.g, k.dg);
  const Plane px = convolve(achromatic, k.ddg, k.g), py = convolve(achromatic, k.g, k.ddg);
  for (size_t i = 0; i < achromatic.v.size(); ++i) {
    edges->v[i] = std::hypot(ex.v[i], ey.v[i]);
    points->v[i] = std::hypot(px.v[i], py.v[i]);
  }
}

}  // namespace

FlipResult flip(const Image& test, const Image& reference, double pixels_per_degree, bool with_map) {
  check_same_size(test, reference);
  if (!(pixels_per_degree > 0.0) || !std::isfinite(pixels_per_degree))
    throw Error("FLIP needs a positive number of pixels per degree, not " + std::to_string(pixels_per_degree));
  FlipResult result;
  const int w = test.width, h = test.height;
  if (with_map) result.map = Image(w, h);
  if (test.size() == 0) return result;

  // The largest colour difference, between Hunt-adjusted green and blue, raised to q_c: it maps to 1.
  const double cmax = std::pow(hyab(hunt_lab({{0.0, 1.0, 0.0}}), hunt_lab({{0.0, 0.0, 1.0}})), kQc);
  Plane achromatic_t(w, h), achromatic_r(w, h);
  std::vector<double> flip_map(test.size());
  {
    const std::vector<Triple> lab_t = filtered_hunt_lab(test, pixels_per_degree, &achromatic_t);
    const std::vector<Triple> lab_r = filtered_hunt_lab(reference, pixels_per_degree, &achromatic_r);
    // Eq. 3: the lower p_c of the range [0, cmax] takes [0, p_t] of the output, so that small
    // differences get most of it.
    for (size_t i = 0; i < flip_map.size(); ++i) {
      const double e = std::pow(hyab(lab_t[i], lab_r[i]), kQc);
      flip_map[i] = e < kPc * cmax ? e * kPt / (kPc * cmax) : kPt + (e - kPc * cmax) / (cmax - kPc * cmax) * (1.0 - kPt);
    }
  }
  const FeatureKernels k = feature_kernels(pixels_per_degree);
  Plane edges_t(w, h), points_t(w, h), edges_r(w, h), points_r(w, h);
  feature_strengths(achromatic_t, k, &edges_t, &points_t);
  feature_strengths(achromatic_r, k, &edges_r, &points_r);
  double sum = 0.0;
  for (size_t i = 0; i < flip_map.size(); ++i) {
    // Eq. 4-5: the feature difference (in [0, 1] after the 1/sqrt(2)) lowers the exponent, so a
    // colour error on an edge or point that differs counts more.
    const double df = std::max(std::abs(edges_t.v[i] - edges_r.v[i]), std::abs(points_t.v[i] - points_r.v[i]));
    const double feature = std::pow(df / std::sqrt(2.0), kQf);
    flip_map[i] = std::pow(flip_map[i], 1.0 - feature);
    sum += flip_map[i];
    if (with_map) result.map.pixels[i] = Rgb(float(flip_map[i]));
  }
  result.mean = sum / double(flip_map.size());
  return result;
}

}  // namespace pathspace
