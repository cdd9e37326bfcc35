#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "support/statistics.h"

namespace pathspace::testing {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normal_two_sided_p(double z) { return std::erfc(std::fabs(z) / std::sqrt(2.0)); }

namespace {
// Series for P(a, x) (Numerical Recipes 6.2), good for x < a + 1.
double gamma_p_series(double a, double x) {
  double sum = 1.0 / a, term = sum;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}
// Continued fraction for Q(a, x) (Lentz), good for x >= a + 1.
double gamma_q_fraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
// Regularised incomplete beta I_x(a, b) by continued fraction (Numerical Recipes 6.4).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m < 10000; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((a - 1.0 + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1.0 + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < 1e-15) break;
  }
  return h;
}
double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}
}  // namespace

double gamma_q(double a, double x) {
  if (x <= 0.0) return 1.0;
  if (x < a + 1.0) return 1.0 - gamma_p_series(a, x);
  return gamma_q_fraction(a, x);
}

double chi2_survival(double x, double dof) { return gamma_q(0.5 * dof, 0.5 * x); }

double student_t_two_sided_p(double t, double dof) {
  if (!std::isfinite(t)) return 0.0;
  return incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double sidak(double alpha, int m) { return 1.0 - std::pow(1.0 - alpha, 1.0 / double(m)); }

MeanTest t_test_mean(double sum, double sum_sq, double n, double expected) {
  MeanTest r;
  r.mean = sum / n;
  const double var = std::max(0.0, (sum_sq - n * r.mean * r.mean) / (n - 1.0));
  r.std_error = std::sqrt(var / n);
  if (r.std_error == 0.0) {
    // A zero-variance estimator (e.g. BSDF sampling in a white furnace) is deterministic: the
    // t-test degenerates and the mean must equal the expectation up to float32 path arithmetic
    // (a few operations of relative rounding 6e-8 each).
    const bool equal = std::abs(r.mean - expected) <= 1e-6 * std::max(1.0, std::abs(expected));
    r.t = equal ? 0.0 : std::numeric_limits<double>::infinity();
    r.p = equal ? 1.0 : 0.0;
    return r;
  }
  r.t = (r.mean - expected) / r.std_error;
  r.p = student_t_two_sided_p(r.t, n - 1.0);
  return r;
}

size_t binomial_allowed_failures(size_t n, double p, double alpha) {
  // P[X >= k] = 1 - sum_{i<k} pmf(i); accumulate the pmf in log space.
  double cdf = 0.0;
  for (size_t k = 0; k <= n; ++k) {
    const double log_pmf = std::lgamma(double(n) + 1) - std::lgamma(double(k) + 1) - std::lgamma(double(n - k) + 1) +
                           double(k) * std::log(p) + double(n - k) * std::log1p(-p);
    // Here cdf = P[X <= k-1], so 1 - cdf = P[X >= k].
    if (1.0 - cdf < alpha) return k == 0 ? 0 : k - 1;
    cdf += std::exp(log_pmf);
  }
  return n;
}

ImageZTest image_z_test(const Image& mean_a, const Image& var_a, const Image& mean_b, const Image& var_b,
                        double alpha_pixel, double alpha_image, double variance_floor) {
  ImageZTest r;
  r.pixels = mean_a.size();
  r.alpha_image = alpha_image;
  double total_var = 0;
  for (size_t i = 0; i < mean_a.size(); ++i) {
    // The film keeps no channel covariances, so the variance of the channel sum is bounded by the
    // fully correlated case, (sum of standard deviations)^2: conservative, never anti-conservative.
    double diff = 0, sd_a = 0, sd_b = 0;
    for (int c = 0; c < 3; ++c) {
      diff += double(mean_a.pixels[i][c]) - double(mean_b.pixels[i][c]);
      sd_a += std::sqrt(double(var_a.pixels[i][c]));
      sd_b += std::sqrt(double(var_b.pixels[i][c]));
    }
    const double var = sd_a * sd_a + sd_b * sd_b + variance_floor;
    r.mean_a += average(mean_a.pixels[i]);
    r.mean_b += average(mean_b.pixels[i]);
    total_var += (sd_a * sd_a + sd_b * sd_b) / 9.0;
    if (normal_two_sided_p(diff / std::sqrt(var)) < alpha_pixel) ++r.failed;
  }
  r.allowed = binomial_allowed_failures(r.pixels, alpha_pixel, alpha_image);
  const double n = double(r.pixels);
  r.mean_a /= n;
  r.mean_b /= n;
  r.mean_z = (r.mean_a - r.mean_b) / std::sqrt(total_var / (n * n) + variance_floor / n);
  r.mean_p = normal_two_sided_p(r.mean_z);
  return r;
}

std::string evidence_dir() {
  const char* env = std::getenv("PATHSPACE_TEST_EVIDENCE");
  std::filesystem::path dir = env ? env : (std::filesystem::temp_directory_path() / "pathspace-test-evidence");
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace pathspace::testing
