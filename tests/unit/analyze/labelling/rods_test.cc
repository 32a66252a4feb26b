// The cluster labeller on a 1D grid (rods on a ring: floor(L) unit segments,
// one row, neighbours left and right, periodic): a hand-made configuration
// counted exactly, random rods against a walk along the ring, and random
// occupation of the segments against 1D site percolation, whose threshold
// is p_c = 1: at occupation p the clusters are geometric, a fraction
// (1 - p) p^(s-1) of them of s segments, so the mean cluster is 1/(1 - p)
// segments and the mean weighted by size (1 + p)/(1 - p) (Stauffer &
// Aharony, section 2.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analyze/labelling/cluster_labeller.h"
#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

// Rod centres as the frame reader gives them: 3 numbers each, y = z = 0.
std::vector<double> rods(const std::vector<double>& x) {
  std::vector<double> p;
  for (double c : x) p.insert(p.end(), {c, 0.0, 0.0});
  return p;
}

std::vector<std::int64_t> sorted_rod_masses(const ClusterLabeller& lab) {
  std::vector<std::int64_t> m;
  lab.for_each_mass([&](std::int64_t x) { m.push_back(x); });
  std::sort(m.begin(), m.end(), std::greater<>());
  return m;
}

// The cluster masses of a walk round the ring of n = floor(L) segments: runs
// of occupied segments, the run through the last segment joined to the run
// through the first.
std::vector<std::int64_t> ring_walk_masses(double L, const std::vector<double>& pos) {
  const int n = int(std::floor(L));
  const double w = L / n;
  std::vector<std::int64_t> count(std::size_t(n), 0);
  for (std::size_t p = 0; p < pos.size(); p += 3) ++count[std::size_t(std::min(n - 1, int(pos[p] / w)))];
  std::vector<std::int64_t> masses;
  bool open = false;
  for (int i = 0; i < n; ++i) {
    if (count[std::size_t(i)] == 0) open = false;
    else if (open) masses.back() += count[std::size_t(i)];
    else masses.push_back(count[std::size_t(i)]), open = true;
  }
  // A run reaching the last segment continues into the run starting at 0.
  if (masses.size() > 1 && count[0] > 0 && count[std::size_t(n - 1)] > 0) {
    masses.front() += masses.back();
    masses.pop_back();
  }
  std::sort(masses.begin(), masses.end(), std::greater<>());
  return masses;
}

// On a ring of 10 segments: segment 0 with two rods, 1 and 9 join it across
// the ends (mass 4); 5 and 6 touch (mass 2); 3 is alone (mass 1).
TEST(RodClusters, AHandMadeConfigurationIsCountedExactly) {
  const ClusterGrid grid(10.0, Geometry(1));
  EXPECT_EQ(grid.cells(), 10);
  EXPECT_EQ(grid.rows_per_plane(), 1);
  EXPECT_EQ(grid.planes(), 1);
  ClusterLabeller lab;
  lab.label(grid, rods({0.2, 0.7, 1.5, 9.9, 3.5, 5.5, 6.2}));
  EXPECT_EQ(sorted_rod_masses(lab), (std::vector<std::int64_t>{4, 2, 1}));
  const auto ranked = lab.ranked();
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0].first_cell, 0);
  EXPECT_EQ(ranked[1].first_cell, 5);
  EXPECT_EQ(ranked[2].first_cell, 3);
  EXPECT_EQ(lab.cluster_of(9), ranked[0].id);  // segment 9 wraps onto segment 0
  EXPECT_EQ(lab.cluster_of(6), ranked[1].id);
  EXPECT_EQ(lab.cluster_of(4), -1);
}

// Every segment occupied: one cluster all the way round (the ring of 3 is the
// smallest whose ends are not already neighbours inside it).
TEST(RodClusters, AFullRingIsOneCluster) {
  for (int n : {1, 2, 3, 64, 65, 200}) {
    std::vector<double> x;
    for (int i = 0; i < n; ++i) x.push_back(i + 0.5);
    ClusterLabeller lab;
    lab.label(ClusterGrid(n, Geometry(1)), rods(x));
    EXPECT_EQ(sorted_rod_masses(lab), (std::vector<std::int64_t>{n})) << n;
  }
}

TEST(RodClusters, MatchTheWalkRoundTheRingOnRandomRods) {
  std::uint64_t seed = 60;
  for (double L : {3.0, 5.7, 64.0, 130.4, 10000.5}) {  // rows of one to 157 words
    for (double occupancy : {0.1, 0.5, 0.9, 0.99}) {
      const auto n = static_cast<std::size_t>(std::ceil(-std::floor(L) * std::log(1 - occupancy)));
      Random rng(seed++);
      std::vector<double> pos(3 * n, 0.0);
      for (std::size_t p = 0; p < n; ++p) pos[3 * p] = L * rng.uniform();
      ClusterLabeller lab;
      lab.label(ClusterGrid(L, Geometry(1)), pos);
      EXPECT_EQ(sorted_rod_masses(lab), ring_walk_masses(L, pos)) << "L = " << L << ", occupancy " << occupancy;
    }
  }
}

// Each of 2^21 segments holds one rod with probability p: the number-average
// cluster size and the size-weighted one, sum s^2 / sum s, against 1/(1 - p)
// and (1 + p)/(1 - p) within 4 standard errors (from the sample's own
// spread of s and s^2 over the clusters).
TEST(RodClusters, RandomOccupationIsOneDimensionalPercolation) {
  const int n = 1 << 21;
  std::uint64_t seed = 70;
  for (double p : {0.3, 0.5, 0.8}) {
    Random rng(seed++);
    std::vector<double> x;
    for (int i = 0; i < n; ++i)
      if (rng.uniform() < p) x.push_back(i + 0.5);
    ClusterLabeller lab;
    lab.label(ClusterGrid(n, Geometry(1)), rods(x));
    double k = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
    lab.for_each_mass([&](std::int64_t m) {
      const double s = double(m);
      k += 1, s1 += s, s2 += s * s, s3 += s * s * s, s4 += s * s * s * s;
    });
    const double mean = s1 / k, mean_err = std::sqrt((s2 / k - mean * mean) / k);
    EXPECT_LT(std::abs(mean - 1 / (1 - p)), 4 * mean_err) << "p = " << p << ": " << mean << " +- " << mean_err;
    // S = sum s^2 / sum s; its error to first order from the cluster-by-cluster
    // spread of s^2 - S s (the delta method for a ratio of sums).
    const double S = s2 / s1;
    const double var = s4 / k - 2 * S * s3 / k + S * S * s2 / k;
    const double S_err = std::sqrt(var * k) / s1;
    EXPECT_LT(std::abs(S - (1 + p) / (1 - p)), 4 * S_err) << "p = " << p << ": " << S << " +- " << S_err;
  }
}

// A line holds far more cells than a plane: the grid takes rings up to
// L < 2^31 - 64, and no 1D cell index overflows.
TEST(RodClusters, TheGridTakesRingsUpToTwoToThe31) {
  EXPECT_THROW(ClusterGrid(40001.0, Geometry(2)), InputError);
  EXPECT_EQ(ClusterGrid(1e9, Geometry(1)).cells(), 1'000'000'000);
  EXPECT_THROW(ClusterGrid(2147483584.0, Geometry(1)), InputError);
  EXPECT_THROW(ClusterGrid(0.5, Geometry(1)), InputError);
}

}  // namespace
}  // namespace coolgas
