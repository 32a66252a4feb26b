#include "common/close_pairs.h"

#include <cstdint>
#include <stdexcept>

#include "common/limits.h"

namespace coolgas {

PairsWithin::PairsWithin(std::span<const double> positions, double reach, double L, Geometry g)
    : L_(L), half_(0.5 * L), reach_(reach * kSafe), reach2_(reach * reach) {
  const std::size_t count = positions.size() / 3;
  if (count > std::size_t(kMaxIndex32)) throw std::length_error("PairsWithin: more points than 32-bit indices");
  // Cells reach/2 wide, else as wide as reach, each with every cell within
  // reach distinct (2m + 1 of them a side); at most about count^(1/d) + 1 a side.
  const double cap = std::ceil(g.root(double(count))) + 1;
  int n = 0, m = 0;
  for (int k = 2; k >= 1 && n == 0; --k) {
    const int c = int(std::min({std::floor(k * L / reach), cap, 1e9}));
    if (c < 1) continue;
    int cm = int(std::ceil(reach / (L / c)));
    if (cm * (L / c) < reach) ++cm;
    if (c >= 2 * cm + 1) n = c, m = cm;
  }
  all_pairs_ = n == 0;
  const double w = w_ = all_pairs_ ? L : L / n;
  for (int k = 0; k < 3; ++k) n_[k] = all_pairs_ ? 1 : g.along(k, n), m_[k] = g.spans(k) && !all_pairs_ ? m : 0;
  auto coord = [&](std::size_t i, int k) { return std::clamp(int(std::floor(positions[3 * i + std::size_t(k)] / w)), 0, n_[k] - 1); };
  auto cell_of = [&](std::size_t i) {
    return (std::size_t(coord(i, 2)) * std::size_t(n_[1]) + std::size_t(coord(i, 1))) * std::size_t(n_[0]) +
           std::size_t(coord(i, 0));
  };
  // A counting sort by cell, stable: within a cell, the caller's order.
  start_.assign(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]) + 1, 0);
  std::vector<std::uint32_t> cell(count);
  for (std::size_t i = 0; i < count; ++i) ++start_[(cell[i] = std::uint32_t(cell_of(i))) + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  index_.resize(count), x_.resize(count), y_.resize(count), z_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t a = fill[cell[i]]++;
    index_[a] = std::uint32_t(i);
    x_[a] = positions[3 * i], y_[a] = positions[3 * i + 1], z_[a] = positions[3 * i + 2];
  }
}

}  // namespace coolgas
