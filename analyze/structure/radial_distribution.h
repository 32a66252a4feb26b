// The radial distribution function g(r) of particles of diameter sigma = 1 in
// a periodic box of side L, in d = 1, 2, 3 (common/geometry.h), and its
// value at contact g(sigma+).
//
// Pairs are found and measured by the shared cell list (common/close_pairs.h,
// PairsWithin) by the minimum image, so r_max <= L/2.
// Bin i holds the pairs with i/b <= r < (i + 1)/b (b = bins per sigma, so
// sigma is a bin edge). Normalisation: the pairs an ideal gas of the same
// N in the same box puts in the bin on average,
//   g_i = pairs_i / (N (N - 1) / 2 * V_i / L^d),   V_i = ball(r_hi) - ball(r_lo)
// (ball: 2r, pi r^2, 4 pi r^3 / 3), so uniform random points give exactly 1
// on average at every r, with no 1/N bias. Over several frames the pairs
// and the ideal-gas expectations are summed before dividing.
//
// g(sigma+) is extrapolated from the first `contact_bins` bins above sigma
// by the maximum-likelihood fit of g(r) = g(sigma+) exp(-kappa (r - sigma))
// to their pair counts (each Poisson of mean the ideal count times g at the
// bin's centre): an exponential, because the equilibrium hard-sphere g(r)
// falls near contact with little curvature of ln g, and a Poisson fit,
// because it stays unbiased when a frame has few pairs per bin (a fit of
// ln g is not, and takes no empty bin). Its error is the fit's (the inverse
// Fisher information), treating pairs as independent. With pairs in fewer
// than two of those bins the slope is undetermined: g(sigma+) is then their
// mean g, and 0 with no pair at all.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

struct RdfBin {
  double r = 0;      // bin centre [sigma]
  double g = 0;      // pairs over the ideal gas's pairs
  double g_err = 0;  // g / sqrt(pairs) (Poisson)
  double pairs = 0;  // pairs counted (summed over the frames)
};

struct ContactValue {
  double g = 0;      // g(sigma+)
  double err = 0;    // its standard error from the fit
  double kappa = 0;  // -d ln g / dr at sigma+ [1/sigma]
  double pairs = 0;  // pairs in the fit's bins
};

class PairDistances {
 public:
  // Bins of width 1/bins_per_sigma from 0 up to r_max (r_max * bins_per_sigma
  // of them, rounded down: r_max() is the last bin's upper edge); the caller
  // has checked the options (check_rdf_options in structure_table.h).
  PairDistances(Geometry g, double r_max, int bins_per_sigma);

  // Counts the pairs of one frame: positions x0 y0 z0 x1 ... inside [0, L)
  // (the coordinates past the dimension 0). r_max <= L/2 is the caller's.
  void add(double L, std::span<const double> positions);
  // Forgets every frame added.
  void clear();

  std::vector<RdfBin> bins() const;
  ContactValue contact(int contact_bins) const;
  double r_max() const { return r_max_; }

 private:
  double ideal_pairs(std::size_t bin) const;  // over all frames added

  Geometry g_;
  double r_max_;
  int per_sigma_;
  std::vector<std::uint64_t> pairs_;
  double pair_density_ = 0;  // sum over frames of N (N - 1) / (2 L^d)
};

}  // namespace coolgas
