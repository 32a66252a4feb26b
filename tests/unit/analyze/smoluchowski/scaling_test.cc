// Physics of the paper's kernel Eq. (4): homogeneity λ = 1/6, so the mean mass
// grows as t^{1/(1−λ)} = t^{6/5} at late times (Leyvraz, Phys. Rep. 383, 95
// (2003), Sec. 3; the paper's text after Eq. 4).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/smoluchowski/run.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {
namespace {

TEST(SmoluchowskiScaling, MeanMassOfBallisticKernelGrowsAsTSixFifths) {
  RunOptions o;
  o.kernel = "ballistic";
  o.method.M = 1 << 14;
  o.integrator = {1e-9, 1e-16, Stepper::Rkck};
  o.t_end = 40;
  o.series = true;
  o.series_t_min = 1;
  std::ostringstream out, warn;
  run(o, out, warn);
  EXPECT_EQ(warn.str(), "");  // no mass leaked past M
  std::istringstream in(out.str());
  const Table t = read_table(in, "series");
  // Least-squares slope of log M_avg against log t over the last decade.
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  const auto time = t.column_values("t"), mean = t.column_values("M_avg");
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < 4) continue;
    const double x = std::log(time[i]), y = std::log(mean[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, n += 1;
  }
  ASSERT_GE(n, 10);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, 6.0 / 5, 0.02);
}

}  // namespace
}  // namespace coolgas::smoluchowski
