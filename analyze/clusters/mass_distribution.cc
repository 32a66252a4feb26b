#include "analyze/clusters/mass_distribution.h"

#include <algorithm>

namespace coolgas {

namespace {
constexpr std::int64_t kSmallMasses = 4096;
}

MassHistogram::MassHistogram(int per_decade, std::int64_t m_max)
    : bins_(per_decade, m_max), count_(static_cast<std::size_t>(bins_.size()), 0) {
  const std::int64_t n = std::min(kSmallMasses, m_max + 1);
  small_.resize(static_cast<std::size_t>(n), 0);
  for (std::int64_t m = 1; m < n; ++m) small_[m] = bins_.index(m);
}

void MassHistogram::clear() {
  std::fill(count_.begin(), count_.end(), 0);
  moments_ = {};
}

}  // namespace coolgas
