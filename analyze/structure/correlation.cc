#include "analyze/structure/correlation.h"

#include <cmath>

#include "common/interrupt.h"

namespace coolgas {

void add_power(const FourierGrid& grid, std::vector<double>& power) {
  power.resize(std::size_t(grid.modes()), 0.0);
  const fftw_complex* f = grid.complex();
  for (std::int64_t q = 0; q < grid.modes(); ++q) power[q] += f[q][0] * f[q][0] + f[q][1] * f[q][1];
  power[0] = 0;  // the mean is not part of the fluctuation
}

std::vector<CorrelationBin> radial_correlation(FourierGrid& grid, double L, const std::vector<double>& power) {
  fftw_complex* f = grid.complex();
  for (std::int64_t q = 0; q < grid.modes(); ++q) f[q][0] = power[q], f[q][1] = 0;
  grid.inverse();
  const int n = grid.n(), last = n / 2;
  const double h = L / n;
  std::vector<double> sum(last + 1, 0.0), rsum(last + 1, 0.0), count(last + 1, 0.0);
  const double* g = grid.real();
  for (int iz = 0; iz < grid.depth(); ++iz) {
    throw_if_interrupted("within a dump (its correlation C(r)); no table written");  // per plane, as shell_average
    for (int iy = 0; iy < grid.height(); ++iy)
      for (int ix = 0; ix < n; ++ix) {
        const long x = grid.signed_index(ix), y = grid.signed_index(iy), z = grid.signed_index(iz);
        const double r = std::sqrt(double(x * x + y * y + z * z));
        const long bin = std::lround(r);
        if (bin > last) continue;
        sum[bin] += g[grid.real_index(ix, iy, iz)];
        rsum[bin] += r * h;
        count[bin] += 1;
      }
  }
  const double c0 = g[0];
  std::vector<CorrelationBin> out;
  for (int b = 0; b <= last; ++b)
    if (count[b] > 0) out.push_back({rsum[b] / count[b], c0 > 0 ? sum[b] / count[b] / c0 : 0.0, count[b]});
  return out;
}

double first_zero(const std::vector<CorrelationBin>& c) {
  for (std::size_t b = 1; b < c.size(); ++b)
    if (c[b].C <= 0) {
      const CorrelationBin& p = c[b - 1];
      return p.r + (c[b].r - p.r) * p.C / (p.C - c[b].C);
    }
  return 0;
}

}  // namespace coolgas
