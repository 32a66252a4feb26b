// Runs: maximal sequences of occupied cells along x within a row, numbered
// in raster order. They are the elements of the labeller's disjoint sets:
// cells of a run always share a cluster, and there are fewer runs than
// occupied cells (4.4e6 runs for 6.6e6 occupied cells at phi = 0.208,
// uniform).
//
// A run's number is found from the bits alone: per occupancy word, the mask
// of run starts and the number of runs begun before the word; the run
// holding cell x is that number plus the starts up to x (a popcount), minus one.
#pragma once
#include <bit>
#include <cstdint>
#include <vector>

#include "analyze/labelling/cluster_occupancy.h"

namespace coolgas {

class CellRuns {
 public:
  // Starts numbering for `grid`, then numbers the runs of each plane, which
  // must come in increasing z, once the plane is filled.
  void reset(const ClusterGrid& grid);
  void add_plane(const CellOccupancy& occ, int k);

  std::int32_t size() const { return total_; }

  // Run holding occupied cell x of row r (the word is r*W + (x >> 6)).
  std::int32_t run_at(std::int64_t r, int x) const { return in_word(r * words_ + (x >> 6), x & 63); }
  // Run holding the occupied cell of grid bit b (see cluster_occupancy.h).
  std::int32_t run_at_bit(std::uint32_t b) const { return in_word(b >> 6, int(b & 63)); }
  // Run-start mask of word w (global word index r*W + word in row).
  std::uint64_t starts(std::int64_t w) const { return starts_[w]; }

 private:
  std::int32_t in_word(std::int64_t w, int bit) const {
    const std::uint64_t upto = ~std::uint64_t{0} >> (63 - bit);
    return first_[w] + std::popcount(starts_[w] & upto) - 1;
  }

  int words_ = 0;
  std::int32_t total_ = 0;
  std::vector<std::uint64_t> starts_;  // bit x set: a run starts at cell x
  std::vector<std::int32_t> first_;    // runs begun before this word
};

}  // namespace coolgas
