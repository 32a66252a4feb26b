// Everything coolgas-structure measures on one frame, on one reusable
// FourierGrid: S(k) of the (mass-weighted) density, the pair correlation of
// the coarse-grained density, and that of the coarse-grained momentum field
//   p(x) = sum_j m_j v_j (CIC-assigned),  C_v(r) = <dp(x).dp(x + r)> / <|dp|^2>.
#pragma once
#include <span>
#include <vector>

#include "analyze/structure/cloud_in_cell.h"
#include "analyze/structure/correlation.h"
#include "analyze/fourier/fourier_grid.h"
#include "analyze/structure/structure_factor.h"

namespace coolgas {

class FrameStructure {
 public:
  FrameStructure(int n, Geometry g) : grid_(n, g) {}
  int n() const { return grid_.n(); }
  Geometry geometry() const { return grid_.geometry(); }

  // S(k) shells of the points (weights: one per point, empty = 1 each).
  // Leaves the density's transform in the grid for density_correlation().
  std::vector<Shell> spectrum(double L, std::span<const double> positions, std::span<const double> weights);
  // C(r) of the CIC density; call right after spectrum().
  std::vector<CorrelationBin> density_correlation(double L);
  // C_v(r) of the momentum field (velocities x0 y0 z0 x1 ...; its d components).
  std::vector<CorrelationBin> momentum_correlation(double L, std::span<const double> positions,
                                                   std::span<const double> velocities, std::span<const double> weights);

 private:
  FourierGrid grid_;
  CloudInCell cic_;
  std::vector<double> power_, component_;
};

}  // namespace coolgas
