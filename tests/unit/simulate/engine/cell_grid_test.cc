// Cell coordinates: coord() divides by the grid size in floating point for
// speed; it must invert index() exactly, for every cell of small grids and
// for cells across the largest grid whose cell count fits an int.
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/engine/cell_grid.h"
#include "tests/support/saved_state.h"

#include <set>
#include <vector>

namespace coolgas {
namespace {

void expect_round_trip(int n, long long cell) {
  const CellCoord c = CellGrid::coord_in(int(cell), n, 1.0 / n);
  ASSERT_EQ((c.z * (long long)n + c.y) * n + c.x, cell) << "n = " << n;
  ASSERT_TRUE(c.x >= 0 && c.x < n && c.y >= 0 && c.y < n && c.z >= 0 && c.z < n) << "n = " << n << " cell " << cell;
}

TEST(CellGrid, CoordInvertsIndexOnEveryCellOfSmallGrids) {
  for (int n : {3, 4, 7, 64, 97}) {
    const CellGrid g(n * 1.01, 1.0, 0, Geometry(3));
    ASSERT_EQ(g.cells_per_side(), n);
    for (int cell = 0; cell < n * n * n; ++cell) {
      const CellCoord c = g.coord(cell);
      ASSERT_EQ(g.index(c), cell) << "n = " << n;
      expect_round_trip(n, cell);
    }
  }
}

TEST(CellGrid, CoordInvertsIndexAcrossTheLargestGrid) {
  const int n = int(std::cbrt(2147483647.0));  // 1290: n^3 just fits an int
  const long long last = 1LL * n * n * n - 1;
  for (long long cell : {0LL, 1LL, n - 1LL, 1LL * n, last - 1, last}) expect_round_trip(n, cell);
  // Every cell on either side of a multiple of n or n^2, where a rounded
  // quotient would fall on the wrong side.
  for (long long k = 1; k < 1LL * n * n; ++k) {
    expect_round_trip(n, k * n - 1);
    expect_round_trip(n, k * n);
  }
}

// The heads are stored in blocks (slot()), padded where n is not a
// multiple of a block's side: each cell still has a slot of its own, and a
// checkpoint holds the heads by plain cell index, so checkpoints written
// before the blocks load unchanged. One particle per cell, particle c in cell
// c; n = 5 pads every axis.
TEST(CellGrid, HeadsHaveDistinctSlotsAndCheckpointsHoldThemByCellIndex) {
  const int n = 5, cells = n * n * n;
  CellGrid grid(n * 1.01, 1.0, std::size_t(cells), Geometry(3));
  std::set<int> slots;
  for (int c = 0; c < cells; ++c) {
    slots.insert(grid.slot(grid.coord(c)));
    grid.insert(c, c);
  }
  EXPECT_EQ(int(slots.size()), cells);
  const StateReader in = test::saved_state_of([&](StateWriter& out) { grid.save(out, "g/"); });
  const std::vector<std::int32_t> heads = in.get<std::int32_t>("g/heads");
  ASSERT_EQ(int(heads.size()), cells);
  CellGrid back(n * 1.01, 1.0, std::size_t(cells), Geometry(3));
  back.load(in, "g/");
  for (int c = 0; c < cells; ++c) {
    EXPECT_EQ(heads[std::size_t(c)], c);
    EXPECT_EQ(back.first(c), c);
    EXPECT_EQ(back.next(c), -1);
  }
}

// The partner search's specialised walk (interior cells without shifts)
// visits exactly the cells of the one periodic walker, in the same order and
// with the same shifts, for every cell and every slab a crossing searches.
// In 2D (one layer, z offsets 0) the same for the 9 cells around and the 3
// beyond each of the 4 faces.
template <int D>
void expect_specialised_search_matches_the_walker() {
  for (const int n : {3, 4, 5, 7}) {
    const double L = 1.1 * n;
    const CellGrid grid(L, 1.0, 1, Geometry(D));
    ASSERT_EQ(grid.cells_per_side(), n);
    ASSERT_EQ(grid.cell_count(), D == 3 ? n * n * n : n * n);
    for (int slab = -1; slab < 2 * D; ++slab) {  // -1: all 27 (9); else the 9 (3) beyond face `slab`
      int lo[3] = {-1, -1, D == 3 ? -1 : 0}, hi[3] = {1, 1, D == 3 ? 1 : 0};
      if (slab >= 0) lo[slab / 2] = hi[slab / 2] = slab % 2 ? 1 : -1;
      for (int cell = 0; cell < grid.cell_count(); ++cell) {
        const CellCoord c = grid.coord(cell);
        int slots[27];
        double shifts[27][3];
        bool wraps = false;
        const int count = neighbour_slots<D>(grid, L, c, lo, hi, slots, shifts, wraps);
        int k = 0;
        for_each_neighbour_cell(n, L, c, lo, hi, [&](const NeighbourCell& nb) {
          ASSERT_LT(k, count);
          EXPECT_EQ(slots[k], grid.slot(grid.coord(nb.index))) << "n " << n << " cell " << cell << " slab " << slab;
          EXPECT_EQ(grid.index(nb.cell), nb.index);
          for (int d = 0; d < 3; ++d) EXPECT_EQ(wraps ? shifts[k][d] : 0.0, nb.shift[d]);
          ++k;
        });
        EXPECT_EQ(k, count);
      }
    }
  }
}

TEST(NeighbourCells, SpecialisedSearchMatchesThePeriodicWalker) { expect_specialised_search_matches_the_walker<3>(); }
TEST(NeighbourCells, SpecialisedSearchMatchesThePeriodicWalkerIn2D) {
  expect_specialised_search_matches_the_walker<2>();
}

}  // namespace
}  // namespace coolgas

namespace coolgas {
namespace {

// The limit a refusal states is the one enforced: the value it names passes,
// the double below it is refused (rounded to six digits, the limit once read
// "L >= 3" in the refusal of L = 3).
TEST(CellGridLimit, TheStatedSmallestBoxIsTheEnforcedOne) {
  for (double width : {1.0, 2.5, 0.7}) {
    const std::string refusal = check_box_fits_grid(3 * width, width);
    const std::string key = "the cell grid needs L >= ";
    const auto at = refusal.find(key);
    ASSERT_NE(at, std::string::npos) << refusal;
    const double stated = std::stod(refusal.substr(at + key.size()));
    EXPECT_GT(stated, 3 * width) << refusal;
    EXPECT_EQ(check_box_fits_grid(stated, width), "") << refusal;
    EXPECT_NE(check_box_fits_grid(std::nextafter(stated, 0.0), width), "") << refusal;
  }
  EXPECT_NE(check_box_fits_grid(3, 1).find("box side L = 3 is too small"), std::string::npos);
}

}  // namespace
}  // namespace coolgas
