// Chi-square goodness-of-fit tests of sampling routines against their densities (docs/testing.md,
// after Mitsuba's chi2.py): samples are binned on a 2D grid, expected counts come from adaptive
// Simpson integration of the density over each bin, cells with expected count < 5 are pooled, and
// a sample in a cell of zero expected mass fails at once. Extra outcomes (discrete lobes, sample
// failures) are further cells, so the test also sees mass that the sampler loses or invents.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pathspace/math/vec3.h"
#include "pathspace/sampling/rng.h"

namespace pathspace::testing {

struct Chi2Result {
  double statistic = 0, dof = 0, p_value = 0;
  std::string error;     // non-empty: failed outright (e.g. samples where the density is zero)
  std::string evidence;  // file with observed and expected counts, written when the test failed
  bool passed(double alpha) const { return error.empty() && p_value >= alpha; }
};

// Pearson chi-square with pooling of cells whose expected count is below min_expected. An expected
// count's uncertainty d (e.g. quadrature error; may be empty) widens its cell's variance to e + d^2.
Chi2Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                     const std::vector<double>& uncertainty = {}, double min_expected = 5.0);

// A rectangle [x0, x1) x [y0, y1) split into nx * ny bins.
struct Grid2 {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int nx = 51, ny = 51;
  int bins() const { return nx * ny; }
  int bin(double x, double y) const;  // -1 outside
};

// Integral of density(x, y) over every bin and an estimate of its error: adaptive Simpson
// to a relative tolerance per bin (or the absolute one where the bin is nearly empty), depth capped
// for jumps inside bins. The density is never evaluated on a bin's edge, so a jump that lies on an
// edge costs no accuracy. min_depth forces uniform refinement (for slivers of support).
struct BinIntegrals {
  std::vector<double> mass, error;
};
BinIntegrals integrate_bins(const Grid2& grid, const std::function<double(double, double)>& density,
                            double rel_tolerance = 1e-4, double abs_tolerance = 1e-11, int min_depth = 1);

// What one call of a sampler produced.
struct Outcome {
  int kind = -1;  // -1: failure; 0: a continuous sample (x, y) or direction; k > 0: discrete outcome k
  double x = 0, y = 0;
  Vec3 w;
};

struct Chi2Options {
  uint64_t samples = 1000000;
  uint64_t seed = 1;
  double alpha = 0.01;          // only decides whether evidence is written
  std::string name = "chi2";    // evidence file name
  // Probabilities of the discrete outcomes 1..n (index 0 unused).
  std::vector<double> discrete;
};

// Samples on a 2D grid against a density in the grid's coordinates.
Chi2Result grid_chi2(const Grid2& grid, const std::function<Outcome(Pcg32&)>& sample,
                     const std::function<double(double, double)>& density, const Chi2Options& options);

// Directions against a solid-angle pdf. Bins are uniform in phi around `axis` and in a polar
// coordinate t in [-1, 1] with z = sign(t) (1 - (1 - |t|)^2): the horizon (z = 0) is a bin edge,
// and bins stay narrow in theta near both poles, where peaked lobes sit.
struct SphereBins {
  Vec3 axis{0.f, 0.f, 1.f};
  int n_t = 64, n_phi = 101;  // n_t even keeps the horizon on an edge
};
Chi2Result direction_chi2(const SphereBins& bins, const std::function<Outcome(Pcg32&)>& sample,
                          const std::function<double(const Vec3&)>& pdf, const Chi2Options& options);

}  // namespace pathspace::testing
