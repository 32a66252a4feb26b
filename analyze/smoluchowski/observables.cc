#include "analyze/smoluchowski/observables.h"

#include <algorithm>
#include <cmath>

namespace coolgas::smoluchowski {

Moments moments(const MassGrid& grid, const std::vector<double>& c) {
  Moments m;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double x = grid.mass[i];
    m.M0 += c[i];
    m.M1 += x * c[i];
    m.M2 += x * x * c[i];
  }
  return m;
}

double largest_mass(const MassGrid& grid, const std::vector<double>& c, double volume) {
  const double need = 1.0 / volume;  // concentration of one cluster
  double above = 0;                  // Σ c over masses above the current cell
  for (std::size_t i = grid.size(); i-- > 0;) {
    if (above + c[i] >= need) {
      // Within the cell the clusters are spread evenly over its interval;
      // integer mass m stands for [m − ½, m + ½).
      const double per_mass = c[i] / grid.width(i);
      return std::floor(grid.edge[i + 1] + 0.5 - (need - above) / per_mass + 1e-12);
    }
    above += c[i];
  }
  return 0;
}

namespace {

// Σ c over each log bin, the clusters of a cell spread evenly over its
// interval; bin [lo, hi] of integer masses covers [lo − ½, hi + ½).
std::vector<double> bin_sums(const MassGrid& grid, const std::vector<double>& c, const LogBins& bins) {
  std::vector<double> sum(bins.size(), 0.0);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (c[i] == 0) continue;
    const double a = grid.edge[i], b = grid.edge[i + 1], per_mass = c[i] / (b - a);
    for (int k = bins.index(static_cast<std::int64_t>(std::floor(a + 0.5))); k < bins.size(); ++k) {
      const double lo = double(bins.lo(k)) - 0.5, hi = double(bins.hi(k)) + 0.5;
      if (lo >= b) break;
      sum[k] += per_mass * (std::min(b, hi) - std::max(a, lo));
    }
  }
  return sum;
}

}  // namespace

std::vector<BinnedPoint> binned_distribution(const MassGrid& grid, const std::vector<double>& c, int per_decade) {
  const LogBins bins(per_decade, grid.cutoff());
  const auto sum = bin_sums(grid, c, bins);
  std::vector<BinnedPoint> out;
  for (int b = 0; b < bins.size(); ++b)
    if (sum[b] > 0) out.push_back({bins.center(b), double(bins.width(b)), sum[b] / double(bins.width(b))});
  return out;
}

double binned_distance(const MassGrid& grid, const std::vector<double>& c, const MassGrid& ref_grid,
                       const std::vector<double>& ref, int per_decade) {
  const LogBins bins(per_decade, std::max(grid.cutoff(), ref_grid.cutoff()));
  const auto a = bin_sums(grid, c, bins), b = bin_sums(ref_grid, ref, bins);
  double diff = 0, norm = 0;
  for (int k = 0; k < bins.size(); ++k) {
    diff += bins.center(k) * std::abs(a[k] - b[k]);
    norm += bins.center(k) * b[k];
  }
  return diff / norm;
}

}  // namespace coolgas::smoluchowski
