// The pair correlation of a coarse-grained field on a FourierGrid: the
// field's autocorrelation
//   C(r) = <df(x) df(x + r)> / <df(x)^2>,  df = f - <f>,
// over the grid points x, computed from the power spectrum (Wiener-Khinchin:
// one inverse FFT of |f(k)|^2 with k = 0 left out) and averaged over
// spherical shells of |r| one grid spacing h wide, up to L/2.
// The coarse-grained density is the cloud-in-cell density itself (smoothed
// over one grid spacing); its self term reaches to |r_a| < 2h only, so the
// zero crossing of a clustered field, at the cluster scale, is not shifted.
#pragma once
#include <vector>

#include "analyze/fourier/fourier_grid.h"

namespace coolgas {

struct CorrelationBin {
  double r = 0;       // mean |r| of the grid separations in the bin [sigma]
  double C = 0;       // mean C over them
  double points = 0;  // grid separations in the bin
};

// Accumulates |f(k)|^2 of a transformed grid into `power` (grid.modes() numbers).
void add_power(const FourierGrid& grid, std::vector<double>& power);

// C(r) from an accumulated power spectrum; uses `grid` as scratch.
// Bins 0 .. n/2 (bin 0 holds r = 0, where C = 1).
std::vector<CorrelationBin> radial_correlation(FourierGrid& grid, double L, const std::vector<double>& power);

// The first r at which C falls to zero, linear between the bins on either
// side; 0 if C stays positive up to L/2.
double first_zero(const std::vector<CorrelationBin>& c);

}  // namespace coolgas
