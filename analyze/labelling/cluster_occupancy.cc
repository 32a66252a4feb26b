#include "analyze/labelling/cluster_occupancy.h"

#include <algorithm>

namespace coolgas {

void CellOccupancy::build(const ClusterGrid& grid, std::span<const double> positions,
                          const std::function<void(int)>& plane_done) {
  grid_ = grid;
  const int n = grid.per_side();
  words_ = (n + 63) / 64;
  bits_.assign(static_cast<std::size_t>(rows() * words_), 0);
  sort_by_plane(positions);
  for (int k = 0; k < grid.planes(); ++k) {
    for (std::uint32_t b : plane_particles(k)) bits_[b >> 6] |= std::uint64_t{1} << (b & 63);
    plane_done(k);
  }
}

void CellOccupancy::sort_by_plane(std::span<const double> pos) {
  const int planes = grid_.planes();
  const std::uint32_t pitch = 64 * words_, plane_bits = pitch * std::uint32_t(grid_.rows_per_plane());
  const std::size_t np = pos.size() / 3;
  bit_.resize(np);
  plane_start_.assign(std::size_t(planes) + 1, 0);
  for (std::size_t p = 0; p < np; ++p) {
    const int k = grid_.cell_1d(pos[3 * p + 2]);
    bit_[p] = std::uint32_t(grid_.cell_1d(pos[3 * p])) + pitch * std::uint32_t(grid_.cell_1d(pos[3 * p + 1])) +
              plane_bits * std::uint32_t(k);
    ++plane_start_[k + 1];
  }
  for (int k = 0; k < planes; ++k) plane_start_[k + 1] += plane_start_[k];
  // The plane of bit b is floor(b / plane_bits), computed as (b + 1/2) / plane_bits
  // in doubles, several times faster than an integer division and exact: the
  // quotient is at least 1/(2 plane_bits) > 2^-22 from an integer, the
  // rounding error below 2^-40.
  const double inv_plane = 1.0 / plane_bits;
  by_plane_.resize(np);
  std::vector<std::int64_t> next(plane_start_.begin(), plane_start_.end() - 1);
  for (std::uint32_t b : bit_) by_plane_[next[static_cast<int>((b + 0.5) * inv_plane)]++] = b;
}

}  // namespace coolgas
