// Gyration tensors of clusters of known shape: a straight rod, a flat slab and
// a filled ball of unit cells (one particle at each cell centre), and a
// cluster cut by the periodic faces, which must come out whole.
#include "analyze/shape/cluster_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"

namespace coolgas {
namespace {

// One particle at the centre of each cell (i, j, k) of an integer box of side L, shifted by s cells.
std::vector<double> cell_centres(const std::vector<std::array<int, 3>>& cells, int L, const int s[3] = nullptr) {
  std::vector<double> p;
  for (const auto& c : cells)
    for (int a = 0; a < 3; ++a) p.push_back(double((c[a] + (s ? s[a] : 0)) % L) + 0.5);
  return p;
}

Shape only_shape(const std::vector<double>& p, int L) {
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(L, Geometry(3)), p);
  EXPECT_EQ(s.size(), 1u);
  EXPECT_FALSE(s[0].wraps);
  return s[0].shape;
}

// A rod of n cells: variance of n equally spaced points, (n^2 - 1)/12, along
// it and 0 across; asphericity 1, prolateness 2.
TEST(ClusterShape, RodHasOneEigenvalue) {
  const int n = 15;
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < n; ++i) cells.push_back({3, 4 + i, 5});
  const Shape s = only_shape(cell_centres(cells, 32), 32);
  EXPECT_EQ(s.mass, n);
  EXPECT_NEAR(s.lambda[0], 0, 1e-12);
  EXPECT_NEAR(s.lambda[1], 0, 1e-12);
  EXPECT_NEAR(s.lambda[2], (n * n - 1) / 12.0, 1e-12);
  EXPECT_NEAR(s.asphericity, 1, 1e-12);
  EXPECT_NEAR(s.prolateness, 2, 1e-12);
}

// An n x n slab: (n^2 - 1)/12 twice and 0; asphericity 1/4, prolateness -1/4.
TEST(ClusterShape, SlabHasTwoEqualEigenvalues) {
  const int n = 9;
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) cells.push_back({2 + i, 7, 1 + k});
  const Shape s = only_shape(cell_centres(cells, 20), 20);
  EXPECT_NEAR(s.lambda[0], 0, 1e-12);
  EXPECT_NEAR(s.lambda[1], (n * n - 1) / 12.0, 1e-12);
  EXPECT_NEAR(s.lambda[2], (n * n - 1) / 12.0, 1e-12);
  EXPECT_NEAR(s.asphericity, 0.25, 1e-12);
  EXPECT_NEAR(s.prolateness, -0.25, 1e-12);
}

// The cells within R of a cell centre: three equal eigenvalues (cubic
// symmetry), each the mean x^2 of the lattice points, close to the solid
// ball's R^2/5; asphericity and prolateness 0.
TEST(ClusterShape, BallIsIsotropic) {
  const int R = 7;
  std::vector<std::array<int, 3>> cells;
  double x2 = 0;
  for (int i = -R; i <= R; ++i)
    for (int j = -R; j <= R; ++j)
      for (int k = -R; k <= R; ++k)
        if (i * i + j * j + k * k <= R * R) cells.push_back({10 + i, 10 + j, 10 + k}), x2 += i * i;
  x2 /= double(cells.size());
  const Shape s = only_shape(cell_centres(cells, 24), 24);
  for (double l : s.lambda) EXPECT_NEAR(l, x2, 1e-9);
  EXPECT_NEAR(x2, R * R / 5.0, 0.05 * R * R / 5.0);
  EXPECT_NEAR(s.Rg, std::sqrt(3 * x2), 1e-9);
  EXPECT_NEAR(s.asphericity, 0, 1e-12);
  EXPECT_NEAR(s.prolateness, 0, 1e-12);
}

// A lattice animal (random walk of cells, random points inside them) moved by
// whole cells so that it straddles all three periodic faces: the same
// tensor as where it lay whole inside the box.
TEST(ClusterShape, ClusterCutByThePeriodicFacesIsUnwrapped) {
  const int L = 30;
  Random rng(5);
  std::vector<std::array<int, 3>> cells{{5, 5, 5}};
  while (cells.size() < 200) {
    auto c = cells[rng.below(cells.size())];
    c[rng.below(3)] += rng.below(2) ? 1 : -1;
    cells.push_back(c);  // repeats put two particles in one cell
  }
  std::vector<double> jitter(3 * cells.size());
  for (double& j : jitter) j = rng.uniform() - 0.5;
  auto points = [&](const int s[3]) {
    auto p = cell_centres(cells, L, s);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] += 0.98 * jitter[i];
    return p;
  };
  const int none[3] = {0, 0, 0}, across[3] = {22, 19, 24};
  const Shape inside = only_shape(points(none), L), cut = only_shape(points(across), L);
  EXPECT_EQ(cut.mass, 200);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(cut.lambda[i], inside.lambda[i], 1e-9 * inside.lambda[2]);
  EXPECT_GT(inside.Rg, 1.5);  // a cluster of some extent, not a point
}

// A ring closing on itself through the periodic faces winds around the box.
TEST(ClusterShape, ClusterSpanningTheBoxIsFlaggedAsWrapping) {
  const int L = 12;
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < L; ++i) cells.push_back({i, 3, 3});
  cells.push_back({5, 8, 8});
  ClusterShapes shapes;
  const auto s = shapes.of_particles(ClusterGrid(L, Geometry(3)), cell_centres(cells, L));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_TRUE(s[0].wraps);
  EXPECT_EQ(s[0].shape.mass, L);
  EXPECT_FALSE(s[1].wraps);
}

// Aggregates: solid spheres of diameter m^(1/3), R_g^2 = (3/5)(d/2)^2.
TEST(ClusterShape, AggregatesAreSolidSpheres) {
  const std::vector<double> m{8, 27, 1};
  const auto s = aggregate_shapes(m, Geometry(3));
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].shape.mass, 27);
  EXPECT_NEAR(s[0].shape.Rg, std::sqrt(0.6) * 1.5, 1e-12);
  EXPECT_NEAR(s[1].shape.Rg, std::sqrt(0.6) * 1.0, 1e-12);
}

}  // namespace
}  // namespace coolgas
