#include "support/chi2.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "pathspace/math/frame.h"
#include "support/statistics.h"

namespace pathspace::testing {

Chi2Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                     const std::vector<double>& uncertainty, double min_expected) {
  Chi2Result r;
  struct Cell {
    double o, e, d;
  };
  std::vector<Cell> cells;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] > 0) {
      cells.push_back({observed[i], expected[i], uncertainty.empty() ? 0.0 : uncertainty[i]});
    } else if (observed[i] > 0) {
      r.error = "cell " + std::to_string(i) + " has " + std::to_string(observed[i]) + " samples but zero expected mass";
      return r;
    }
  }
  // Pool the cells with small expected counts (Mitsuba's chi2.py does the same).
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.e < b.e; });
  Cell pool{0, 0, 0};
  std::vector<Cell> kept;
  for (const Cell& c : cells) {
    if (c.e < min_expected) {
      pool.o += c.o;
      pool.e += c.e;
      pool.d += c.d;
    } else {
      kept.push_back(c);
    }
  }
  if (pool.e >= min_expected || kept.empty()) {
    kept.push_back(pool);
  } else if (pool.e > 0) {  // too small on its own: merge into the smallest kept cell
    kept.front().o += pool.o;
    kept.front().e += pool.e;
    kept.front().d += pool.d;
  }
  // The quadrature error of an expected count adds to its variance (Poisson: e).
  for (const Cell& c : kept) r.statistic += (c.o - c.e) * (c.o - c.e) / (c.e + c.d * c.d);
  r.dof = double(kept.size()) - 1.0;
  if (r.dof < 1) {
    r.error = "fewer than two cells with enough expected samples";
    return r;
  }
  r.p_value = chi2_survival(r.statistic, r.dof);
  return r;
}

int Grid2::bin(double x, double y) const {
  // The upper edges are closed: the pole (t = 1) and phi = 2 pi after rounding are in the grid.
  const int i = std::min(int(std::floor((x - x0) / (x1 - x0) * nx)), x == x1 ? nx - 1 : nx);
  const int j = std::min(int(std::floor((y - y0) / (y1 - y0) * ny)), y == y1 ? ny - 1 : ny);
  if (i < 0 || i >= nx || j < 0 || j >= ny) return -1;
  return j * nx + i;
}

namespace {

// Adaptive 2D Simpson: a rectangle with known 3x3 node values is split into four (16 new
// evaluations) until the children agree with their parent. Accumulates an error estimate:
// |children - parent| / 15 where converged, the full difference where the depth cap stopped it
// (a jump inside the bin).
struct Quadrature {
  const std::function<double(double, double)>& f;
  int min_depth = 1;
  double error = 0;
  static constexpr int kMaxDepth = 8;

  static double rule(double area, const double v[3][3]) {
    static constexpr double w[3] = {1, 4, 1};
    double s = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s += w[i] * w[j] * v[i][j];
    return s * area / 36.0;
  }

  double refine(double x0, double x1, double y0, double y1, const double v[3][3], double whole, double tol, int depth) {
    double g[5][5];
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        g[i][j] = (i % 2 == 0 && j % 2 == 0) ? v[i / 2][j / 2] : f(x0 + (x1 - x0) * i / 4.0, y0 + (y1 - y0) * j / 4.0);
    const double area = (x1 - x0) * (y1 - y0) / 4.0;
    double child[2][2][3][3], part[2][2], sum = 0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) child[a][b][i][j] = g[2 * a + i][2 * b + j];
        sum += part[a][b] = rule(area, child[a][b]);
      }
    const double diff = std::fabs(sum - whole);
    if (depth >= min_depth && diff <= 15.0 * tol) {
      error += diff / 15.0;
      return sum + (sum - whole) / 15.0;  // Richardson
    }
    if (depth >= kMaxDepth) {
      error += diff;
      return sum;
    }
    const double xs[3] = {x0, 0.5 * (x0 + x1), x1}, ys[3] = {y0, 0.5 * (y0 + y1), y1};
    double total = 0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        total += refine(xs[a], xs[a + 1], ys[b], ys[b + 1], child[a][b], part[a][b], tol / 4.0, depth + 1);
    return total;
  }
};

void write_evidence(Chi2Result* r, const std::string& name, const Grid2& grid, const std::vector<double>& observed,
                    const std::vector<double>& expected) {
  r->evidence = evidence_dir() + "/" + name + ".txt";
  std::ofstream out(r->evidence);
  out << "# " << name << ": chi2 " << r->statistic << " dof " << r->dof << " p " << r->p_value << " " << r->error
      << "\n# grid " << grid.nx << " x " << grid.ny << " over [" << grid.x0 << ", " << grid.x1 << ") x [" << grid.y0
      << ", " << grid.y1 << "); rows are y; extra cells (discrete outcomes, failures) last\n# observed\n";
  auto dump = [&](const std::vector<double>& v) {
    for (size_t i = 0; i < v.size(); ++i)
      out << v[i] << ((i + 1) % size_t(grid.nx) == 0 || i + 1 == v.size() ? "\n" : " ");
  };
  dump(observed);
  out << "# expected\n";
  dump(expected);
}

}  // namespace

BinIntegrals integrate_bins(const Grid2& grid, const std::function<double(double, double)>& density,
                            double rel_tolerance, double abs_tolerance, int min_depth) {
  BinIntegrals r;
  r.mass.resize(size_t(grid.bins()));
  r.error.resize(size_t(grid.bins()));
  const double dx = (grid.x1 - grid.x0) / grid.nx, dy = (grid.y1 - grid.y0) / grid.ny;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double x0 = grid.x0 + i * dx, y0 = grid.y0 + j * dy;
      // Points on the bin's edges are moved inside by 1e-4 of the bin: a density that jumps on an
      // edge (the horizon, t = 0) is then seen from inside the bin and costs no accuracy.
      const double ex = 1e-4 * dx, ey = 1e-4 * dy;
      const std::function<double(double, double)> f = [&](double x, double y) {
        x = x == x0 ? x0 + ex : (x == x0 + dx ? x0 + dx - ex : x);
        y = y == y0 ? y0 + ey : (y == y0 + dy ? y0 + dy - ey : y);
        return density(x, y);
      };
      Quadrature q{f, min_depth};
      double v[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) v[a][b] = f(x0 + a * dx / 2, y0 + b * dy / 2);
      const double whole = Quadrature::rule(dx * dy, v);
      const double tol = std::max(rel_tolerance * std::fabs(whole), abs_tolerance);
      const size_t k = size_t(j) * grid.nx + i;
      r.mass[k] = q.refine(x0, x0 + dx, y0, y0 + dy, v, whole, tol, 0);
      r.error[k] = q.error;
    }
  return r;
}

Chi2Result grid_chi2(const Grid2& grid, const std::function<Outcome(Pcg32&)>& sample,
                     const std::function<double(double, double)>& density, const Chi2Options& options) {
  const size_t bins = size_t(grid.bins()), extra = options.discrete.empty() ? 0 : options.discrete.size() - 1;
  const size_t failure_cell = bins + extra;
  const double total = double(options.samples);
  const BinIntegrals integrals = integrate_bins(grid, density);
  std::vector<double> observed(bins + extra + 1, 0.0), expected(observed.size()), uncertainty(observed.size(), 0.0);
  double mass = 0, mass_error = 0;
  for (size_t i = 0; i < bins; ++i) {
    mass += (expected[i] = integrals.mass[i] * total);
    mass_error += (uncertainty[i] = integrals.error[i] * total);
  }
  for (size_t k = 0; k < extra; ++k) mass += (expected[bins + k] = options.discrete[k + 1] * total);

  Pcg32 rng(options.seed, 0x9e3779b97f4a7c15ull);
  std::string error;
  std::vector<int> missed;  // bins with samples but no mass found by the quadrature
  for (uint64_t n = 0; n < options.samples; ++n) {
    const Outcome o = sample(rng);
    if (o.kind == 0) {
      const int b = grid.bin(o.x, o.y);
      if (b < 0) {
        if (error.empty()) error = "sample (" + std::to_string(o.x) + ", " + std::to_string(o.y) + ") outside the grid";
        continue;
      }
      if (expected[size_t(b)] == 0.0 && observed[size_t(b)] == 0.0) missed.push_back(b);
      observed[size_t(b)] += 1;
    } else if (o.kind > 0 && size_t(o.kind) <= extra) {
      observed[bins + size_t(o.kind) - 1] += 1;
    } else {
      observed[failure_cell] += 1;
    }
  }
  // A sliver of support the adaptive quadrature may have stepped over: integrate such bins on a
  // fine grid. Where that finds no mass either, chi2_test fails (samples where the density is 0).
  const double dx = (grid.x1 - grid.x0) / grid.nx, dy = (grid.y1 - grid.y0) / grid.ny;
  for (const int b : missed) {
    const double x0 = grid.x0 + (b % grid.nx) * dx, y0 = grid.y0 + (b / grid.nx) * dy;
    const BinIntegrals fine = integrate_bins({x0, x0 + dx, y0, y0 + dy, 1, 1}, density, 1e-4, 1e-11, 5);
    mass += (expected[size_t(b)] = fine.mass[0] * total);
    mass_error += (uncertainty[size_t(b)] = fine.error[0] * total);
  }
  // What the density does not account for must be lost samples; it carries the summed
  // integration error. Never exactly zero, so a few legitimate failures are not an outright error.
  expected[failure_cell] = std::max(total - mass, 1e-6);
  uncertainty[failure_cell] = mass_error;
  Chi2Result r = chi2_test(observed, expected, uncertainty);
  if (!error.empty()) r.error = error;
  if (!r.passed(options.alpha)) write_evidence(&r, options.name, grid, observed, expected);
  return r;
}

Chi2Result direction_chi2(const SphereBins& bins, const std::function<Outcome(Pcg32&)>& sample,
                          const std::function<double(const Vec3&)>& pdf, const Chi2Options& options) {
  const Frame frame(normalize(bins.axis));
  const Grid2 grid{-1.0, 1.0, 0.0, 2.0 * M_PI, bins.n_t, bins.n_phi};
  auto to_grid = [&](Outcome o) {
    if (o.kind != 0) return o;
    const Vec3 w = frame.to_local(normalize(o.w));
    const double z = w.z, r2 = double(w.x) * w.x + double(w.y) * w.y;
    const double one_minus_abs_z = r2 / (1.0 + std::fabs(z));  // 1 - |z| without cancellation
    o.x = std::copysign(1.0 - std::sqrt(one_minus_abs_z), z);
    o.y = std::atan2(double(w.y), double(w.x));
    if (o.y < 0) o.y += 2.0 * M_PI;
    return o;
  };
  auto density = [&](double t, double phi) {
    const double s = 1.0 - std::fabs(t), one_minus_abs_z = s * s;
    const double z = std::copysign(1.0 - one_minus_abs_z, t);
    const double r = std::sqrt(std::max(0.0, one_minus_abs_z * (2.0 - one_minus_abs_z)));
    const Vec3 local(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    return pdf(frame.to_world(local)) * 2.0 * s;  // dz/dt = 2 (1 - |t|), d(omega) = dz dphi
  };
  return grid_chi2(grid, [&](Pcg32& rng) { return to_grid(sample(rng)); }, density, options);
}

}  // namespace pathspace::testing
