// The few aggregates wider than a cell of the aggregation engine's grid
// (aggregation_engine.h), indexed apart: each keeps its logical fine cell
// (changed only at its crossing events, like any aggregate's), and is listed
// in the coarse cell holding that fine cell. A coarse cell is a block of
// block³ fine cells (the fine grid has n_coarse × block cells per side), so
// the coarse cell follows the fine one exactly and needs no events of its
// own. Aggregates are indexed by size class (the engine's choice: the reach
// they need), each class in coarse cells of its own, so that a search walks
// far only for the few very large ones: a search for a class's aggregates
// within `reach` fine cells of a fine cell (aggregation_reach.h) walks the
// coarse cells that overlap that range, each once even where the range
// wraps the box. Each coarse cell's list is linked through the engine's own
// records (bind_links), as the fine grid's are, so walking it touches the
// records the search reads anyway, and a class costs 4 bytes per coarse
// cell. Each list is kept in slot order, so the index is rebuilt
// identically from the fine cells alone (a resumed run searches in the same
// order as the original).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/geometry.h"

#include "simulate/engine/cell_grid.h"

namespace coolgas {

class LargeAggregateIndex {
 public:
  LargeAggregateIndex() = default;
  // For a fine grid of n_fine³ cells (a multiple of block per side; in 2D
  // n_fine² cells, one layer; in 1D n_fine, one row) and n aggregate slots.
  LargeAggregateIndex(int n_fine, int block, std::size_t n, Geometry g)
      : block_(block),
        n_(n_fine / block),
        rows_(g.along(1, n_)),
        layers_(g.along(2, n_)),
        inv_fine_(1.0 / n_fine),
        fine_(n, -1),
        class_(n, -1) {}

  // The forward links live at base[i * stride] (one per slot, unused by the fine grid for these).
  void bind_links(std::int32_t* base, std::size_t stride) {
    next_ = base;
    stride_ = stride;
  }

  int block() const { return block_; }
  std::size_t size() const { return count_; }
  bool contains(int i) const { return fine_[std::size_t(i)] >= 0; }
  int fine_cell(int i) const { return fine_[std::size_t(i)]; }

  int classes() const { return int(levels_.size()); }

  void insert(int i, int fine, int size_class) {
    fine_[std::size_t(i)] = fine;
    class_[std::size_t(i)] = size_class;
    if (size_class >= classes()) levels_.resize(std::size_t(size_class) + 1);
    auto& level = levels_[std::size_t(size_class)];
    if (level.empty()) level.assign(std::size_t(n_) * std::size_t(rows_) * std::size_t(layers_), -1);
    std::int32_t* at = &level[coarse_of(fine)];  // the link that will point to i
    while (*at >= 0 && *at < i) at = &link(*at);
    link(i) = *at;
    *at = i;
    ++count_;
  }
  void remove(int i) {
    std::int32_t* at = &levels_[std::size_t(class_[std::size_t(i)])][coarse_of(fine_[std::size_t(i)])];
    while (*at != i) at = &link(*at);
    *at = link(i);
    fine_[std::size_t(i)] = class_[std::size_t(i)] = -1;
    --count_;
  }
  void move(int i, int fine) {
    if (coarse_of(fine) == coarse_of(fine_[std::size_t(i)])) {
      fine_[std::size_t(i)] = fine;
      return;
    }
    const int size_class = class_[std::size_t(i)];
    remove(i);
    insert(i, fine, size_class);
  }

  // Calls f(j) once for every aggregate of class size_class whose fine cell
  // may lie within `reach` fine cells of fine cell `fine` (periodic), and for a few more.
  template <class F>
  void for_each_near(int fine, int size_class, int reach, F&& f) const {
    const auto& level = levels_[std::size_t(size_class)];
    if (level.empty()) return;
    const CellCoord c = CellGrid::coord_in(fine, n_ * block_, inv_fine_);
    int lo[3], count[3];
    const int cc[3] = {c.x, c.y, c.z};
    for (int d = 0; d < 3; ++d) {
      lo[d] = floor_div(cc[d] - reach, block_);
      count[d] = std::min(floor_div(cc[d] + reach, block_) - lo[d] + 1, n_);
    }
    if (layers_ == 1) {  // 2D: the one layer; 1D: the one row of it
      lo[2] = 0, count[2] = 1;
      if (rows_ == 1) lo[1] = 0, count[1] = 1;
    }
    for (int z = 0; z < count[2]; ++z) {
      const std::size_t cz = std::size_t(wrap(lo[2] + z));
      for (int y = 0; y < count[1]; ++y) {
        const std::size_t cy = std::size_t(wrap(lo[1] + y));
        for (int x = 0; x < count[0]; ++x)
          for (int j = level[(cz * std::size_t(n_) + cy) * std::size_t(n_) + std::size_t(wrap(lo[0] + x))]; j >= 0;
               j = link(j))
            f(j);
      }
    }
  }

  const std::vector<std::int32_t>& fine_cells() const { return fine_; }
  // The index holding the aggregates whose fine cells are given (-1: not
  // large), in the classes class_of(i) gives.
  template <class C>
  void assign(const std::vector<std::int32_t>& fine, C&& class_of) {
    for (std::size_t i = 0; i < fine.size(); ++i)
      if (fine[i] >= 0) insert(int(i), fine[i], class_of(int(i)));
  }

 private:
  static int floor_div(int a, int b) { return a >= 0 ? a / b : -((b - 1 - a) / b); }
  int wrap(int x) const { return x - floor_div(x, n_) * n_; }
  std::int32_t& link(int i) const { return next_[std::size_t(i) * stride_]; }
  CellCoord coarse_coord(int fine) const {
    const CellCoord f = CellGrid::coord_in(fine, n_ * block_, inv_fine_);
    return {f.x / block_, f.y / block_, f.z / block_};
  }
  std::size_t coarse_of(int fine) const {
    const CellCoord c = coarse_coord(fine);
    return (std::size_t(c.z) * std::size_t(n_) + std::size_t(c.y)) * std::size_t(n_) + std::size_t(c.x);
  }

  int block_ = 1, n_ = 1, rows_ = 1, layers_ = 1;  // coarse cells along y (n_, or 1 in 1D) and z (n_, or 1 in 2D, 1D)
  double inv_fine_ = 1;
  std::size_t count_ = 0;
  std::vector<std::int32_t> fine_, class_;  // each slot's fine cell and class, -1 if not listed
  std::vector<std::vector<std::int32_t>> levels_;  // per class (empty until used), per coarse cell: its first slot, or -1
  std::int32_t* next_ = nullptr;  // slot i's successor in its list: next_[i * stride_]
  std::size_t stride_ = 1;
};

}  // namespace coolgas
