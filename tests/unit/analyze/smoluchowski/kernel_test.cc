// Kernel strings: the named kernels are the formulas they claim to be, the
// general separable form is read as documented, and nonsense is refused.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/smoluchowski/kernel.h"
#include "common/error.h"

namespace coolgas::smoluchowski {
namespace {

TEST(SmoluchowskiKernel, NamedKernelsAreTheirFormulas) {
  for (double i : {1.0, 2.0, 7.0, 1000.0})
    for (double j : {1.0, 3.0, 64.0}) {
      EXPECT_DOUBLE_EQ(parse_kernel("constant")(i, j), 1.0);
      EXPECT_DOUBLE_EQ(parse_kernel("additive")(i, j), i + j);
      EXPECT_DOUBLE_EQ(parse_kernel("product")(i, j), i * j);
      // The paper's Eq. (4) with prefactor 1.
      const double eq4 = (1 / std::sqrt(i) + 1 / std::sqrt(j)) * std::pow(std::cbrt(i) + std::cbrt(j), 2);
      EXPECT_NEAR(parse_kernel("ballistic")(i, j), eq4, 1e-13 * eq4);
      EXPECT_NEAR(parse_kernel("eq4")(i, j), eq4, 1e-13 * eq4);
    }
}

TEST(SmoluchowskiKernel, BallisticKernelHasSixExponentsAndHomogeneityOneSixth) {
  // tests/physics/README.md: six products with exponents 1/6, -1/6, 1/3, -1/2, 2/3 (and 0).
  const Kernel k = parse_kernel("ballistic");
  EXPECT_EQ(k.exponents().size(), 6u);
  EXPECT_NEAR(k.homogeneity(), 1.0 / 6, 1e-15);
  EXPECT_NEAR(k(8, 8), std::pow(8.0, 1.0 / 6) * k(1, 1), 1e-12 * k(8, 8));
}

TEST(SmoluchowskiKernel, SeparableFormIsSymmetrisedSumWithFractions) {
  const Kernel k = parse_kernel("separable:2,1/2,-1/3;0.5,1,1");
  const double i = 5, j = 11;
  const double want = 2 * (std::sqrt(i) / std::cbrt(j) + std::sqrt(j) / std::cbrt(i)) + 0.5 * (2 * i * j);
  EXPECT_NEAR(k(i, j), want, 1e-13 * want);
  EXPECT_DOUBLE_EQ(k(i, j), k(j, i));
  // Written back, it parses to the same kernel.
  EXPECT_NEAR(parse_kernel(k.as_separable())(i, j), want, 1e-13 * want);
}

TEST(SmoluchowskiKernel, RejectsBadStrings) {
  for (const char* bad : {"", "constnat", "separable:", "separable:1,2", "separable:1,2,3,4", "separable:0,1,1",
                          "separable:-1,0,0", "separable:1,x,0", "separable:1,1/0,0", "separable:1,0,0;"})
    EXPECT_THROW(parse_kernel(bad), InputError) << bad;
}

}  // namespace
}  // namespace coolgas::smoluchowski
