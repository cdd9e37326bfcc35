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

// Per-pixel-channel z-test of two independent estimates a, b with variance-of-the-mean images.
// A channel fails when its two-sided p-value is below alpha_pixel. variance_floor keeps black or
// noiseless pixels from failing on rounding.
struct ImageZTest {
  size_t channels = 0, failed = 0;
  double failed_fraction() const { return channels ? double(failed) / double(channels) : 0.0; }
};
ImageZTest image_z_test(const Image& mean_a, const Image& var_a, const Image& mean_b, const Image& var_b,
                        double alpha_pixel, double variance_floor = 1e-8);

// Folder for evidence of failing statistical tests (created on demand); prints nothing itself.
std::string evidence_dir();

}  // namespace pathspace::testing
