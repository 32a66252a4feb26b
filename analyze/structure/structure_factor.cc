#include "analyze/structure/structure_factor.h"

#include <cmath>
#include <complex>

#include "analyze/structure/cloud_in_cell.h"
#include "common/interrupt.h"

namespace coolgas {

int shell_of(long m2) {
  // Integer arithmetic: s is the shell when (s - 1/2)^2 <= m2 < (s + 1/2)^2, i.e. s^2 - s < m2 <= s^2 + s.
  long s = std::lround(std::sqrt(double(m2)));
  while (s * s + s < m2) ++s;
  while (s > 0 && s * s - s >= m2) --s;
  return int(s);
}

Weights weights_of(std::span<const double> weights, std::size_t points) {
  if (weights.empty()) return {double(points), 1.0};
  double m = 0, m2 = 0;
  for (double w : weights) m += w, m2 += w * w;
  return {m, m2 / m};
}

namespace {

struct ShellSums {
  double weight = 0, k = 0, S = 0, S2 = 0;
};

// Per-axis window tables, indexed by the row index 0..n-1.
struct AxisTables {
  std::vector<double> window, alias;
  explicit AxisTables(const FourierGrid& g) : window(g.n()), alias(g.n()) {
    for (int i = 0; i < g.n(); ++i) {
      const double u = double(g.signed_index(i)) / g.n();
      window[i] = cic_window(u);
      alias[i] = cic_alias_sum(u);
    }
  }
};

}  // namespace

std::vector<Shell> shell_average(const FourierGrid& grid, double L, const Weights& w) {
  const int n = grid.n(), last = n / 4;
  const AxisTables t(grid);
  std::vector<ShellSums> sums(last + 1);
  const fftw_complex* f = grid.complex();
  const double dk = 2 * M_PI / L;
  for (int iz = 0; iz < grid.depth(); ++iz) {
    // A plane is at most 1024^2 modes, milliseconds: a 1024^3 grid's
    // average (seconds) stops within one (common/interrupt.h).
    throw_if_interrupted("within a dump (its S(k) shells); no table written");
    const long c = grid.signed_index(iz);
    for (int iy = 0; iy < grid.height(); ++iy) {
      const long b = grid.signed_index(iy);
      const fftw_complex* row = f + std::int64_t(grid.half()) * (iy + std::int64_t(grid.height()) * iz);
      for (int a = 0; a < grid.half(); ++a) {
        const long m2 = long(a) * a + b * b + c * c;
        if (m2 == 0 || m2 > long(last) * last + last) continue;
        const int s = shell_of(m2);
        const double W = t.window[a] * t.window[iy] * t.window[iz];
        const double C1 = t.alias[a] * t.alias[iy] * t.alias[iz];
        const double P = (row[a][0] * row[a][0] + row[a][1] * row[a][1]) / w.total;
        const double S = w.shot + (P - w.shot * C1) / (W * W);
        // Modes with 0 < a < n/2 stand for themselves and their conjugates.
        const double weight = (a == 0 || a == n / 2) ? 1.0 : 2.0;
        ShellSums& sum = sums[s];
        sum.weight += weight;
        sum.k += weight * dk * std::sqrt(double(m2));
        sum.S += weight * S;
        sum.S2 += weight * S * S;
      }
    }
  }
  std::vector<Shell> out;
  for (int s = 1; s <= last; ++s) {
    const ShellSums& sum = sums[s];
    if (sum.weight == 0) continue;
    const double mean = sum.S / sum.weight, independent = sum.weight / 2;
    const double var = std::max(0.0, sum.S2 / sum.weight - mean * mean);
    const double err = independent > 1 ? std::sqrt(var / (independent - 1)) : mean;
    out.push_back({s, sum.k / sum.weight, mean, err, independent});
  }
  return out;
}

namespace {

// e^{-2 pi i u} for any real u, to round-off, without a sin and cos per call:
// a table of 4096 unit phases times the Taylor series of the remainder
// e^{-i d}, 0 <= d < 2 pi/4096, to fifth order (truncation d^6/720 < 2e-20).
// Three calls per particle are most of the exact sum's cost.
class UnitPhase {
 public:
  UnitPhase() {
    for (int j = 0; j < kTable; ++j) table_[j] = std::polar(1.0, -2 * M_PI * j / kTable);
  }
  std::complex<double> operator()(double u) const {
    const double v = (u - std::floor(u)) * kTable;
    int j = static_cast<int>(v);
    const double d = 2 * M_PI / kTable * (v - j);
    j &= kTable - 1;  // v rounded up to kTable
    const double d2 = d * d;
    const double re = 1 - d2 / 2 * (1 - d2 / 12), im = -d * (1 - d2 / 6 * (1 - d2 / 20));
    const std::complex<double> t = table_[j];  // product written out: see below
    return {t.real() * re - t.imag() * im, t.real() * im + t.imag() * re};
  }

 private:
  static constexpr int kTable = 4096;
  std::complex<double> table_[kTable];
};

}  // namespace

std::vector<double> direct_structure_factor(double L, std::span<const double> positions,
                                            std::span<const double> weights, int max_shell, Geometry g) {
  // The modes of shells 1..max_shell in one half space (k and -k give the same |rho|^2).
  struct Mode {
    int a, b, c, shell;
  };
  std::vector<Mode> modes;
  const int b_max = g.spans(1) ? max_shell : 0, c_max = g.spans(2) ? max_shell : 0;  // 2D: c = 0; 1D: b = 0
  for (int c = 0; c <= c_max; ++c)
    for (int b = -b_max; b <= b_max; ++b)
      for (int a = -max_shell; a <= max_shell; ++a) {
        if (c == 0 && (b < 0 || (b == 0 && a <= 0))) continue;
        const int s = shell_of(long(a) * a + long(b) * b + long(c) * c);
        if (s <= max_shell) modes.push_back({a, b, c, s});
      }
  // Complex products written out: std::complex's operator* checks for
  // infinities (__muldc3) and would cost more than everything else here.
  struct C {
    double re = 0, im = 0;
  };
  auto mul = [](C a, C b) { return C{a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; };
  const int span = 2 * max_shell + 1;
  std::vector<C> rho(modes.size()), px(span), py(span), pz(span);
  const std::size_t count = positions.size() / 3;
  static const UnitPhase phase;
  // e^{-i a (2 pi/L) x} for a = -max..max from one phase per coordinate.
  auto powers = [&](double x, std::vector<C>& p) {
    const std::complex<double> e0 = phase(x / L);
    const C e{e0.real(), e0.imag()};
    p[max_shell] = {1, 0};
    for (int a = 1; a <= max_shell; ++a) {
      p[max_shell + a] = mul(p[max_shell + a - 1], e);
      p[max_shell - a] = {p[max_shell + a].re, -p[max_shell + a].im};
    }
  };
  for (std::size_t j = 0; j < count; ++j) {
    const double m = weights.empty() ? 1.0 : weights[j];
    powers(positions[3 * j], px);
    powers(positions[3 * j + 1], py);
    powers(positions[3 * j + 2], pz);
    for (std::size_t q = 0; q < modes.size(); ++q) {
      const Mode& k = modes[q];
      const C e = mul(mul(px[max_shell + k.a], py[max_shell + k.b]), pz[max_shell + k.c]);
      rho[q].re += m * e.re;
      rho[q].im += m * e.im;
    }
  }
  const Weights w = weights_of(weights, count);
  std::vector<double> S(max_shell + 1, 0.0), per(max_shell + 1, 0.0);
  for (std::size_t q = 0; q < modes.size(); ++q) {
    S[modes[q].shell] += (rho[q].re * rho[q].re + rho[q].im * rho[q].im) / w.total;
    per[modes[q].shell] += 1;
  }
  std::vector<double> out;
  for (int s = 1; s <= max_shell; ++s) out.push_back(per[s] > 0 ? S[s] / per[s] : 0.0);
  return out;
}

}  // namespace coolgas
