// The validator's overlap check (data-schema/value_checks.h): exact on
// pairs placed by hand, periodic, by diameters, and the same as all pairs
// on random frames (the cell list misses nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "common/random.h"
#include "data-schema/value_checks.h"

namespace coolgas::schema {
namespace {

Finding check(const std::vector<double>& r, const std::vector<double>& d, double L) {
  return check_no_overlaps(r, d, {}, L, Geometry(3));
}

TEST(OverlapCheck, TouchingIsAllowedOverlapIsNot) {
  const double L = 10;
  EXPECT_FALSE(check({1, 1, 1, 2, 1, 1}, {}, L));  // unit spheres at contact
  EXPECT_FALSE(check({1, 1, 1, 2 - 0.5e-9, 1, 1}, {}, L));  // within the tolerance
  EXPECT_TRUE(check({1, 1, 1, 2 - 2e-9, 1, 1}, {}, L));
  EXPECT_TRUE(check({0.2, 5, 5, 9.5, 5, 5}, {}, L));  // 0.7 apart across the boundary
  EXPECT_FALSE(check({0.2, 5, 5, 9.2, 5, 5}, {}, L));  // exactly 1 apart across it
}

// An aggregate wider than L/4 is checked against every sphere: one of
// diameter 6 overlaps a unit sphere 3.4 from its centre (contact 3.5).
TEST(OverlapCheck, AggregatesUseTheirDiametersAndIds) {
  const double L = 20;
  const std::vector<double> r{5, 5, 5, 8.4, 5, 5, 15, 15, 15};
  const std::vector<double> d{6, 1, 1};
  const std::vector<std::int32_t> id{7, 12, 30};
  const Finding f = check_no_overlaps(r, d, id, L, Geometry(3));
  ASSERT_TRUE(f);
  EXPECT_NE(f->find("particles 7 and 12 overlap"), std::string::npos) << *f;
  EXPECT_FALSE(check({5, 5, 5, 8.5, 5, 5}, {6, 1}, L));
}

// Random frames of mixed diameters: the finding (its count of pairs) is
// that of the plain test of every pair.
TEST(OverlapCheck, SameAsAllPairsOnRandomFrames) {
  Random rng(41);
  for (int frame = 0; frame < 20; ++frame) {
    const double L = 12;
    const std::size_t n = 200;
    std::vector<double> r(3 * n), d(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) r[3 * i + std::size_t(k)] = L * rng.uniform();
      d[i] = frame % 2 ? 0.3 + 0.5 * rng.uniform() : (rng.uniform() < 0.02 ? 4 : 0.6);
    }
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
          double x = r[3 * j + std::size_t(k)] - r[3 * i + std::size_t(k)];
          x -= L * std::round(x / L);
          s += x * x;
        }
        pairs += std::sqrt(s) < 0.5 * (d[i] + d[j]) * (1 - kOverlapTolerance);
      }
    const Finding f = check(r, d, L);
    ASSERT_EQ(bool(f), pairs > 0) << frame;
    if (pairs > 1) {
      EXPECT_NE(f->find("(and " + std::to_string(pairs - 1) + " more)"), std::string::npos) << *f;
    }
  }
}

}  // namespace
}  // namespace coolgas::schema
