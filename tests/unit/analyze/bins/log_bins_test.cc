// Logarithmic mass bins: every integer mass in exactly one bin, widths add up.
#include "analyze/bins/log_bins.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/error.h"

namespace coolgas {
namespace {

TEST(LogBins, PartitionTheIntegersExactly) {
  LogBins b(10, 100000);
  std::int64_t total = 0;
  for (int k = 0; k < b.size(); ++k) {
    EXPECT_LE(b.lo(k), b.hi(k));
    if (k > 0) {
      EXPECT_EQ(b.lo(k), b.hi(k - 1) + 1);
    }
    total += b.width(k);
  }
  EXPECT_EQ(b.lo(0), 1);
  EXPECT_EQ(b.hi(b.size() - 1), 100000);
  EXPECT_EQ(total, 100000);
  for (std::int64_t m : {1, 2, 7, 10, 11, 99, 100, 12345, 100000}) {
    const int k = b.index(m);
    EXPECT_GE(m, b.lo(k));
    EXPECT_LE(m, b.hi(k));
  }
}

TEST(LogBins, SmallMassesGetOneBinEachLargeOnesConstantLogWidth) {
  LogBins b(10, 1000000);
  EXPECT_EQ(b.width(0), 1);  // m = 1
  EXPECT_EQ(b.width(1), 1);  // m = 2
  // Ten bins per decade: from 10^5 on, consecutive edges grow by 10^(1/10).
  const int k = b.index(200000);
  EXPECT_NEAR(double(b.lo(k + 1)) / double(b.lo(k)), std::pow(10.0, 0.1), 1e-4);
}

// The edges of the plain walk over every k (the definition in log_bins.h),
// which the constructor shortens by jumping over edges that make no bin.
std::vector<std::int64_t> plain_lower_edges(int per_decade, std::int64_t m_max) {
  std::vector<std::int64_t> lows;
  std::int64_t lo = 1;
  for (std::int64_t k = 1; lo <= m_max; ++k) {
    const auto edge = static_cast<std::int64_t>(std::ceil(std::pow(10.0, double(k) / per_decade) - 1e-9));
    if (edge <= lo) continue;
    lows.push_back(lo);
    lo = edge;
  }
  return lows;
}

TEST(LogBins, SameEdgesAsThePlainWalkOverEveryK) {
  for (const int per_decade : {1, 3, 10, 64, 1000, 100000})
    for (const std::int64_t m_max : {1, 9, 1000, 123457}) {
      const LogBins b(per_decade, m_max);
      const std::vector<std::int64_t> lows = plain_lower_edges(per_decade, m_max);
      ASSERT_EQ(std::size_t(b.size()), lows.size()) << per_decade << " " << m_max;
      for (int k = 0; k < b.size(); ++k) ASSERT_EQ(b.lo(k), lows[std::size_t(k)]) << per_decade << " " << m_max;
    }
}

// 10^9 bins per decade walked every k (past 2^31 of them) for minutes: each
// mass gets its own bin, found in O(bins).
TEST(LogBins, AHugeBinDensityGivesOneBinPerMassAtOnce) {
  const LogBins b(1000000000, 100000);
  ASSERT_EQ(b.size(), 100000);
  for (int k = 0; k < b.size(); ++k) ASSERT_EQ(b.lo(k), k + 1);
}

TEST(LogBins, RejectsNonsense) {
  EXPECT_THROW(LogBins(0, 10), InputError);
  EXPECT_THROW(LogBins(10, 0), InputError);
}

}  // namespace
}  // namespace coolgas
