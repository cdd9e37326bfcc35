// Hypothesis-test helpers for the test suite (docs/testing.md): normal, Student t and chi-square
// tail probabilities, Sidak correction, and a per-pixel z-test of two images with variances.
#pragma once

#include <cstddef>
#include <string>

#include "pathspace/film/image.h"

namespace pathspace::testing {

double normal_cdf(double z);
// Two-sided p-value of a standard normal statistic.
double normal_two_sided_p(double z);
// Regularised upper incomplete gamma Q(a, x).
double gamma_q(double a, double x);
// P[X >= x] for X ~ chi-square with dof degrees of freedom.
double chi2_survival(double x, double dof);
// Two-sided p-value of Student's t with dof degrees of freedom.
double student_t_two_sided_p(double t, double dof);
// Per-test significance that keeps the family-wise error at alpha over m tests.
double sidak(double alpha, int m);

// One-sample t-test of mean == expected from running moments.
struct MeanTest {
  double mean = 0, std_error = 0, t = 0, p = 1;
};
MeanTest t_test_mean(double sum, double sum_sq, double n, double expected);

// Per-pixel z-test of two independent estimates a, b with variance-of-the-mean images. The test
// statistic is the pixel's channel sum (channels of one pixel are strongly correlated, so testing
// them separately would count one deviation three times). A pixel fails when its two-sided p-value
// is below alpha_pixel; variance_floor keeps black or noiseless pixels from failing on rounding.
// The image passes when the number of failing pixels is not improbable under H0:
// P[Binomial(pixels, alpha_pixel) >= failed] >= alpha_image.
// Independently of the per-pixel counts, the image averages of the two estimates must agree (a
// two-sample z-test on the mean over all pixels, p >= alpha_image): this has the power to see a
// small bias spread over the whole image that no single pixel reveals.
struct ImageZTest {
  size_t pixels = 0, failed = 0;
  size_t allowed = 0;      // largest failure count that still passes
  double mean_a = 0, mean_b = 0, mean_z = 0, mean_p = 1;
  double alpha_image = 0;
  bool passed() const { return failed <= allowed && mean_p >= alpha_image; }
};
ImageZTest image_z_test(const Image& mean_a, const Image& var_a, const Image& mean_b, const Image& var_b,
                        double alpha_pixel, double alpha_image, double variance_floor = 1e-8);
// Smallest k with P[Binomial(n, p) >= k] < alpha, minus one: the most failures a test may see.
size_t binomial_allowed_failures(size_t n, double p, double alpha);

// Folder for evidence of failing statistical tests (created on demand); prints nothing itself.
std::string evidence_dir();

}  // namespace pathspace::testing
