#include "analyze/smoluchowski/geometric.h"

#include <algorithm>
#include <cmath>

#include "analyze/smoluchowski/direct.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

MassGrid geometric_grid(std::int64_t M, double ratio) {
  if (!(ratio > 1) || !std::isfinite(ratio))
    throw InputError("grid ratio must be a number > 1, got " + format_number(ratio));
  std::vector<std::int64_t> x{1};
  while (true) {
    const auto next = std::max(x.back() + 1, static_cast<std::int64_t>(std::llround(double(x.back()) * ratio)));
    if (next >= M) break;
    x.push_back(next);
  }
  // The cut-off is the last pivot; merge it with a too-close predecessor.
  if (x.size() > 1 && 2 * (M - x.back()) < x.back() - x[x.size() - 2]) x.back() = M;
  else if (x.back() != M) x.push_back(M);
  MassGrid g;
  g.edge.push_back(0.5);
  for (std::size_t i = 0; i < x.size(); ++i) {
    g.mass.push_back(static_cast<double>(x[i]));
    g.edge.push_back(i + 1 < x.size() ? 0.5 * double(x[i] + x[i + 1]) : double(M) + 0.5);
  }
  return g;
}

GeometricRhs::GeometricRhs(const Kernel& kernel, std::int64_t M, double ratio)
    : grid_(geometric_grid(M, ratio)), powers_(kernel, grid_.mass) {}

void GeometricRhs::evaluate(const double* c, double* dcdt) {
  const std::size_t n = grid_.size();
  const double* x = grid_.mass.data();
  std::fill(dcdt, dcdt + n, 0.0);
  std::vector<double> loss(n, 0.0);
  const long top = last_nonzero(c, n);
  for (long i = 0; i <= top; ++i) {
    if (i % 1024 == 0 && interrupted()) return;  // the integrator stops the step (integrator.h)
    if (c[i] == 0) continue;
    // Pivot k below v = x_i + x_j only moves up as j grows: walk it along.
    std::size_t k = std::upper_bound(x, x + n, x[i] + x[i]) - x - 1;
    for (long j = i; j <= top; ++j) {
      const double kij = powers_.k(i, j);
      loss[i] += kij * c[j];
      if (j != i) loss[j] += kij * c[i];
      const double rate = (i == j ? 0.5 : 1.0) * kij * c[i] * c[j];
      const double v = x[i] + x[j];
      while (k + 1 < n && x[k + 1] <= v) ++k;
      if (v > x[n - 1] || rate == 0) continue;  // beyond the cut-off: leaks out
      if (v == x[k]) {
        dcdt[k] += rate;
      } else {
        const double eta = (x[k + 1] - v) / (x[k + 1] - x[k]);
        dcdt[k] += eta * rate;
        dcdt[k + 1] += (1 - eta) * rate;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) dcdt[i] -= c[i] * loss[i];
}

}  // namespace coolgas::smoluchowski
