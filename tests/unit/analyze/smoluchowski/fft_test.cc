// The FFT method solves the same truncated equation as the direct reference:
// the two agree to 1e-10 of the peak, for every kernel shape.
#include <gtest/gtest.h>

#include "analyze/smoluchowski/observables.h"
#include "tests/unit/analyze/smoluchowski/test_support.h"

namespace coolgas::smoluchowski {
namespace {

using testing::max_difference;
using testing::run;

TEST(SmoluchowskiFft, AgreesWithDirectToOneInTenToTheTen) {
  struct C {
    const char* kernel;
    double t;
  };
  for (const C& c : {C{"constant", 10}, C{"additive", 1.5}, C{"product", 0.8}, C{"ballistic", 3},
                     C{"separable:1,0.3,-0.2;0.25,0.9,0", 2}}) {
    const auto direct = run(c.kernel, Method::Direct, 512, c.t);
    const auto fft = run(c.kernel, Method::Fft, 512, c.t);
    EXPECT_LT(max_difference(fft.c, direct.c), 1e-10) << c.kernel;
    const auto a = moments(fft.grid, fft.c), b = moments(direct.grid, direct.c);
    EXPECT_NEAR(a.M0 / b.M0, 1, 1e-10) << c.kernel;
    EXPECT_NEAR(a.M2 / b.M2, 1, 1e-10) << c.kernel;
  }
}

TEST(SmoluchowskiFft, ConservesMassAndStaysNonNegative) {
  // t = 8: mean mass about 60, so nothing reaches M = 4096.
  const auto s = run("ballistic", Method::Fft, 4096, 8);
  EXPECT_NEAR(moments(s.grid, s.c).M1, 1, 1e-10);
  for (double x : s.c) ASSERT_GE(x, 0.0);
}

TEST(SmoluchowskiFft, SameResultRunToRun) {
  // FFTW_ESTIMATE plans: the arithmetic, hence every bit, repeats.
  const auto a = run("ballistic", Method::Fft, 1024, 2);
  const auto b = run("ballistic", Method::Fft, 1024, 2);
  EXPECT_EQ(a.c, b.c);
}

}  // namespace
}  // namespace coolgas::smoluchowski
