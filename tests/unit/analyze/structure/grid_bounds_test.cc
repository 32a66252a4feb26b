// Issue 52, class 5: coolgas.structure(P, 3e4) allocated a 1024^3 grid
// beyond the memory ("MemoryError"). The grid's bytes are counted first and
// a grid beyond the memory available is refused naming --grid, the bytes and
// the largest grid that fits.
#include <gtest/gtest.h>

#include <string>

#include "analyze/structure/structure_table.h"
#include "common/error.h"
#include "common/geometry.h"

namespace coolgas {
namespace {

std::string refusal(int grid, double L, Geometry g, double memory) {
  try {
    return "points " + std::to_string(structure_grid_points(grid, L, g, memory));
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST(StructureGridBounds, TheGridsBytesAreTheDensityAndThePowerSpectrum) {
  // 3D, n = 8: 8 x 8 rows of 10 reals (FFTW's padding) and 5 powers.
  EXPECT_EQ(structure_grid_bytes(8, Geometry(3)), (10 + 5) * 64 * 8.0);
  EXPECT_EQ(structure_grid_bytes(8, Geometry(2)), (10 + 5) * 8 * 8.0);
  EXPECT_EQ(structure_grid_bytes(8, Geometry(1)), (10 + 5) * 8.0);
}

TEST(StructureGridBounds, AGridBeyondTheMemoryIsRefusedNamingTheLargestThatFits) {
  const Geometry g(3);
  EXPECT_EQ(refusal(0, 3e4, g, 4e9),
            "--grid 1024 (the default for L = 30000) would need 12.9 GB for its density grid; the memory available "
            "is 4 GB: --grid at most 692");
  EXPECT_LE(structure_grid_bytes(692, g), 4e9);
  EXPECT_GT(structure_grid_bytes(694, g), 4e9);
  EXPECT_EQ(refusal(900, 12, g, 4e9).find("--grid 900 would need 8.77 GB"), 0u) << refusal(900, 12, g, 4e9);
  EXPECT_EQ(refusal(0, 3e4, g, 13e9), "points 1024");
  EXPECT_EQ(refusal(0, 68.5, g, 4e9), "points 68");
  EXPECT_EQ(refusal(0, 1e300, Geometry(1), 4e9), "points 1024");  // 1D: 1024 numbers
  EXPECT_EQ(refusal(0, 7.9, g, 4e9).find("box side L = 7.9 is too small"), 0u);
}

}  // namespace
}  // namespace coolgas
