// Sums of the weights of cells, to draw a cell with probability
// proportional to its weight: cells in groups of 16, groups in pages of 16,
// a Fenwick tree over the pages. A draw reads the page tree (small enough to
// stay in cache), then one group's 16 sums and one group's 16 cells, which
// are contiguous: three memory accesses instead of the ~20 scattered ones
// of a Fenwick tree over the cells (the draw is bound by memory latency).
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace coolgas {

class WeightTree {
 public:
  static constexpr std::size_t kGroup = 16;  // cells per group, and groups per page

  explicit WeightTree(std::size_t cells)
      : groups_((cells + kGroup - 1) / kGroup), pages_((groups_.size() + kGroup - 1) / kGroup) {}

  // Sets the sums from the cells' weights, weight(c) for c < cells.
  template <class Weight>
  void build(std::size_t cells, Weight&& weight);
  void add(std::size_t cell, std::int64_t delta);
  std::uint64_t total() const { return total_; }
  // The group holding the r-th unit of weight (r < total()); r becomes the
  // rest within the group, to be found among its cells by the caller.
  std::size_t find_group(std::uint64_t& r) const { return find_group_in(find_page(r), r); }
  // The same in two steps: the page, then the group within it.
  std::size_t find_page(std::uint64_t& r) const;
  std::size_t find_group_in(std::size_t page, std::uint64_t& r) const;
  void prefetch_page(std::size_t page) const { __builtin_prefetch(&groups_[page * kGroup]); }

 private:
  std::vector<std::uint64_t> groups_;  // sum of each group's cells
  std::vector<std::uint64_t> pages_;   // Fenwick tree of the pages' sums
  std::uint64_t total_ = 0;
};

template <class Weight>
void WeightTree::build(std::size_t cells, Weight&& weight) {
  std::fill(groups_.begin(), groups_.end(), 0);
  std::fill(pages_.begin(), pages_.end(), 0);
  total_ = 0;
  for (std::size_t c = 0; c < cells; ++c) groups_[c / kGroup] += weight(c);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    pages_[g / kGroup] += groups_[g];
    total_ += groups_[g];
  }
  for (std::size_t k = 1; k <= pages_.size(); ++k) {  // page sums into a Fenwick tree, in place
    const std::size_t parent = k + (k & (~k + 1));
    if (parent <= pages_.size()) pages_[parent - 1] += pages_[k - 1];
  }
}

inline void WeightTree::add(std::size_t cell, std::int64_t delta) {
  const std::uint64_t d = std::uint64_t(delta);  // two's complement: adding it subtracts a negative delta
  const std::size_t g = cell / kGroup;
  groups_[g] += d;
  total_ += d;
  for (std::size_t k = g / kGroup + 1; k <= pages_.size(); k += k & (~k + 1)) pages_[k - 1] += d;
}

inline std::size_t WeightTree::find_page(std::uint64_t& r) const {
  std::size_t page = 0;
  for (std::size_t step = std::bit_floor(pages_.size()); step > 0; step >>= 1)
    if (page + step <= pages_.size() && pages_[page + step - 1] <= r) {
      page += step;
      r -= pages_[page - 1];
    }
  return page;
}

inline std::size_t WeightTree::find_group_in(std::size_t page, std::uint64_t& r) const {
  std::size_t g = page * kGroup;
  while (r >= groups_[g]) r -= groups_[g++];
  return g;
}

}  // namespace coolgas
