// Logarithmic mass bins: every integer mass in exactly one bin, widths add up.
#include "analyze/bins/log_bins.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(LogBins, RejectsNonsense) {
  EXPECT_THROW(LogBins(0, 10), InputError);
  EXPECT_THROW(LogBins(10, 0), InputError);
}

}  // namespace
}  // namespace coolgas
