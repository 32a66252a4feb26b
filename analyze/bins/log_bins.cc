#include "analyze/bins/log_bins.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"

namespace coolgas {

LogBins::LogBins(int per_decade, std::int64_t m_max) {
  if (per_decade < 1) throw InputError("bins per decade must be >= 1, got " + std::to_string(per_decade));
  if (m_max < 1) throw InputError("largest mass must be >= 1, got " + std::to_string(m_max));
  std::int64_t lo = 1;
  // k runs to per_decade log10(m_max), beyond 2^31 for a large per_decade,
  // so it is 64-bit; and since only edges above lo make bins, it jumps over
  // the run of edges that cannot (10^(k/per_decade) <= lo 10^(-2/per_decade)),
  // so the loop takes O(bins), not O(per_decade) steps (10^9 bins per decade
  // took minutes). Every edge it meets is the one the plain walk meets.
  for (std::int64_t k = 1; lo <= m_max; ++k) {
    const auto below = static_cast<std::int64_t>(std::floor(double(per_decade) * std::log10(double(lo)))) - 2;
    k = std::max(k, below);
    const auto edge = static_cast<std::int64_t>(std::ceil(std::pow(10.0, double(k) / per_decade) - 1e-9));
    if (edge <= lo) continue;  // this edge coincides with the previous one
    lo_.push_back(lo);
    hi_.push_back(std::min(edge - 1, m_max));
    lo = edge;
  }
}

double LogBins::center(int k) const { return std::sqrt(double(lo_[k]) * double(hi_[k])); }

int LogBins::index(std::int64_t m) const {
  auto it = std::upper_bound(lo_.begin(), lo_.end(), m);
  return static_cast<int>(it - lo_.begin()) - 1;
}

}  // namespace coolgas
