// The direct method (the reference) against the exact solutions of the
// classic kernels, ½-gain convention, c_k(0) = δ_k1.
// Sources of the formulas: Leyvraz, Phys. Rep. 383, 95 (2003), Sec. 2;
// Aldous, Bernoulli 5, 3 (1999), Sec. 2.1 (see analyze/smoluchowski/exact.h).
#include <gtest/gtest.h>

#include "analyze/smoluchowski/exact.h"
#include "analyze/smoluchowski/observables.h"
#include "common/error.h"
#include "tests/unit/analyze/smoluchowski/test_support.h"

namespace coolgas::smoluchowski {
namespace {

using testing::run;

// Largest relative error of c_k over the masses with c_k > floor.
double worst_relative_error(const Solution& s, const Kernel& k, double floor) {
  double worst = 0;
  for (std::size_t i = 0; i < s.c.size(); ++i) {
    const double exact = exact_concentration(k, long(i) + 1, s.t);
    if (exact > floor) worst = std::max(worst, std::abs(s.c[i] / exact - 1));
  }
  return worst;
}

TEST(SmoluchowskiExact, ConstantKernelToOneInTenToTheEightWhereverAboveTenToTheMinusTwelve) {
  const Kernel k = parse_kernel("constant");
  for (double t : {1.0, 10.0}) {
    const auto s = run("constant", Method::Direct, 256, t, 1e-12, 1e-26, Stepper::Rk8pd);
    EXPECT_LT(worst_relative_error(s, k, 1e-12), 1e-8) << "t = " << t;
  }
}

TEST(SmoluchowskiExact, AdditiveAndProductKernelsMatchTheirFormulas) {
  // Product kernel only before gelation (t_g = 1).
  for (auto [name, t] : {std::pair{"additive", 1.0}, std::pair{"product", 0.6}}) {
    const auto s = run(name, Method::Direct, 512, t, 1e-12, 1e-26, Stepper::Rk8pd);
    EXPECT_LT(worst_relative_error(s, parse_kernel(name), 1e-12), 1e-7) << name;
  }
}

TEST(SmoluchowskiExact, ProductKernelSecondMomentDivergesAtGelationTimeOne) {
  // For K = ij from δ_k1: dM2/dt = M2^2, so M2 = 1/(1 − t) (Leyvraz 2003, Sec. 2.3).
  for (double t : {0.3, 0.6}) {
    const auto s = run("product", Method::Fft, 4096, t);
    EXPECT_NEAR(moments(s.grid, s.c).M2, 1 / (1 - t), 1e-8 / (1 - t)) << t;
  }
  EXPECT_THROW(exact_concentration(parse_kernel("product"), 3, 1.5), InputError);
}

TEST(SmoluchowskiExact, ExactSolutionsConserveMassAndGiveKnownMeanMass) {
  // M1 = 1; mean mass 1 + t/2 (constant), e^t (additive), 1/(1 − t/2) (product:
  // dM0/dt = −M1²/2); Leyvraz 2003, Sec. 2.
  struct C {
    const char* name;
    double t, mean;
  };
  for (const C& c : {C{"constant", 4, 3}, C{"additive", 1, std::exp(1.0)}, C{"product", 0.5, 1 / 0.75}}) {
    const Kernel k = parse_kernel(c.name);
    double M0 = 0, M1 = 0;
    for (long m = 1; m < 20000; ++m) {
      const double x = exact_concentration(k, m, c.t);
      M0 += x;
      M1 += m * x;
    }
    EXPECT_NEAR(M1, 1, 1e-10) << c.name;
    EXPECT_NEAR(M1 / M0, c.mean, 1e-10) << c.name;
  }
}

TEST(SmoluchowskiExact, MassConservedWhileTheCutoffHolds) {
  for (const char* name : {"constant", "ballistic", "separable:1,0.3,-0.2"}) {
    const auto s = run(name, Method::Direct, 512, 2.0);
    EXPECT_NEAR(moments(s.grid, s.c).M1, 1, 1e-10) << name;
  }
}

}  // namespace
}  // namespace coolgas::smoluchowski
