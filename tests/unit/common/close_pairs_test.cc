// common/close_pairs.h: every pair within reach is offered, in d = 1, 2, 3
// (the same set as the plain test of all pairs), and the work stays O(n):
// about the d-th root of n cells per side, whatever d. PairsWithin gives
// each pair within reach once, with the squared distance of the callers'
// formula to the last bit, in boxes from every pair (too few cells) to
// many cells of half the reach.
#include "common/close_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
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

// The squared minimum-image distance as g(r) and the contact labeller
// summed it before PairsWithin: |x_j - x_i|, folded at L/2, x then y then z.
double callers_r2(const std::vector<double>& p, std::size_t i, std::size_t j, double L) {
  double r2 = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    double dx = std::abs(p[3 * j + k] - p[3 * i + k]);
    dx = dx > 0.5 * L ? L - dx : dx;
    r2 += dx * dx;
  }
  return r2;
}

TEST(PairsWithin, EachPairWithinReachOnceWithTheCallersDistance) {
  Random rng(7);
  for (int d = 1; d <= 3; ++d) {
    const Geometry g(d);
    for (const double L : {2.5, 12.0, 40.0})
      for (const double reach : {1.0, 1.1, 0.3 * L, 0.5 * L}) {
        SCOPED_TRACE(std::to_string(d) + "D, L = " + std::to_string(L) + ", reach = " + std::to_string(reach));
        std::vector<double> p;
        for (const auto& r : random_points(d == 1 ? 200 : 400, L, g, rng)) p.insert(p.end(), r.begin(), r.end());
        const std::size_t n = p.size() / 3;
        std::map<std::pair<std::size_t, std::size_t>, double> want;
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = i + 1; j < n; ++j)
            if (const double r2 = callers_r2(p, i, j, L); r2 < reach * reach) want[{i, j}] = r2;
        const PairsWithin pairs(p, reach, L, g);
        ASSERT_EQ(pairs.size(), n);
        std::map<std::pair<std::size_t, std::size_t>, double> got;
        pairs.for_each([&](std::size_t a, std::size_t b, double r2) {
          EXPECT_NE(a, b);
          const std::size_t i = pairs.index(a), j = pairs.index(b);
          EXPECT_TRUE(got.emplace(std::minmax(i, j), r2).second) << "twice: " << i << ", " << j;
        });
        EXPECT_EQ(got.size(), want.size());
        for (const auto& [ij, r2] : want) {
          const auto it = got.find(ij);
          ASSERT_NE(it, got.end()) << ij.first << ", " << ij.second;
          EXPECT_EQ(std::bit_cast<std::uint64_t>(it->second), std::bit_cast<std::uint64_t>(r2));
        }
      }
  }
}

}  // namespace
}  // namespace coolgas
