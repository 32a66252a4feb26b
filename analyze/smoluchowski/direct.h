// The reference method: the truncated Smoluchowski equation on masses 1..M,
// every pair summed explicitly, O(M^2) per right-hand side. Slow and obviously
// correct; the FFT and geometric-grid methods are tested against it.
#pragma once
#include "analyze/smoluchowski/grid.h"
#include "analyze/smoluchowski/powers.h"

namespace coolgas::smoluchowski {

class DirectRhs : public CoagulationRhs {
 public:
  DirectRhs(const Kernel& kernel, std::int64_t M);
  const MassGrid& grid() const override { return grid_; }
  void evaluate(const double* c, double* dcdt) override;

  // Up to this M the kernel is tabulated once (32 MB at most); above it,
  // evaluated from the power tables pair by pair.
  static constexpr std::int64_t kTableLimit = 2048;

 private:
  template <class K>
  void evaluate_with(const K& kernel, const double* c, double* dcdt) const;

  MassGrid grid_;
  KernelPowers powers_;
  std::vector<double> table_;  // K(i,j) at table_[i*M + j], when M <= kTableLimit
};

// Index of the last non-zero entry of c[0..n), or -1. Masses above it hold no
// clusters, so sums may stop there without changing the result.
long last_nonzero(const double* c, std::size_t n);

}  // namespace coolgas::smoluchowski
