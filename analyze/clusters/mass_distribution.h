// The cluster mass distribution of one frame: clusters counted in the
// logarithmic bins of analyze/bins/log_bins.h, and the moments that the shared "cluster
// series" table reports (data-schema/tsv-tables.md, "Shared table shapes").
#pragma once
#include <cstdint>
#include <vector>

#include "analyze/bins/log_bins.h"

namespace coolgas {

// Moments of the cluster masses of one frame (sums over clusters).
struct ClusterMoments {
  std::int64_t clusters = 0;  // Σ 1
  std::int64_t mass = 0;      // Σ m (the number of particles)
  double mass2 = 0;           // Σ m²
  std::int64_t largest = 0;   // max m
  double mean() const { return clusters ? double(mass) / double(clusters) : 0.0; }
};

class MassHistogram {
 public:
  // Bins for masses 1..m_max (the number of particles), `per_decade` per decade.
  MassHistogram(int per_decade, std::int64_t m_max);

  void clear();
  void add(std::int64_t m) {
    ++count_[bin_of(m)];
    ++moments_.clusters;
    moments_.mass += m;
    moments_.mass2 += double(m) * double(m);
    if (m > moments_.largest) moments_.largest = m;
  }

  const LogBins& bins() const { return bins_; }
  std::int64_t count(int k) const { return count_[k]; }
  const ClusterMoments& moments() const { return moments_; }

 private:
  // Most clusters are small: a table answers for them, the binary search of
  // LogBins::index for the rest.
  int bin_of(std::int64_t m) const { return m < std::int64_t(small_.size()) ? small_[m] : bins_.index(m); }

  LogBins bins_;
  std::vector<int> small_;
  std::vector<std::int64_t> count_;
  ClusterMoments moments_;
};

}  // namespace coolgas
