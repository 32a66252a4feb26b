// Shapes in 1D (rods on a ring: unit segments, a 1 x 1 gyration "tensor")
// against exact answers: a run of m points of unit spacing has R_g^2 =
// (m^2 - 1)/12 (the variance of a uniform grid of m points), also when it is
// unwrapped across the ring's ends; a full ring winds; runs of 1..200
// segments have d_f = 1; aggregates are solid rods of length m (R_g^2 =
// m^2/12, d_f = 1 exactly); the 1D tables keep no shape columns.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/shape/cluster_shapes.h"
#include "analyze/shape/gyration.h"
#include "analyze/shape/mass_radius.h"
#include "analyze/shape/shape_table.h"

namespace coolgas {
namespace {

std::vector<double> segment_centres(const std::vector<int>& segments) {
  std::vector<double> p;
  for (int i : segments) p.insert(p.end(), {i + 0.5, 0.0, 0.0});
  return p;
}

TEST(RodGyration, AGridOfMPointsHasRgSquaredMSquaredMinusOneOverTwelve) {
  for (int m : {1, 2, 5, 100}) {
    GyrationSums g;
    for (int i = 0; i < m; ++i) g.add(-3.7 + i, 0, 0);
    const Shape s = shape_of(g, Geometry(1));
    EXPECT_EQ(s.mass, m);
    EXPECT_NEAR(s.Rg * s.Rg, (m * m - 1) / 12.0, 1e-12 * m * m) << m;
    EXPECT_NEAR(s.lambda[0], (m * m - 1) / 12.0, 1e-12 * m * m) << m;
    EXPECT_EQ(s.lambda[1], 0.0);
    EXPECT_EQ(s.asphericity, 0.0);
    EXPECT_EQ(s.prolateness, 0.0);
  }
}

// On a ring of 30: a rod of 7 segments across the ends (27..29, 0..3) is
// whole again, R_g^2 = 48/12 = 4; one of 3 inside (10..12), 8/12.
TEST(RodClusterShapes, RodsAcrossTheEndsAreUnwrapped) {
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(30.0, Geometry(1)), segment_centres({27, 28, 29, 0, 1, 2, 3, 10, 11, 12}));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].shape.mass, 7);
  EXPECT_FALSE(s[0].wraps);
  EXPECT_NEAR(s[0].shape.Rg * s[0].shape.Rg, 4.0, 1e-12);
  EXPECT_EQ(s[1].shape.mass, 3);
  EXPECT_NEAR(s[1].shape.Rg * s[1].shape.Rg, 8 / 12.0, 1e-12);
}

// Every segment occupied: the one cluster meets itself a ring further on.
TEST(RodClusterShapes, AFullRingWraps) {
  std::vector<int> all;
  for (int i = 0; i < 20; ++i) all.push_back(i);
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(20.0, Geometry(1)), segment_centres(all));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].shape.mass, 20);
  EXPECT_TRUE(s[0].wraps);
}

MassRadius fit_rods(const std::vector<ClusterShape>& s, const std::string& window) {
  return mass_radius(s, 10, parse_window(window, "--fit-mass"));
}

// Runs of 1..200 segments, each alone on its ring: R_g = sqrt((m^2 - 1)/12)
// tends to m/sqrt(12), so the fit from m = 10 gives d_f = 1.
TEST(RodMassRadius, RunsOfSegmentsHaveDimensionOne) {
  ClusterShapes shapes;
  std::vector<ClusterShape> rods;
  for (int m = 1; m <= 200; ++m) {
    std::vector<int> run;
    for (int i = 0; i < m; ++i) run.push_back(5 + i);
    for (const auto& c : shapes.of_particles(ClusterGrid(256.0, Geometry(1)), segment_centres(run))) rods.push_back(c);
  }
  const MassRadius mr = fit_rods(rods, "10:");
  EXPECT_NEAR(mr.d_f, 1, 0.01);
  EXPECT_EQ(mr.wrapping_fraction, 0);
}

// Aggregates of rods are solid rods of length m: R_g^2 = m^2/12, d_f = 1.
TEST(RodMassRadius, AggregatesAreSolidRods) {
  std::vector<double> masses;
  for (int m = 2; m <= 4000; m = m * 5 / 4 + 1) masses.push_back(m);
  const auto s = aggregate_shapes(masses, Geometry(1));
  EXPECT_NEAR(s.back().shape.Rg * s.back().shape.Rg, 4 / 12.0, 1e-12);  // the smallest, m = 2
  EXPECT_EQ(s.back().shape.lambda[1], 0.0);
  EXPECT_NEAR(fit_rods(s, "1:").d_f, 1, 1e-9);
}

// The 1D tables keep R_g (and lambda1 = R_g^2) and drop every shape invariant.
TEST(RodShapeTable, OneDimensionalTablesKeepOnlyTheRadiusOfGyration) {
  EXPECT_EQ(shape_columns(ShapeTable::kClusters, Geometry(1)), (std::vector<std::string>{"t", "mass", "Rg", "lambda1", "wraps"}));
  EXPECT_EQ(shape_columns(ShapeTable::kMassRadius, Geometry(1)),
            (std::vector<std::string>{"t", "m", "dm", "clusters", "Rg", "Rg_err"}));
  EXPECT_EQ(shape_columns(ShapeTable::kSeries, Geometry(1)),
            (std::vector<std::string>{"t", "d_f", "d_f_err", "fit_bins", "fitted_clusters", "wrapping_fraction"}));
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(20.0, Geometry(1)), segment_centres({1, 2, 3}));
  const TableBlock b = shape_block(ShapeTable::kClusters, 1.0, s, fit_rods(s, "1:"), 1, Geometry(1));
  ASSERT_EQ(b.rows.size(), 1u);
  ASSERT_EQ(b.rows[0].size(), 5u);
  EXPECT_NEAR(b.rows[0][2], std::sqrt(8 / 12.0), 1e-12);  // Rg
  EXPECT_NEAR(b.rows[0][3], 8 / 12.0, 1e-12);             // lambda1 = (3^2 - 1)/12
  EXPECT_EQ(b.rows[0][4], 0.0);                           // wraps
}

}  // namespace
}  // namespace coolgas
