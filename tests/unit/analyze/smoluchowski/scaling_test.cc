// Physics of the ballistic kernels: the paper's Eq. (4) has homogeneity
// λ = 1/6, so the mean mass grows as t^{1/(1−λ)} = t^{6/5} at late times
// (Leyvraz, Phys. Rep. 383, 95 (2003), Sec. 3; the paper's text after Eq. 4);
// the same kernel in d dimensions, (i^-1/2 + j^-1/2)(i^1/d + j^1/d)^(d-1),
// has λ = (d-2)/(2d) and the mean-field exponent 2d/(d+2): t^1 for disks,
// t^{2/3} for rods.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/smoluchowski/kernel.h"
#include "analyze/smoluchowski/run.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {
namespace {

// Least-squares slope of log M_avg against log t for t >= t_from.
double late_slope(const std::string& kernel, double t_end, double t_from) {
  RunOptions o;
  o.kernel = kernel;
  o.method.M = 1 << 14;
  o.integrator = {1e-9, 1e-16, Stepper::Rkck};
  o.t_end = t_end;
  o.series = true;
  o.series_t_min = 1;
  std::ostringstream out, warn;
  run(o, out, warn);
  EXPECT_EQ(warn.str(), "");  // no mass leaked past M
  std::istringstream in(out.str());
  const Table t = read_table(in, "series");
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  const auto time = t.column_values("t"), mean = t.column_values("M_avg");
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < t_from) continue;
    const double x = std::log(time[i]), y = std::log(mean[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, n += 1;
  }
  EXPECT_GE(n, 10);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(SmoluchowskiScaling, MeanMassOfBallisticKernelGrowsAsTSixFifths) {
  EXPECT_NEAR(late_slope("ballistic", 40, 4), 6.0 / 5, 0.02);
}

TEST(SmoluchowskiScaling, MeanMassOfTheTwoDimensionalBallisticKernelGrowsAsT) {
  EXPECT_NEAR(late_slope("ballistic2d", 400, 40), 1.0, 0.02);
}

TEST(SmoluchowskiScaling, MeanMassOfTheOneDimensionalBallisticKernelGrowsAsTTwoThirds) {
  EXPECT_NEAR(late_slope("ballistic1d", 4000, 400), 2.0 / 3, 0.02);
}

// K(i, j) = (i^-1/2 + j^-1/2)(i^1/d + j^1/d)^(d-1) at i = 1, j = 4 and 8, and its homogeneity.
TEST(SmoluchowskiScaling, BallisticKernelsInEveryDimension) {
  const Kernel k3 = parse_kernel("ballistic"), k2 = parse_kernel("ballistic2d"), k1 = parse_kernel("ballistic1d");
  for (double j : {4.0, 8.0}) {
    const double speed = 1 + 1 / std::sqrt(j);
    EXPECT_NEAR(k3(1, j), speed * std::pow(1 + std::cbrt(j), 2), 1e-12);
    EXPECT_NEAR(k2(1, j), speed * (1 + std::sqrt(j)), 1e-12);
    EXPECT_NEAR(k1(1, j), speed, 1e-12);
  }
  EXPECT_NEAR(k3.homogeneity(), 1.0 / 6, 1e-12);
  EXPECT_EQ(k2.homogeneity(), 0.0);
  EXPECT_EQ(k1.homogeneity(), -0.5);
}

}  // namespace
}  // namespace coolgas::smoluchowski
