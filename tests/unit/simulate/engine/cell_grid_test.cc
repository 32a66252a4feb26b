// Cell coordinates: coord() divides by the grid size in floating point for
// speed; it must invert index() exactly, for every cell of small grids and
// for cells across the largest grid whose cell count fits an int.
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/engine/cell_grid.h"

namespace coolgas {
namespace {

void expect_round_trip(int n, long long cell) {
  const CellCoord c = CellGrid::coord_in(int(cell), n, 1.0 / n);
  ASSERT_EQ((c.z * (long long)n + c.y) * n + c.x, cell) << "n = " << n;
  ASSERT_TRUE(c.x >= 0 && c.x < n && c.y >= 0 && c.y < n && c.z >= 0 && c.z < n) << "n = " << n << " cell " << cell;
}

TEST(CellGrid, CoordInvertsIndexOnEveryCellOfSmallGrids) {
  for (int n : {3, 4, 7, 64, 97}) {
    const CellGrid g(n * 1.01, 1.0, 0);
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

}  // namespace
}  // namespace coolgas
