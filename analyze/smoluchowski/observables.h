// What the tables report about a solution: moments, the largest cluster of a
// finite system, and N(m) on the shared logarithmic bins (the same columns as
// coolgas-clusters, data-schema/tsv-tables.md "Shared table shapes").
//
// On a geometric grid a cell's clusters are spread evenly over its mass
// interval [edge_i, edge_i+1) when binned; moments use the pivot masses, which the scheme
// conserves exactly.
#pragma once
#include <vector>

#include "analyze/bins/log_bins.h"
#include "analyze/smoluchowski/grid.h"

namespace coolgas::smoluchowski {

struct Moments {
  double M0 = 0, M1 = 0, M2 = 0;  // Σ N, Σ m N, Σ m^2 N (per unit volume)
  double mean() const { return M1 / M0; }
};

Moments moments(const MassGrid& grid, const std::vector<double>& c);

// Largest m with V Σ_{m' >= m} c_{m'} >= 1: the largest cluster expected in a
// system of volume V (0 when V Σ c < 1).
double largest_mass(const MassGrid& grid, const std::vector<double>& c, double volume);

struct BinnedPoint {
  double m;   // bin centre √(lo·hi)
  double dm;  // integer masses in the bin
  double N;   // Σ c_m over the bin / dm
};

// Bins with N > 0 only, in increasing mass.
std::vector<BinnedPoint> binned_distribution(const MassGrid& grid, const std::vector<double>& c, int per_decade);

// Mass-weighted relative L1 distance between two binned distributions on the
// same bins, Σ m dm |N − N_ref| / Σ m dm N_ref: the accuracy measure.
double binned_distance(const MassGrid& grid, const std::vector<double>& c, const MassGrid& ref_grid,
                       const std::vector<double>& ref, int per_decade);

}  // namespace coolgas::smoluchowski
