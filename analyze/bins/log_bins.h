// Logarithmic bins over the positive integers (cluster masses), shared by
// coolgas-clusters and coolgas-smoluchowski so their N(m,t) tables line up.
//
// Bin k holds the integer masses [lo(k), hi(k)]. Edges are the integers
// ceil(10^(k/per_decade)), merged where two would coincide, so small masses
// get one bin each and large masses a constant logarithmic width.
#pragma once
#include <cstdint>
#include <vector>

namespace coolgas {

class LogBins {
 public:
  // Bins covering masses 1..m_max with `per_decade` bins per decade (>= 1).
  LogBins(int per_decade, std::int64_t m_max);
  int size() const { return static_cast<int>(lo_.size()); }
  std::int64_t lo(int k) const { return lo_[k]; }
  std::int64_t hi(int k) const { return hi_[k]; }
  // Number of integer masses in bin k (the bin width for a density per unit mass).
  std::int64_t width(int k) const { return hi_[k] - lo_[k] + 1; }
  // Geometric centre sqrt(lo*hi), the abscissa to plot.
  double center(int k) const;
  // Bin holding mass m (1 <= m <= m_max).
  int index(std::int64_t m) const;

 private:
  std::vector<std::int64_t> lo_, hi_;
};

}  // namespace coolgas
