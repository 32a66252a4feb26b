// Shapes in 2D (disks: every z = 0, unit squares, a 2 x 2 gyration tensor)
// against exact answers: the eigenvalues of rectangles and of a diagonal rod
// of points, a rod unwrapped across the periodic boundary, a row that winds
// round the box, d_f of rods (1) and squares (2) of unit squares, the
// clusters of site percolation at the square lattice's threshold p_c =
// 0.592746 (Newman & Ziff, PRL 85, 4104 (2000)) with D = 91/48 (den Nijs,
// J. Phys. A 12, 1857 (1979)), and aggregates as solid discs.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/shape/cluster_shapes.h"
#include "analyze/shape/gyration.h"
#include "analyze/shape/mass_radius.h"
#include "analyze/shape/shape_table.h"
#include "tests/unit/analyze/shape/percolation.h"

namespace coolgas {
namespace {

// Points on an a x b grid of unit spacing: eigenvalues (a^2 - 1)/12 and
// (b^2 - 1)/12 (the variance of a uniform grid of a points), asphericity
// ((l2 - l1)/(l1 + l2))^2; a square (a = b) has 0.
TEST(DiskGyration, RectanglesHaveTheirExactEigenvalues) {
  for (auto [a, b] : {std::pair{5, 5}, {3, 7}, {1, 9}}) {
    GyrationSums g;
    for (int i = 0; i < a; ++i)
      for (int j = 0; j < b; ++j) g.add(0.3 + i, -2.0 + j, 0.0);
    const Shape s = shape_of(g, Geometry(2));
    const double la = (a * a - 1) / 12.0, lb = (b * b - 1) / 12.0;
    EXPECT_NEAR(s.lambda[0], std::min(la, lb), 1e-12);
    EXPECT_NEAR(s.lambda[1], std::max(la, lb), 1e-12);
    EXPECT_EQ(s.lambda[2], 0.0);
    EXPECT_NEAR(s.Rg * s.Rg, la + lb, 1e-12);
    EXPECT_NEAR(s.asphericity, std::pow((lb - la) / (la + lb), 2), 1e-12);
    EXPECT_EQ(s.prolateness, 0.0);
  }
}

// A rod of k points along the diagonal: one eigenvalue 2 (k^2 - 1)/12, the
// other 0, asphericity 1 whatever its direction.
TEST(DiskGyration, ADiagonalRodIsARod) {
  GyrationSums g;
  for (int i = 0; i < 9; ++i) g.add(i, i, 0);
  const Shape s = shape_of(g, Geometry(2));
  EXPECT_NEAR(s.lambda[0], 0, 1e-12);
  EXPECT_NEAR(s.lambda[1], 2 * 80 / 12.0, 1e-12);
  EXPECT_NEAR(s.asphericity, 1, 1e-12);
}

std::vector<double> square_centres(const std::vector<std::pair<int, int>>& squares) {
  std::vector<double> p;
  for (auto [i, j] : squares) p.insert(p.end(), {i + 0.5, j + 0.5, 0.0});
  return p;
}

// In a 20 x 20 box: a rod of 5 squares across x = 0 is whole again (R_g^2 =
// (25 - 1)/12 = 2), a full column winds round the box along y.
TEST(DiskClusterShapes, RodsAreUnwrappedAndFullRowsWrap) {
  std::vector<std::pair<int, int>> squares{{18, 4}, {19, 4}, {0, 4}, {1, 4}, {2, 4}};
  for (int j = 0; j < 20; ++j) squares.push_back({10, j});
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(20.0, Geometry(2)), square_centres(squares));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].shape.mass, 20);
  EXPECT_TRUE(s[0].wraps);
  EXPECT_EQ(s[1].shape.mass, 5);
  EXPECT_FALSE(s[1].wraps);
  EXPECT_NEAR(s[1].shape.Rg * s[1].shape.Rg, 2.0, 1e-12);
  EXPECT_NEAR(s[1].shape.asphericity, 1.0, 1e-12);
}

MassRadius fit(const std::vector<ClusterShape>& s, const std::string& window) {
  return mass_radius(s, 10, parse_window(window, "--fit-mass"));
}

// Rods of 1..60 squares and squares of side 1..30, each alone in its box.
TEST(DiskMassRadius, RodsAndSquaresHaveDimensionOneAndTwo) {
  ClusterShapes shapes;
  std::vector<ClusterShape> rods, squares;
  for (int n = 1; n <= 60; ++n) {
    std::vector<std::pair<int, int>> rod, square;
    for (int i = 0; i < n; ++i) rod.push_back({2 + i, 3});
    for (int i = 0; i < n / 2; ++i)
      for (int j = 0; j < n / 2; ++j) square.push_back({2 + i, 2 + j});
    for (const auto& c : shapes.of_particles(ClusterGrid(64.0, Geometry(2)), square_centres(rod))) rods.push_back(c);
    if (n % 2 == 0)
      for (const auto& c : shapes.of_particles(ClusterGrid(64.0, Geometry(2)), square_centres(square))) squares.push_back(c);
  }
  EXPECT_NEAR(fit(rods, "10:").d_f, 1, 0.02);
  EXPECT_NEAR(fit(squares, "10:").d_f, 2, 0.03);
}

// Sites of a 1024^2 periodic lattice occupied with probability p_c, one disk
// at each occupied site's centre: the finite clusters obey M ~ R_g^D, D = 91/48.
TEST(DiskMassRadius, PercolationClustersAtThresholdHaveTheKnownFractalDimension) {
  const MassRadius mr = test::percolation_mass_radius(1024, 2, 0.592746, 8, "50:");
  EXPECT_NEAR(mr.d_f, 91.0 / 48.0, 0.08);
  EXPECT_LT(mr.d_f_err, 0.08);
  EXPECT_GE(mr.fit_bins, 10);
}

// Aggregates of disks are solid discs of diameter m^(1/2): R_g^2 = m/8, d_f = 2.
TEST(DiskMassRadius, AggregatesAreSolidDiscs) {
  std::vector<double> masses;
  for (int m = 2; m <= 4000; m = m * 5 / 4 + 1) masses.push_back(m);
  const auto s = aggregate_shapes(masses, Geometry(2));
  EXPECT_NEAR(s.back().shape.Rg * s.back().shape.Rg, 2.0 / 8.0, 1e-12);  // the smallest, m = 2
  EXPECT_NEAR(fit(s, "1:").d_f, 2, 1e-9);
}

// The 2D tables have no lambda3 and no prolateness column, their rows as many entries.
TEST(DiskShapeTable, TwoDimensionalTablesLeaveOutTheThreeDimensionalInvariants) {
  EXPECT_EQ(shape_columns(ShapeTable::kClusters, Geometry(2)),
            (std::vector<std::string>{"t", "mass", "Rg", "lambda1", "lambda2", "asphericity", "wraps"}));
  EXPECT_EQ(shape_columns(ShapeTable::kSeries, Geometry(2)).size(), 7u);
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(20.0, Geometry(2)), square_centres({{1, 1}, {2, 1}, {3, 1}}));
  const TableBlock b = shape_block(ShapeTable::kClusters, 1.0, s, fit(s, "1:"), 1, Geometry(2));
  ASSERT_EQ(b.rows.size(), 1u);
  EXPECT_EQ(b.rows[0].size(), 7u);
  EXPECT_NEAR(b.rows[0][3], 0, 1e-12);          // lambda1
  EXPECT_NEAR(b.rows[0][4], 8 / 12.0, 1e-12);   // lambda2 = (3^2 - 1)/12
}

}  // namespace
}  // namespace coolgas
