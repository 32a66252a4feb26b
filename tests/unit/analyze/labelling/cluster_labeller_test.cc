// The cluster labeller against a slow exact reference: a breadth-first flood
// fill over the periodic grid, cell by cell, with the six face neighbours
// from modular arithmetic (nothing shared with the run-based labeller but the
// cell of each particle). The cluster definition is the paper's (Pathak et
// al. 2014, Sec. IV; tests/physics/README.md): unit cells, occupied when they hold
// a centre, face neighbours, periodic boundaries.
#include "analyze/labelling/cluster_labeller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <queue>

#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

// Flood fill: component id of every cell (-1 if empty) and the component masses.
struct Reference {
  std::vector<int> component;
  std::vector<std::int64_t> mass;
};

Reference flood_fill(const ClusterGrid& g, const std::vector<double>& pos) {
  const int n = g.per_side();
  std::vector<std::int64_t> count(static_cast<std::size_t>(g.cells()), 0);
  for (std::size_t p = 0; p < pos.size(); p += 3) ++count[g.cell_of(pos[p], pos[p + 1], pos[p + 2])];
  Reference r;
  r.component.assign(count.size(), -1);
  auto index = [n](int i, int j, int k) { return ((i + n) % n) + n * (((j + n) % n) + n * ((k + n) % n)); };
  for (int start = 0; start < int(count.size()); ++start) {
    if (count[start] == 0 || r.component[start] >= 0) continue;
    const int id = int(r.mass.size());
    r.mass.push_back(0);
    std::queue<int> todo;
    todo.push(start);
    r.component[start] = id;
    while (!todo.empty()) {
      const int c = todo.front();
      todo.pop();
      r.mass[id] += count[c];
      const int i = c % n, j = (c / n) % n, k = c / (n * n);
      const std::array<int, 6> nb = {index(i + 1, j, k), index(i - 1, j, k), index(i, j + 1, k),
                                     index(i, j - 1, k), index(i, j, k + 1), index(i, j, k - 1)};
      for (int b : nb) {
        if (count[b] == 0 || r.component[b] >= 0) continue;
        r.component[b] = id;
        todo.push(b);
      }
    }
  }
  return r;
}

// Same partition of the cells (a bijection between reference components and
// labeller roots) and the same masses.
void expect_same_clusters(const ClusterGrid& g, const std::vector<double>& pos) {
  const Reference ref = flood_fill(g, pos);
  ClusterLabeller lab;
  lab.label(g, pos);
  std::map<int, std::int32_t> root_of_component;
  std::map<std::int32_t, int> component_of_root;
  for (std::int64_t c = 0; c < g.cells(); ++c) {
    const std::int32_t root = lab.cluster_of(c);
    ASSERT_EQ(root < 0, ref.component[c] < 0) << "cell " << c;
    if (root < 0) continue;
    const auto [it1, new1] = root_of_component.try_emplace(ref.component[c], root);
    const auto [it2, new2] = component_of_root.try_emplace(root, ref.component[c]);
    ASSERT_EQ(it1->second, root) << "cell " << c << " split from its reference cluster";
    ASSERT_EQ(it2->second, ref.component[c]) << "cell " << c << " merged into a foreign cluster";
  }
  std::vector<std::int64_t> got, want = ref.mass;
  lab.for_each_mass([&](std::int64_t m) { got.push_back(m); });
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

std::vector<double> random_positions(double L, std::size_t n, std::uint64_t seed) {
  Random rng(seed);
  std::vector<double> pos(3 * n);
  for (double& x : pos) x = L * rng.uniform();
  return pos;
}

// Random occupancy on both sides of the site-percolation threshold of the
// simple cubic lattice (p_c = 0.3116, Stauffer & Aharony, "Introduction to
// Percolation Theory", Table 2): many small clusters, and one that spans
// and wraps the box. Box sides include non-integers and the tiny grids
// ncell = 1, 2, 3 whose periodic neighbours coincide.
TEST(ClusterLabeller, MatchesFloodFillOnRandomGrids) {
  int seed = 1;
  for (double L : {1.0, 2.5, 3.0, 5.7, 12.0, 23.0}) {
    for (double occupancy : {0.05, 0.2, 0.3116, 0.45, 0.9}) {
      const double cells = std::pow(std::floor(L), 3);
      // Poisson occupancy 1 - exp(-n/cells) = occupancy.
      const auto n = static_cast<std::size_t>(std::ceil(-cells * std::log(1 - occupancy)));
      SCOPED_TRACE("L = " + std::to_string(L) + ", occupancy " + std::to_string(occupancy));
      expect_same_clusters(ClusterGrid(L, Geometry(3)), random_positions(L, n, seed++));
    }
  }
}

// Rows longer than one 64-bit word: runs and contacts that cross word
// boundaries, and the periodic x face between different words.
TEST(ClusterLabeller, MatchesFloodFillOnRowsOfSeveralWords) {
  int seed = 100;
  for (double L : {64.0, 65.0, 70.5, 129.0}) {
    for (double occupancy : {0.3116, 0.7}) {
      const double cells = std::pow(std::floor(L), 3);
      const auto n = static_cast<std::size_t>(std::ceil(-cells * std::log(1 - occupancy)));
      SCOPED_TRACE("L = " + std::to_string(L) + ", occupancy " + std::to_string(occupancy));
      expect_same_clusters(ClusterGrid(L, Geometry(3)), random_positions(L, n, seed++));
    }
  }
  // One line of occupied cells along x through the whole row closes through the face.
  std::vector<double> line;
  for (int i = 0; i < 129; ++i) line.insert(line.end(), {i + 0.5, 3.5, 7.5});
  ClusterLabeller lab;
  lab.label(ClusterGrid(129.0, Geometry(3)), line);
  EXPECT_EQ(lab.clusters(), 1u);
}

// Clustered configurations: particles in Gaussian blobs around random
// centres, wrapped into the box, so most blobs near a face, edge or corner
// cross it.
TEST(ClusterLabeller, MatchesFloodFillOnClusteredGrids) {
  Random rng(42);
  const double L = 20.0;
  auto u = [&] { return L * rng.uniform(); };
  for (double spread : {0.8, 1.5, 3.0}) {
    std::vector<double> pos;
    for (int blob = 0; blob < 40; ++blob) {
      const double c[3] = {u(), u(), u()};
      for (int p = 0; p < 60; ++p)
        for (int d = 0; d < 3; ++d) {
          double x = std::fmod(c[d] + spread * rng.normal(), L);
          pos.push_back(x < 0 ? x + L : x);
        }
    }
    SCOPED_TRACE("spread " + std::to_string(spread));
    expect_same_clusters(ClusterGrid(L, Geometry(3)), pos);
  }
}

// One particle at the centre of each listed cell of a grid with ncell = 6.
std::vector<double> particles_in_cells(const std::vector<std::array<int, 3>>& cells) {
  std::vector<double> pos;
  for (const auto& c : cells)
    for (int d = 0; d < 3; ++d) pos.push_back(c[d] + 0.5);
  return pos;
}

std::vector<std::int64_t> sorted_masses(const std::vector<double>& pos) {
  ClusterLabeller lab;
  lab.label(ClusterGrid(6.0, Geometry(3)), pos);
  std::vector<std::int64_t> m;
  for (const auto& c : lab.ranked()) m.push_back(c.mass);
  return m;
}

TEST(ClusterLabeller, ClustersWrapAcrossFacesEdgesAndCorners) {
  // Across the x face: (5,2,2)-(0,2,2).
  EXPECT_EQ(sorted_masses(particles_in_cells({{5, 2, 2}, {0, 2, 2}})), (std::vector<std::int64_t>{2}));
  // Around the edge x = y = 0: the four cells {5,0} x {5,0} x {3} form a ring.
  EXPECT_EQ(sorted_masses(particles_in_cells({{5, 5, 3}, {0, 5, 3}, {5, 0, 3}, {0, 0, 3}})),
            (std::vector<std::int64_t>{4}));
  // Around the corner: the eight cells {5,0}^3 are one cluster.
  std::vector<std::array<int, 3>> corner;
  for (int i : {5, 0})
    for (int j : {5, 0})
      for (int k : {5, 0}) corner.push_back({i, j, k});
  EXPECT_EQ(sorted_masses(particles_in_cells(corner)), (std::vector<std::int64_t>{8}));
  // Cells meeting only at an edge or a corner (across the boundary) are not neighbours.
  EXPECT_EQ(sorted_masses(particles_in_cells({{0, 0, 2}, {5, 5, 2}})), (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(sorted_masses(particles_in_cells({{0, 0, 0}, {5, 5, 5}})), (std::vector<std::int64_t>{1, 1}));
  // A line of cells along x closes on itself through the face: one cluster, mass 6.
  EXPECT_EQ(sorted_masses(particles_in_cells({{0, 1, 1}, {1, 1, 1}, {2, 1, 1}, {3, 1, 1}, {4, 1, 1}, {5, 1, 1}})),
            (std::vector<std::int64_t>{6}));
}

TEST(ClusterLabeller, MassCountsParticlesNotCells) {
  // 300 centres in one cell and 2 in its +x neighbour, 1 alone.
  std::vector<double> pos;
  for (int p = 0; p < 300; ++p) pos.insert(pos.end(), {0.1 + 0.001 * p, 0.5, 0.5});
  pos.insert(pos.end(), {1.5, 0.5, 0.5, 1.6, 0.5, 0.5, 3.5, 3.5, 3.5});
  EXPECT_EQ(sorted_masses(pos), (std::vector<std::int64_t>{302, 1}));
}

TEST(ClusterLabeller, RankedIsMassDescendingThenSmallestCell) {
  // Two clusters of mass 2 and one of mass 3; the mass-2 cluster holding cell
  // (1,0,0) (index 1) comes before the one holding (3,3,3).
  const auto pos = particles_in_cells({{3, 3, 3}, {3, 3, 4}, {1, 0, 0}, {1, 1, 0}, {1, 3, 0}, {1, 3, 1}, {1, 3, 2}});
  ClusterLabeller lab;
  lab.label(ClusterGrid(6.0, Geometry(3)), pos);
  const auto r = lab.ranked();
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].mass, 3);
  EXPECT_EQ(r[1].mass, 2);
  EXPECT_EQ(r[1].first_cell, 1);
  EXPECT_EQ(r[2].mass, 2);
  EXPECT_EQ(r[2].first_cell, 3 + 6 * (3 + 6 * 3));
  for (const auto& c : r) EXPECT_EQ(lab.cluster_of(c.first_cell), c.id);
}

TEST(ClusterGrid, FloorLCellsOfWidthLOverFloorL) {
  const ClusterGrid g(5.5, Geometry(3));
  EXPECT_EQ(g.per_side(), 5);
  EXPECT_DOUBLE_EQ(g.width(), 1.1);
  EXPECT_EQ(g.cell_1d(1.0), 0);  // 1.0 / 1.1 < 1
  EXPECT_EQ(g.cell_1d(1.15), 1);
  EXPECT_EQ(g.cell_1d(5.5), 4);     // x = L (round-off) clamps into the last cell
  EXPECT_EQ(g.cell_1d(-1e-15), 0);  // and just below 0 into the first
  EXPECT_EQ(g.cell_of(1.15, 0, 2.3), 1 + 5 * (0 + 5 * 2));
  EXPECT_THROW(ClusterGrid(0.9, Geometry(3)), InputError);
  EXPECT_THROW(ClusterGrid(std::nan(""), Geometry(3)), InputError);
  EXPECT_THROW(ClusterGrid(1251.0, Geometry(3)), InputError);  // too many cells for int32 run numbers
  EXPECT_NO_THROW(ClusterGrid(1250.9, Geometry(3)));
}

}  // namespace
}  // namespace coolgas
