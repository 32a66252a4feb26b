#include "analyze/labelling/cluster_runs.h"

namespace coolgas {

void CellRuns::reset(const ClusterGrid& grid) {
  const std::int64_t n = grid.per_side();
  words_ = static_cast<int>((n + 63) / 64);
  starts_.resize(static_cast<std::size_t>(grid.rows_per_plane() * std::int64_t(grid.planes()) * words_));
  first_.resize(starts_.size());
  total_ = 0;
}

void CellRuns::add_plane(const CellOccupancy& occ, int k) {
  const std::int64_t rows = occ.grid().rows_per_plane();
  for (std::int64_t r = rows * k; r < rows * (k + 1); ++r) {
    const std::uint64_t* bits = occ.row(r);
    std::uint64_t carry = 0;  // occupancy of the cell just before this word
    for (int w = 0; w < words_; ++w) {
      const std::int64_t g = r * words_ + w;
      // A run starts where a cell is occupied and its -x neighbour in the row is not.
      starts_[g] = bits[w] & ~((bits[w] << 1) | carry);
      carry = bits[w] >> 63;
      first_[g] = total_;
      total_ += std::popcount(starts_[g]);
    }
  }
}

}  // namespace coolgas
