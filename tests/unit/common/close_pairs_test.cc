// common/close_pairs.h: every pair within reach is offered, in d = 1, 2, 3
// (the same set as the plain test of all pairs), and the work stays O(n):
// about the d-th root of n cells per side, whatever d.
#include "common/close_pairs.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "common/random.h"

namespace coolgas {
namespace {

double distance(const std::vector<std::array<double, 3>>& r, std::size_t i, std::size_t j, double L) {
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    double x = r[j][std::size_t(k)] - r[i][std::size_t(k)];
    x -= L * std::round(x / L);
    s += x * x;
  }
  return std::sqrt(s);
}

struct Found {
  std::set<std::pair<std::size_t, std::size_t>> close;
  std::size_t offered = 0;
};

Found close_pairs(const std::vector<std::array<double, 3>>& r, double reach, double L, Geometry g) {
  std::vector<std::size_t> all(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) all[i] = i;
  Found f;
  for_each_close_pair(all, [&](std::size_t i) { return r[i]; }, reach, L, g, [&](std::size_t i, std::size_t j) {
    ++f.offered;
    EXPECT_LT(i, j);
    if (distance(r, i, j, L) < reach) {
      EXPECT_TRUE(f.close.insert({i, j}).second) << "offered twice";
    }
  });
  return f;
}

std::vector<std::array<double, 3>> random_points(std::size_t n, double L, Geometry g, Random& rng) {
  std::vector<std::array<double, 3>> r(n);
  for (auto& p : r)
    for (int k = 0; k < 3; ++k) p[std::size_t(k)] = g.spans(k) ? L * rng.uniform() : 0.0;
  return r;
}

TEST(ClosePairs, SameAsAllPairsInEveryDimension) {
  Random rng(5);
  for (int d = 1; d <= 3; ++d) {
    const Geometry g(d);
    for (const double L : {2.5, 12.0, 40.0}) {
      SCOPED_TRACE(std::to_string(d) + "D, L = " + std::to_string(L));
      const auto r = random_points(300, L, g, rng);
      std::size_t within = 0;
      for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = i + 1; j < r.size(); ++j) within += distance(r, i, j, L) < 1.0;
      EXPECT_EQ(close_pairs(r, 1.0, L, g).close.size(), within);
    }
  }
}

// 20 000 points at one per unit measure: about 2 * 3^d neighbours' worth of
// pairs are offered per point, not the n^(1/3)-per-side cells' hundreds
// (the cube root once sized a 2D grid: 28 cells a side for 20 000 disks).
TEST(ClosePairs, TheWorkIsLinearInTheCount) {
  Random rng(6);
  for (int d = 1; d <= 3; ++d) {
    const Geometry g(d);
    const std::size_t n = 20000;
    const double L = g.root(double(n));
    const Found f = close_pairs(random_points(n, L, g, rng), 1.0, L, g);
    EXPECT_LT(double(f.offered), 0.5 * std::pow(3.0, d) * 2.0 * double(n)) << d << "D";
  }
}

}  // namespace
}  // namespace coolgas
