// The cluster labeller on a 2D grid (disks: floor(L)^2 unit squares, one
// plane, edge neighbours, periodic): a hand-made configuration counted
// exactly, and random ones against a flood fill over the four edge
// neighbours of each square, on both sides of the square lattice's site
// percolation threshold p_c = 0.5927 (Stauffer & Aharony, Table 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>

#include "analyze/labelling/cluster_labeller.h"
#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

// Disk centres as the frame reader gives them: 3 numbers each, z = 0.
std::vector<double> disks(const std::vector<std::array<double, 2>>& xy) {
  std::vector<double> p;
  for (const auto& c : xy) p.insert(p.end(), {c[0], c[1], 0.0});
  return p;
}

std::vector<std::int64_t> sorted_masses(const ClusterLabeller& lab) {
  std::vector<std::int64_t> m;
  lab.for_each_mass([&](std::int64_t x) { m.push_back(x); });
  std::sort(m.begin(), m.end(), std::greater<>());
  return m;
}

// The cluster masses of a 2D flood fill over squares (i, j), neighbours i +- 1, j +- 1 mod n.
std::vector<std::int64_t> flood_fill_masses(double L, const std::vector<double>& pos) {
  const int n = int(std::floor(L));
  const double w = L / n;
  std::vector<std::int64_t> count(std::size_t(n) * n, 0);
  for (std::size_t p = 0; p < pos.size(); p += 3)
    ++count[std::size_t(std::min(n - 1, int(pos[p] / w)) + n * std::min(n - 1, int(pos[p + 1] / w)))];
  std::vector<bool> seen(count.size(), false);
  std::vector<std::int64_t> masses;
  for (std::size_t start = 0; start < count.size(); ++start) {
    if (count[start] == 0 || seen[start]) continue;
    std::int64_t mass = 0;
    std::queue<std::size_t> todo;
    todo.push(start);
    seen[start] = true;
    while (!todo.empty()) {
      const std::size_t c = todo.front();
      todo.pop();
      mass += count[c];
      const int i = int(c % n), j = int(c / n);
      for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const std::size_t b = std::size_t((i + di + n) % n + n * ((j + dj + n) % n));
        if (count[b] == 0 || seen[b]) continue;
        seen[b] = true;
        todo.push(b);
      }
    }
    masses.push_back(mass);
  }
  std::sort(masses.begin(), masses.end(), std::greater<>());
  return masses;
}

// In a 10 x 10 box: squares (0,0) with two disks, (1,0) and (9,0) join across
// the x face (mass 4); (3,0) and (3,9) join across the y face (mass 2);
// (5,5) and (6,6) touch only at a corner: two clusters of 1.
TEST(DiskClusters, AHandMadeConfigurationIsCountedExactly) {
  const ClusterGrid grid(10.0, Geometry(2));
  EXPECT_EQ(grid.cells(), 100);
  EXPECT_EQ(grid.planes(), 1);
  ClusterLabeller lab;
  lab.label(grid, disks({{0.2, 0.5}, {0.7, 0.1}, {1.5, 0.5}, {9.9, 0.9}, {3.5, 0.0}, {3.5, 9.99}, {5.5, 5.5},
                         {6.5, 6.5}}));
  EXPECT_EQ(sorted_masses(lab), (std::vector<std::int64_t>{4, 2, 1, 1}));
  const auto ranked = lab.ranked();
  ASSERT_EQ(ranked.size(), 4u);
  EXPECT_EQ(ranked[0].first_cell, 0);               // square (0, 0)
  EXPECT_EQ(ranked[1].first_cell, 3);               // square (3, 0)
  EXPECT_EQ(lab.cluster_of(9), ranked[0].id);       // (9, 0) wraps onto (0, 0)
  EXPECT_EQ(lab.cluster_of(3 + 10 * 9), ranked[1].id);
  EXPECT_EQ(lab.cluster_of(4), -1);
}

// A row of squares all the way round the box is one cluster that wraps.
TEST(DiskClusters, AFullRowWrapsIntoOneCluster) {
  std::vector<std::array<double, 2>> row;
  for (int i = 0; i < 7; ++i) row.push_back({i + 0.5, 2.5});
  ClusterLabeller lab;
  lab.label(ClusterGrid(7.0, Geometry(2)), disks(row));
  EXPECT_EQ(sorted_masses(lab), (std::vector<std::int64_t>{7}));
}

TEST(DiskClusters, MatchFloodFillOnRandomSquares) {
  std::uint64_t seed = 40;
  for (double L : {3.0, 5.7, 31.0, 130.4}) {  // 130 squares: rows of three words
    for (double occupancy : {0.1, 0.4, 0.5927, 0.8}) {
      const double cells = std::pow(std::floor(L), 2);
      const auto n = static_cast<std::size_t>(std::ceil(-cells * std::log(1 - occupancy)));
      Random rng(seed++);
      std::vector<double> pos(3 * n, 0.0);
      for (std::size_t p = 0; p < n; ++p) pos[3 * p] = L * rng.uniform(), pos[3 * p + 1] = L * rng.uniform();
      ClusterLabeller lab;
      lab.label(ClusterGrid(L, Geometry(2)), pos);
      EXPECT_EQ(sorted_masses(lab), flood_fill_masses(L, pos)) << "L = " << L << ", occupancy " << occupancy;
    }
  }
}

// 2D grids reach far larger boxes than 3D ones (n^2 cells against n^3).
TEST(DiskClusters, TheGridTakesBoxesUpTo40000) {
  EXPECT_THROW(ClusterGrid(5000.0, Geometry(3)), InputError);
  EXPECT_EQ(ClusterGrid(5000.0, Geometry(2)).cells(), 25'000'000);
  EXPECT_THROW(ClusterGrid(40001.0, Geometry(2)), InputError);
}

}  // namespace
}  // namespace coolgas
