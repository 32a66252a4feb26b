// g(r) (analyze/structure/radial_distribution.h) in d = 1, 2, 3: the cell
// list counts exactly the pairs an all-pairs loop over minimum images counts;
// uniform random points give g = 1 at every r (the normalisation has no 1/N
// bias); a lattice's neighbour shell holds its d N pairs; and equilibrium
// hard rods, whose g(r) is known exactly, give the Tonks contact value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analyze/structure/radial_distribution.h"
#include "analyze/structure/structure_table.h"
#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

// n points uniform in [0, L)^d, as 3-vectors (the coordinates past d 0).
std::vector<double> uniform_points(std::size_t n, double L, Geometry g, Random& rng) {
  std::vector<double> p(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      if (g.spans(k)) p[3 * i + k] = L * rng.uniform();
  return p;
}

// The pairs per bin by an all-pairs loop over minimum images.
std::vector<double> all_pairs(const std::vector<double>& p, double L, double r_max, int per_sigma) {
  std::vector<double> count(std::size_t(std::floor(r_max * per_sigma)), 0.0);
  const std::size_t n = p.size() / 3;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      double r2 = 0;
      for (int k = 0; k < 3; ++k) {
        double dx = std::abs(p[3 * i + k] - p[3 * j + k]);
        dx = std::min(dx, L - dx);
        r2 += dx * dx;
      }
      const auto bin = std::size_t(std::sqrt(r2) * per_sigma);
      if (bin < count.size()) count[bin] += 1;
    }
  return count;
}

class EveryDimension : public ::testing::TestWithParam<int> {};

TEST_P(EveryDimension, CellListCountsWhatAllPairsCount) {
  const Geometry g(GetParam());
  Random rng(71 + GetParam());
  const double L = 12, r_max = 3.5;  // 3 cells a side: every neighbouring cell distinct, and wrapping
  const auto p = uniform_points(g.d() == 1 ? 60 : 600, L, g, rng);
  PairDistances pd(g, r_max, 20);
  pd.add(L, p);
  const auto expected = all_pairs(p, L, r_max, 20);
  const auto bins = pd.bins();
  ASSERT_EQ(bins.size(), expected.size());
  double total = 0;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    EXPECT_EQ(bins[i].pairs, expected[i]) << "bin " << i;
    total += bins[i].pairs;
  }
  EXPECT_GT(total, 100);
}

// Uniform random points: E[pairs_i] is exactly the normaliser, so each bin's
// g is 1 within 4 of its errors, and their pooled g within 3.
TEST_P(EveryDimension, UniformRandomPointsAreFlatAtOne) {
  const Geometry g(GetParam());
  Random rng(81 + GetParam());
  const double L = g.d() == 1 ? 400 : 20;
  PairDistances pd(g, 4, 10);
  for (int frame = 0; frame < 20; ++frame) pd.add(L, uniform_points(g.d() == 1 ? 400 : 2000, L, g, rng));
  double pairs = 0, expected = 0;
  for (const RdfBin& b : pd.bins()) {
    ASSERT_GT(b.pairs, 0) << "r = " << b.r;
    EXPECT_NEAR(b.g, 1, 4 * b.g_err) << "r = " << b.r;
    pairs += b.pairs, expected += b.pairs / b.g;
  }
  EXPECT_NEAR(pairs / expected, 1, 3 / std::sqrt(pairs));
  const ContactValue c = pd.contact(5);
  EXPECT_NEAR(c.g, 1, 3 * c.err);
}

INSTANTIATE_TEST_SUITE_P(D, EveryDimension, ::testing::Values(1, 2, 3));

// A simple cubic (square, ring) lattice of spacing a: its nearest-neighbour
// bin holds exactly d N pairs, and g there is d N over the ideal gas's pairs.
TEST(RadialDistribution, LatticeNeighbourShellHoldsDNPairs) {
  for (int d = 1; d <= 3; ++d) {
    const Geometry g(d);
    const int side = 8;
    const double a = 1.55, L = side * a;  // bin 15.5 / 10: no rounding near an edge
    std::vector<double> p;
    const int ny = g.along(1, side), nz = g.along(2, side);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < ny; ++j)
        for (int k = 0; k < nz; ++k) p.insert(p.end(), {a * i + 0.3, g.spans(1) ? a * j + 0.3 : 0, g.spans(2) ? a * k + 0.3 : 0});
    const double N = double(p.size() / 3);
    PairDistances pd(g, 2, 10);  // the bin [1.5, 1.6) holds the neighbours; none below, none else up to 2
    pd.add(L, p);
    const auto bins = pd.bins();
    for (std::size_t i = 0; i < bins.size(); ++i) EXPECT_EQ(bins[i].pairs, i == 15 ? d * N : 0.0) << d << "D, bin " << i;
    const double ideal = N * (N - 1) / 2 * (g.ball_measure(1.6) - g.ball_measure(1.5)) / g.box_measure(L);
    EXPECT_DOUBLE_EQ(bins[15].g, d * N / ideal) << d << "D";
  }
}

// Equilibrium hard rods on a ring (the Tonks gas): the gaps between
// neighbours are the spacings of N uniform points on a ring of L - N, so for
// sigma <= r < 2 sigma only the two neighbours count and
//   g(r) = exp(-lambda (r - sigma)) / (1 - phi),  lambda = n / (1 - phi),
// exactly the fitted form: the contact value is 1/(1 - phi) within its error
// and 1 %.
TEST(RadialDistribution, HardRodsGiveTheTonksContactValue) {
  const Geometry g(1);
  const std::size_t N = 2000;
  const double phi = 0.8, L = double(N) / phi;
  Random rng(91);
  PairDistances pd(g, 2, 50);
  std::vector<double> u(N), p(3 * N, 0.0);
  for (int frame = 0; frame < 500; ++frame) {
    for (double& x : u) x = (L - double(N)) * rng.uniform();
    std::sort(u.begin(), u.end());
    for (std::size_t i = 0; i < N; ++i) p[3 * i] = u[i] + double(i);
    pd.add(L, p);
  }
  const ContactValue c = pd.contact(5);
  const double exact = g.contact_value(phi), lambda = phi / (1 - phi);
  EXPECT_DOUBLE_EQ(exact, 1 / (1 - phi));
  EXPECT_NEAR(c.g, exact, 3 * c.err);
  EXPECT_NEAR(c.g / exact, 1, 0.01);
  EXPECT_LT(c.err / exact, 0.004);  // the check above is not empty
  EXPECT_GT(c.pairs, 10000);
  for (const RdfBin& b : pd.bins()) {
    if (b.r < 1) EXPECT_EQ(b.pairs, 0) << "r = " << b.r;  // rods never overlap
    if (b.r < 1) continue;
    const double lo = b.r - 0.01, hi = b.r + 0.01;  // the exact mean of g over the bin
    const double mean = (std::exp(-lambda * (lo - 1)) - std::exp(-lambda * (hi - 1))) / (lambda * 0.02) / (1 - phi);
    EXPECT_NEAR(b.g, mean, 4 * b.g_err + 1e-3 * mean) << "r = " << b.r;
  }
}

// The range: min(5, L/2) by default, never beyond L/2, always past the
// contact fit, and no more than 10^7 bins (a long ring could ask for more).
TEST(RadialDistribution, RangeRules) {
  EXPECT_EQ(rdf_range(0, 40, 50, 5), 5);
  EXPECT_EQ(rdf_range(0, 6, 50, 5), 3);
  EXPECT_EQ(rdf_range(7.5, 40, 50, 5), 7.5);
  EXPECT_THROW(rdf_range(20.5, 40, 50, 5), InputError);
  EXPECT_THROW(rdf_range(0, 2.1, 50, 10), InputError);  // L/2 = 1.05 < 1.2
  EXPECT_NO_THROW(rdf_range(1.2, 2.4, 50, 10));
  EXPECT_THROW(rdf_range(2e4, 1e5, 1000, 5), InputError);
  EXPECT_THROW(check_rdf_options(0, 10, 11), InputError);
  EXPECT_THROW(check_rdf_options(std::nan(""), 10, 5), InputError);
}

}  // namespace
}  // namespace coolgas
