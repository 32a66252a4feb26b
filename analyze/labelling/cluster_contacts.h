// Finding the face contacts between runs of occupied cells (cluster_runs.h) on
// the periodic grid, 64 cells at a time.
//
// Two runs in neighbouring rows (along y or z, or across a periodic face)
// touch where both rows' occupancy words overlap (a bitwise AND). Each
// maximal segment of that AND is the contact of exactly one pair of runs
// (runs are intervals, and so are their intersections), so one link per
// segment connects everything a cell-by-cell walk over the six face
// neighbours would, with far fewer unions and no per-cell branches. The
// disjoint-set union that uses the contacts is in cluster_labeller.h.
#pragma once
#include <bit>
#include <cstdint>

#include "analyze/labelling/cluster_runs.h"

namespace coolgas {

namespace cluster_contacts_detail {

// Calls link(x) at the first cell of each maximal segment of a & b (rows of `words` words).
template <class F>
void for_each_contact(const std::uint64_t* a, const std::uint64_t* b, int words, F&& link) {
  std::uint64_t carry = 0;
  for (int w = 0; w < words; ++w) {
    const std::uint64_t both = a[w] & b[w];
    std::uint64_t first = both & ~((both << 1) | carry);
    carry = both >> 63;
    while (first) {
      link(64 * w + std::countr_zero(first));
      first &= first - 1;
    }
  }
}

}  // namespace cluster_contacts_detail

// Calls on_link(run_a, run_b) once per contact between a run of plane k and
// a run of a row already walked: the -y and -z neighbour rows, and across the
// periodic faces (the cells x = 0 and x = n-1 of a row, rows j = n-1 and
// j = 0, and, for k = n-1, plane 0). Walking planes 0..n-1 in turn links
// every contact once. Runs connect cells along x, so runs plus contacts
// connect exactly the face-adjacent occupied cells. With ncell <= 2 the
// periodic neighbours are interior ones (or the cell itself) and are not
// linked again; a 2D grid's single plane has no neighbour along z, a 1D
// grid's single row none along y either (only its ends meet, across x).
template <class OnLink>
void walk_plane_contacts(const CellOccupancy& occ, const CellRuns& runs, std::int64_t k, OnLink&& on_link) {
  const int n = occ.grid().per_side(), words = occ.words_per_row(), planes = occ.grid().planes();
  const int rows = occ.grid().rows_per_plane();
  const bool periodic = n > 2;
  for (std::int64_t j = 0; j < rows; ++j) {
    const std::int64_t r = j + rows * k;
    if (periodic && occ.occupied(0, r) && occ.occupied(n - 1, r)) on_link(runs.run_at(r, 0), runs.run_at(r, n - 1));
    auto link_rows = [&](std::int64_t other) {
      cluster_contacts_detail::for_each_contact(occ.row(r), occ.row(other), words,
                                                [&](int x) { on_link(runs.run_at(r, x), runs.run_at(other, x)); });
    };
    if (j > 0) link_rows(r - 1);
    if (k > 0) link_rows(r - rows);
    if (rows > 2 && j == rows - 1) link_rows(rows * k);
    if (planes > 2 && k == planes - 1) link_rows(j);
  }
}

}  // namespace coolgas
