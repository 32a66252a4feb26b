// The geometric-grid (fixed-pivot) scheme: exact on an all-integer grid,
// conserves number per event and mass identically, converges as the ratio
// shrinks. Kumar & Ramkrishna, Chem. Eng. Sci. 51, 1311 (1996).
#include <gtest/gtest.h>

#include "analyze/smoluchowski/exact.h"
#include "analyze/smoluchowski/geometric.h"
#include "analyze/smoluchowski/observables.h"
#include "tests/unit/analyze/smoluchowski/test_support.h"

namespace coolgas::smoluchowski {
namespace {

using testing::max_difference;
using testing::run;

TEST(SmoluchowskiGeometric, GridIsIntegersThenGeometricUpToTheCutoff) {
  const MassGrid g = geometric_grid(100000, 1.1);
  EXPECT_EQ(g.mass.front(), 1);
  EXPECT_EQ(g.mass.back(), 100000);
  EXPECT_EQ(g.edge.back(), 100000.5);
  for (std::size_t i = 1; i < g.size(); ++i) {
    EXPECT_GT(g.mass[i], g.mass[i - 1]);
    // Integer spacing at first, then a ratio of 1.1 up to rounding.
    EXPECT_LE(g.mass[i], std::max(g.mass[i - 1] + 1, std::round(1.1 * g.mass[i - 1])) + 0.5 * g.mass[i - 1]);
  }
  EXPECT_LT(g.size(), 150u);  // about log(1e5)/log(1.1) + the integer start
}

TEST(SmoluchowskiGeometric, AllIntegerGridReproducesTheDirectMethod) {
  // With r = 1.01 every pivot up to 128 is an integer: the discrete equation itself.
  ASSERT_EQ(geometric_grid(128, 1.01).size(), 128u);
  const auto g = run("ballistic", Method::Geometric, 128, 1.0, 1e-10, 1e-18, Stepper::Rkck, 1.01);
  const auto d = run("ballistic", Method::Direct, 128, 1.0);
  EXPECT_LT(max_difference(g.c, d.c), 1e-12);
}

TEST(SmoluchowskiGeometric, EachEventConservesMassAndRemovesOneCluster) {
  // For any state below the cut-off: dM1/dt = 0 and dM0/dt = −½ Σ_ij K N_i N_j.
  const Kernel k = parse_kernel("ballistic");
  GeometricRhs rhs(k, 1 << 20, 1.2);
  const MassGrid& g = rhs.grid();
  std::vector<double> c(g.size(), 0.0), dc(g.size());
  for (std::size_t i = 0; i < 40; ++i) c[i] = 1.0 / (1 + i * i);  // pairs stay far below 2^20
  rhs.evaluate(c.data(), dc.data());
  double dM0 = 0, dM1 = 0, pairs = 0, scale = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    dM0 += dc[i];
    dM1 += g.mass[i] * dc[i];
    scale += g.mass[i] * std::abs(dc[i]);
    for (std::size_t j = 0; j < g.size(); ++j) pairs += 0.5 * k(g.mass[i], g.mass[j]) * c[i] * c[j];
  }
  EXPECT_NEAR(dM1, 0, 1e-14 * scale);
  EXPECT_NEAR(dM0, -pairs, 1e-13 * pairs);
}

TEST(SmoluchowskiGeometric, ErrorShrinksWithTheGridRatio) {
  // Constant kernel at t = 20 against its exact solution, on log bins.
  const Kernel k = parse_kernel("constant");
  const MassGrid exact_grid = uniform_grid(4096);
  std::vector<double> exact(4096);
  for (long m = 1; m <= 4096; ++m) exact[m - 1] = exact_concentration(k, m, 20);
  double previous = 1;
  for (double r : {1.5, 1.2, 1.05}) {
    const auto s = run("constant", Method::Geometric, 4096, 20, 1e-10, 1e-18, Stepper::Rkck, r);
    const double err = binned_distance(s.grid, s.c, exact_grid, exact, 10);
    EXPECT_LT(err, previous) << "ratio " << r;
    previous = err;
    EXPECT_NEAR(moments(s.grid, s.c).M1, 1, 1e-10) << "ratio " << r;
  }
  EXPECT_LT(previous, 0.02);
}

}  // namespace
}  // namespace coolgas::smoluchowski
