// The few aggregates wider than a cell of the aggregation engine's grid
// (aggregation_engine.h), indexed apart: each keeps its logical fine cell
// (changed only at its crossing events, like any aggregate's), and is listed
// in the coarse cell holding that fine cell. A coarse cell is a block of
// block³ fine cells (the fine grid has n_coarse × block cells per side), so
// the coarse cell follows the fine one exactly and needs no events of its
// own. With block >= the largest reach of a pair (aggregation_reach.h), every
// large aggregate within reach of a fine cell is listed in the 27 coarse
// cells around it; with fewer than three coarse cells per side, every
// coarse cell is searched. Each coarse cell lists its aggregates in id order,
// so the index is rebuilt identically from the fine cells alone (a resumed
// run searches in the same order as the original).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "simulate/engine/cell_grid.h"

namespace coolgas {

class LargeAggregateIndex {
 public:
  LargeAggregateIndex() = default;
  // For a fine grid of n_fine³ cells (a multiple of block per side) and n aggregate slots.
  LargeAggregateIndex(int n_fine, int block, std::size_t n)
      : block_(block), n_(n_fine / block), inv_fine_(1.0 / n_fine), fine_(n, -1),
        lists_(std::size_t(n_) * std::size_t(n_) * std::size_t(n_)) {}

  int block() const { return block_; }
  std::size_t size() const { return count_; }
  bool contains(int i) const { return fine_[std::size_t(i)] >= 0; }
  int fine_cell(int i) const { return fine_[std::size_t(i)]; }

  void insert(int i, int fine) {
    fine_[std::size_t(i)] = fine;
    auto& l = lists_[coarse_of(fine)];
    l.insert(std::lower_bound(l.begin(), l.end(), i), i);
    ++count_;
  }
  void remove(int i) {
    auto& l = lists_[coarse_of(fine_[std::size_t(i)])];
    l.erase(std::lower_bound(l.begin(), l.end(), i));
    fine_[std::size_t(i)] = -1;
    --count_;
  }
  void move(int i, int fine) {
    if (coarse_of(fine) == coarse_of(fine_[std::size_t(i)])) {
      fine_[std::size_t(i)] = fine;
      return;
    }
    remove(i);
    insert(i, fine);
  }

  // Calls f(j) for every listed aggregate that may lie within a pair's reach
  // (at most block fine cells) of fine cell `fine`.
  template <class F>
  void for_each_near(int fine, F&& f) const {
    if (n_ < 3) {
      for (const auto& l : lists_)
        for (const int j : l) f(j);
      return;
    }
    const CellCoord c = coarse_coord(fine);
    for_each_neighbour_cell(n_, 0.0, c, [&](const NeighbourCell& nb) {
      for (const int j : lists_[std::size_t(nb.index)]) f(j);
    });
  }

  const std::vector<std::int32_t>& fine_cells() const { return fine_; }
  // The index holding the aggregates whose fine cells are given (-1: not large).
  void assign(const std::vector<std::int32_t>& fine) {
    for (std::size_t i = 0; i < fine.size(); ++i)
      if (fine[i] >= 0) insert(int(i), fine[i]);
  }

 private:
  CellCoord coarse_coord(int fine) const {
    const CellCoord f = CellGrid::coord_in(fine, n_ * block_, inv_fine_);
    return {f.x / block_, f.y / block_, f.z / block_};
  }
  std::size_t coarse_of(int fine) const {
    const CellCoord c = coarse_coord(fine);
    return (std::size_t(c.z) * std::size_t(n_) + std::size_t(c.y)) * std::size_t(n_) + std::size_t(c.x);
  }

  int block_ = 1, n_ = 1;
  double inv_fine_ = 1;
  std::size_t count_ = 0;
  std::vector<std::int32_t> fine_;  // each slot's fine cell, -1 if not listed
  std::vector<std::vector<int>> lists_;
};

}  // namespace coolgas
