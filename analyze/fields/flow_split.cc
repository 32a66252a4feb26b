#include "analyze/fields/flow_split.h"

#include <cmath>
#include <complex>
#include <numbers>

namespace coolgas {

namespace {

using Modes = std::vector<std::complex<double>>;

// The transform of momentum component a of every cell.
Modes transform(const CellFields& f, int a, FourierGrid& grid) {
  grid.clear();
  const int n = f.n;
  for (int iz = 0; iz < grid.depth(); ++iz)
    for (int iy = 0; iy < grid.height(); ++iy)
      for (int ix = 0; ix < n; ++ix)
        grid.real()[grid.real_index(ix, iy, iz)] = f.momentum[3 * (ix + std::int64_t(n) * (iy + std::int64_t(n) * iz)) + a];
  grid.forward();
  Modes out(grid.modes());
  for (std::int64_t m = 0; m < grid.modes(); ++m) out[m] = {grid.complex()[m][0], grid.complex()[m][1]};
  return out;
}

}  // namespace

FlowSplit flow_split(const CellFields& f, double temperature, FourierGrid& grid) {
  const int d = f.g.d(), n = f.n;
  std::vector<Modes> j;
  for (int a = 0; a < d; ++a) j.push_back(transform(f, a, grid));
  FlowSplit out;
  out.shells.resize(n / 2);
  for (int s = 0; s < n / 2; ++s) out.shells[s].shell = s + 1;
  const double M = f.total_mass, cells = double(f.cells()), unit = 2 * std::numbers::pi / f.L;
  std::int64_t m = 0;
  for (int iz = 0; iz < grid.depth(); ++iz)
    for (int iy = 0; iy < grid.height(); ++iy)
      for (int ix = 0; ix < grid.half(); ++ix, ++m) {
        const double k[3] = {unit * ix, unit * grid.signed_index(iy), unit * grid.signed_index(iz)};
        const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
        if (k2 == 0) continue;
        // Modes 0 < kx < n/2 stand for their conjugates too.
        const double w = ix == 0 || 2 * ix == n ? 1 : 2;
        std::complex<double> kj = 0;
        double j2 = 0;
        for (int a = 0; a < d; ++a) kj += k[a] * j[a][m], j2 += std::norm(j[a][m]);
        // With one axis every flow is along k: no transverse part, not even round-off.
        const double jl2 = std::norm(kj) / k2, jt2 = f.g.spans(1) ? std::max(0.0, j2 - jl2) : 0;
        const double el = w * jl2 / (2 * M * M), et = w * jt2 / (2 * M * M);
        out.longitudinal += el, out.transverse += et;
        out.vorticity2 += w * k2 * jt2 / (M * M);
        const int s = int(std::lround(std::sqrt(k2) / unit));
        if (s < 1 || s > n / 2) continue;
        FlowShell& sh = out.shells[s - 1];
        sh.longitudinal += el, sh.transverse += et, sh.modes += std::int64_t(w), sh.k += w * std::sqrt(k2);
      }
  for (FlowShell& sh : out.shells)
    if (sh.modes > 0) sh.k /= double(sh.modes);
  // <sum_c |j_c|^2> = d T (M - sum_c M_c^2 / M); the split's energy is that over 2 M_cell M.
  double mass2 = 0;
  for (double mc : f.mass) mass2 += mc * mc;
  const double noise = temperature * (M - mass2 / M) * cells / (2 * M * M);
  out.longitudinal_noise = noise;
  out.transverse_noise = (d - 1) * noise;
  return out;
}

}  // namespace coolgas
